//! A cam joint over its turn, for the cam panel: the follower's lift, its rates and
//! the cam's pressure angle and radii at every cam angle, made once per edit.

use linkage::Mechanism;
use linkage::cam::CamPoint;
use linkage::extremum::{Extreme, locate_max, locate_min};
use linkage::model::{CamJoint, FollowerGuide};

/// Cam angles over a turn in the cam panel's plots (every degree).
pub const CAM_SAMPLES: usize = 360;

/// No extreme: a cam without points.
const NONE: Extreme = Extreme {
    angle_rad: 0.0,
    value: 0.0,
};

/// One cam joint over its turn.
#[derive(Clone, Debug)]
pub struct CamCurves {
    /// The joint, `cam/follower`.
    pub name: String,
    /// Whether the follower is an arm (lifts in rad) rather than a slider (m).
    pub is_arm: bool,
    /// The cam at [`CAM_SAMPLES`] angles of its link over a turn.
    pub points: Vec<CamPoint>,
    /// The largest pressure angle allowed, rad.
    pub pressure_limit_rad: f64,
    /// The cam's speed for the rates: the crank's where the cam is on the crank,
    /// else 1 rad/s (rates per radian of cam).
    pub speed_rad_s: f64,
    /// The base circle's radius, m (located between the samples).
    pub base_radius_m: f64,
    /// The pressure angle of largest size over the turn (signed, rad) and the cam
    /// angle where it is, located between the samples.
    pub largest_pressure: Extreme,
    /// The profile's smallest radius of curvature (m) and where, located.
    pub least_profile_radius: Extreme,
}

impl CamCurves {
    /// The curves of every cam joint of `m`.
    pub fn of(m: &Mechanism) -> Vec<Self> {
        m.cams.iter().map(|c| Self::of_joint(m, c)).collect()
    }

    fn of_joint(m: &Mechanism, c: &CamJoint) -> Self {
        let points: Vec<CamPoint> = (0..CAM_SAMPLES)
            .map(|i| std::f64::consts::TAU * i as f64 / CAM_SAMPLES as f64)
            .map(|theta| c.point_at(theta))
            .collect();
        // The extremes, bracketed by the samples and located on the cam itself.
        let series = |f: &dyn Fn(&CamPoint) -> f64| -> Vec<[f64; 2]> {
            points.iter().map(|p| [p.angle_rad, f(p)]).collect()
        };
        let turn = Some(std::f64::consts::TAU);
        let centre = |p: &CamPoint| p.profile_m[0].hypot(p.profile_m[1]);
        let base_radius_m = locate_min(&series(&centre), turn, |x| Some(centre(&c.point_at(x))))
            .map_or(0.0, |e| e.value);
        let size = |p: &CamPoint| p.pressure_angle_rad.abs();
        let largest = locate_max(&series(&size), turn, |x| Some(size(&c.point_at(x))));
        let largest_pressure = largest.map_or(NONE, |e| Extreme {
            value: c.point_at(e.angle_rad).pressure_angle_rad,
            ..e
        });
        let radius = |p: &CamPoint| p.profile_radius_m;
        let least_profile_radius =
            locate_min(&series(&radius), turn, |x| Some(radius(&c.point_at(x)))).unwrap_or(NONE);
        Self {
            name: c.name.clone(),
            is_arm: matches!(c.guide, FollowerGuide::Arm { .. }),
            points,
            pressure_limit_rad: c.pressure_limit_rad(),
            speed_rad_s: if c.cam == m.driver.link {
                m.driver.speed_rad_s
            } else {
                1.0
            },
            base_radius_m,
            largest_pressure,
            least_profile_radius,
        }
    }
}
