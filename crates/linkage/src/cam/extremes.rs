//! Where a disc cam is at its limits: the largest pressure angle of each segment and
//! where, and the smallest radius of curvature of the pitch curve and of the profile
//! on their convex parts and where; undercutting where a roller's profile has no
//! positive radius on a convex part of the pitch curve. Each extreme is found by a
//! scan of its segment and a golden-section search round the best sample, so that
//! the angle is found to about 1e-12 rad and the value to rounding.

use serde::Serialize;

use super::disc::{CamPoint, DiscCam};

pub use crate::extremum::Extreme;

/// A cam's extremes over the turn.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CamExtremes {
    /// Per segment: the pressure angle of largest size (signed, rad).
    pub pressure_by_segment: Vec<Extreme>,
    /// The smallest radius of curvature of the pitch curve where convex, m.
    pub smallest_pitch_radius: Extreme,
    /// The smallest radius of curvature of the profile where the pitch curve is
    /// convex, m (≤ 0: undercut).
    pub smallest_profile_radius: Extreme,
    /// The profile folds (a roller bigger than the pitch curve's radius there).
    pub undercut: bool,
}

/// Samples per segment before the search.
const SCAN: usize = 256;

/// The θ in [a, b] where `f` is largest, and its value: the best of a scan, then a
/// golden-section search between its neighbours ([`crate::extremum`]).
pub(super) fn largest(f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> Extreme {
    let samples: Vec<[f64; 2]> = (0..=SCAN)
        .map(|i| {
            let x = a + (b - a) * i as f64 / SCAN as f64;
            [x, f(x)]
        })
        .collect();
    crate::extremum::locate_max(&samples, None, |x| Some(f(x))).unwrap_or(Extreme {
        angle_rad: a,
        value: f(a),
    })
}

impl DiscCam {
    /// The cam's extremes over the turn.
    pub fn extremes(&self) -> CamExtremes {
        let spans = self.program.spans();
        let pressure_by_segment = spans
            .iter()
            .map(|&(a, b)| {
                let e = largest(&|t| self.at(t).pressure_angle_rad.abs(), a, b);
                Extreme {
                    angle_rad: e.angle_rad,
                    value: self.at(e.angle_rad).pressure_angle_rad,
                }
            })
            .collect();
        let smallest = |pick: &dyn Fn(&CamPoint) -> f64| -> Extreme {
            // Largest of −radius over the convex parts (concave parts rank last).
            let f = |t: f64| {
                let p = self.at(t);
                if p.pitch_radius_m > 0.0 {
                    -pick(&p)
                } else {
                    f64::NEG_INFINITY
                }
            };
            let best = spans
                .iter()
                .map(|&(a, b)| largest(&f, a, b))
                .max_by(|x, y| x.value.total_cmp(&y.value))
                .unwrap_or(Extreme {
                    angle_rad: 0.0,
                    value: f64::NEG_INFINITY,
                });
            Extreme {
                angle_rad: best.angle_rad,
                value: -best.value,
            }
        };
        let smallest_pitch_radius = smallest(&|p| p.pitch_radius_m);
        let smallest_profile_radius = smallest(&|p| p.profile_radius_m);
        CamExtremes {
            pressure_by_segment,
            smallest_pitch_radius,
            undercut: smallest_profile_radius.value <= 0.0,
            smallest_profile_radius,
        }
    }
}
