//! Edits of a cam joint's program from the cam panel: a segment's law, a segment's
//! angle (the next segment gives or takes the difference, so that the turn stays
//! 360 degrees), the lift (every segment's in proportion, so that the program still
//! closes) and the roller's radius. Each is checked by building the scene.

use linkage::cam::{Law, SegmentSpec};

use super::Session;
use super::history::EditTarget;
use super::notice::{Notice, ValueKind};

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

impl Session {
    /// Applies `edit` to cam joint `cam`; a refusal leaves a notice.
    pub(super) fn edit_cam(&mut self, cam: usize, edit: CamEdit) {
        let mut scene = self.scene().clone();
        let Some(joint) = scene.cams.get_mut(cam) else {
            return;
        };
        match edit {
            CamEdit::Law { segment, law } => {
                match joint
                    .segments
                    .get_mut(segment)
                    .and_then(SegmentSpec::law_mut)
                {
                    Some(l) => *l = law,
                    None => return,
                }
            }
            CamEdit::Span { segment, deg } => {
                let n = joint.segments.len();
                if segment >= n || n < 2 {
                    return;
                }
                let next = (segment + 1) % n;
                let room = joint.segments[segment].angle_deg() + joint.segments[next].angle_deg();
                if !(deg.is_finite() && deg > 0.0 && deg < room) {
                    self.message = Some(Notice::CamSpanRefused {
                        segment,
                        deg,
                        room_deg: room,
                    });
                    return;
                }
                *joint.segments[segment].angle_deg_mut() = deg;
                *joint.segments[next].angle_deg_mut() = room - deg;
            }
            CamEdit::Lift(to) => {
                let largest = joint
                    .segments
                    .iter()
                    .filter_map(SegmentSpec::lift)
                    .fold(0.0, f64::max);
                if !(to.is_finite() && to > 0.0 && largest > 0.0) {
                    self.message = Some(Notice::InvalidValue {
                        what: ValueKind::CamLift,
                        value: to,
                        valid: linkage::error::Valid::Positive,
                    });
                    return;
                }
                for lift in joint.segments.iter_mut().filter_map(SegmentSpec::lift_mut) {
                    *lift *= to / largest;
                }
            }
            CamEdit::Roller(radius) => joint.roller_radius = radius,
        }
        let what = super::notice::EditSubject::Cam {
            cam: joint.cam.clone(),
            follower: joint.follower.clone(),
        };
        self.rebuild(EditTarget::Cam(cam), scene, what);
    }
}
