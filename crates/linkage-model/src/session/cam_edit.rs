//! Edits of a cam joint's program from the cam panel: a segment's law, a segment's
//! angle (the next segment gives or takes the difference, so that the turn stays
//! 360 degrees), the lift (every segment's in proportion, so that the program still
//! closes) and the roller's radius. Each is checked by building the scene.

use linkage::cam::{Law, SegmentSpec};

use super::Session;
use super::history::EditTarget;
use super::notice::Notice;

/// One edit of a cam joint, by its index in the scene's `cams`.
#[derive(Clone, Debug, PartialEq)]
pub enum CamEdit {
    /// The law of a rise or return.
    Law {
        /// The segment.
        segment: usize,
        /// Its new law.
        law: Law,
    },
    /// A segment's cam angle, deg; the next segment (round the turn) makes up the
    /// difference.
    Span {
        /// The segment.
        segment: usize,
        /// Its new angle, deg.
        deg: f64,
    },
    /// The largest lift (deg of an arm, or the scene's length unit), every lift
    /// scaled with it.
    Lift(f64),
    /// The roller's radius, scene length unit.
    Roller(f64),
}

/// A segment's angle, deg.
fn span_deg(s: &SegmentSpec) -> f64 {
    match *s {
        SegmentSpec::Rise { deg, .. }
        | SegmentSpec::Dwell { deg }
        | SegmentSpec::Return { deg, .. } => deg,
    }
}

fn set_span(s: &mut SegmentSpec, to: f64) {
    match s {
        SegmentSpec::Rise { deg, .. }
        | SegmentSpec::Dwell { deg }
        | SegmentSpec::Return { deg, .. } => *deg = to,
    }
}

impl Session {
    /// Applies `edit` to cam joint `cam`; a refusal leaves a notice.
    pub(super) fn edit_cam(&mut self, cam: usize, edit: CamEdit) {
        let mut scene = self.scene().clone();
        let Some(joint) = scene.cams.get_mut(cam) else {
            return;
        };
        match edit {
            CamEdit::Law { segment, law } => match joint.segments.get_mut(segment) {
                Some(SegmentSpec::Rise { law: l, .. } | SegmentSpec::Return { law: l, .. }) => {
                    *l = law;
                }
                _ => return,
            },
            CamEdit::Span { segment, deg } => {
                let n = joint.segments.len();
                if segment >= n || n < 2 {
                    return;
                }
                let next = (segment + 1) % n;
                let room = span_deg(&joint.segments[segment]) + span_deg(&joint.segments[next]);
                if !(deg.is_finite() && deg > 0.0 && deg < room) {
                    self.message = Some(Notice::CamSpanRefused {
                        segment,
                        deg,
                        room_deg: room,
                    });
                    return;
                }
                set_span(&mut joint.segments[segment], deg);
                set_span(&mut joint.segments[next], room - deg);
            }
            CamEdit::Lift(to) => {
                let largest = joint
                    .segments
                    .iter()
                    .filter_map(|s| match s {
                        SegmentSpec::Rise { lift, .. } | SegmentSpec::Return { lift, .. } => {
                            Some(*lift)
                        }
                        SegmentSpec::Dwell { .. } => None,
                    })
                    .fold(0.0, f64::max);
                if !(to.is_finite() && to > 0.0 && largest > 0.0) {
                    self.message = Some(Notice::InvalidValue {
                        what: "cam lift",
                        value: to,
                        valid: "it must be finite and > 0",
                    });
                    return;
                }
                for s in &mut joint.segments {
                    if let SegmentSpec::Rise { lift, .. } | SegmentSpec::Return { lift, .. } = s {
                        *lift *= to / largest;
                    }
                }
            }
            CamEdit::Roller(radius) => joint.roller_radius = radius,
        }
        let what = format!("the cam {}/{}", joint.cam, joint.follower);
        self.rebuild(EditTarget::Cam(cam), scene, what);
    }
}
