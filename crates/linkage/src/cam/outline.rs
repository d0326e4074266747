//! The follower as a figure of the cam draws it at one cam angle: the roller, knife
//! edge or flat face on the pitch curve, the stem in its guide or the arm on its
//! pivot. The figures (the app's cam view, the task sheet) draw these lines and
//! circles; the geometry is the solver's, so that the follower drawn touches the
//! profile drawn.

use std::f64::consts::TAU;

use super::disc::{DiscCam, Face, Follower};

/// Samples of the turn over which a flat face's width is found.
const FACE_SAMPLES: u32 = 180;

/// The follower at one cam angle, in the frame of the cam's centre (the cam turned by
/// that angle, counter-clockwise), m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FollowerOutline {
    /// The point on the pitch curve: the roller's centre, the knife edge, or a flat
    /// face's contact.
    pub tip_m: [f64; 2],
    /// The roller's radius, where the follower has one.
    pub roller_radius_m: Option<f64>,
    /// The stem of a translating follower (from the tip away from the cam, a base
    /// radius long) or the arm of an oscillating one (from the tip to its pivot).
    pub stem_m: [[f64; 2]; 2],
    /// A flat face's ends: wide enough for every contact of the turn.
    pub flat_face_m: Option<[[f64; 2]; 2]>,
    /// An oscillating follower's pivot on the frame.
    pub pivot_m: Option<[f64; 2]>,
    /// A translating follower's guide: its line's two ends beside the stem.
    pub guide_m: Option<[[f64; 2]; 2]>,
}

impl FollowerOutline {
    /// The points a figure must hold to show the follower whole: the tip, the stem's
    /// or arm's ends, a flat face's ends, the pivot.
    pub fn extent_m(&self) -> impl Iterator<Item = [f64; 2]> + '_ {
        [self.tip_m, self.stem_m[0], self.stem_m[1]]
            .into_iter()
            .chain(self.flat_face_m.into_iter().flatten())
            .chain(self.pivot_m)
    }
}

impl DiscCam {
    /// The follower where it stands at cam angle `theta_rad`.
    pub fn follower_outline(&self, theta_rad: f64) -> FollowerOutline {
        let tip = self.pitch_in_frame(theta_rad);
        let roller_radius_m = match self.face() {
            Face::Roller { radius_m } => Some(radius_m),
            Face::KnifeEdge | Face::Flat => None,
        };
        match self.follower {
            Follower::Translating { offset_m, face } => {
                let reach = self.base_radius_m;
                let top = [offset_m, tip[1] + reach];
                let flat_face_m = matches!(face, Face::Flat).then(|| {
                    let half = self.flat_face_half_width(offset_m);
                    [[offset_m - half, tip[1]], [offset_m + half, tip[1]]]
                });
                FollowerOutline {
                    tip_m: tip,
                    roller_radius_m,
                    stem_m: [[offset_m, tip[1]], top],
                    flat_face_m,
                    pivot_m: None,
                    guide_m: Some([[offset_m, tip[1] + 0.5 * reach], top]),
                }
            }
            Follower::Oscillating { pivot_m, .. } => FollowerOutline {
                tip_m: tip,
                roller_radius_m,
                stem_m: [tip, [pivot_m, 0.0]],
                flat_face_m: None,
                pivot_m: Some([pivot_m, 0.0]),
                guide_m: None,
            },
        }
    }

    /// The pitch point at `theta_rad` in the frame, as the follower's motion puts it
    /// (not the cam's own-frame point of [`DiscCam::at`] turned back).
    fn pitch_in_frame(&self, theta_rad: f64) -> [f64; 2] {
        let ([c, ..], _) = self.pitch_point(&self.program.at(theta_rad));
        [c.x, c.y]
    }

    /// Half a flat face's width: its farthest contact from the stem over the turn,
    /// and a fifth more, at least a fifth of the base radius.
    fn flat_face_half_width(&self, offset_m: f64) -> f64 {
        (0..FACE_SAMPLES)
            .map(|i| TAU * f64::from(i) / f64::from(FACE_SAMPLES))
            .map(|theta| (self.pitch_in_frame(theta)[0] - offset_m).abs())
            .fold(0.0, f64::max)
            .max(1.0 / 6.0 * self.base_radius_m)
            * 1.2
    }
}
