//! A cam joint over its turn, for the cam panel: the follower's lift, its rates and
//! the cam's pressure angle and radii at every cam angle, made once per edit.

use linkage::Mechanism;
use linkage::cam::CamPoint;
use linkage::model::{CamJoint, FollowerGuide};

/// Cam angles over a turn in the cam panel's plots (every degree).
pub const CAM_SAMPLES: usize = 360;

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
    /// The base circle's radius, m.
    pub base_radius_m: f64,
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
        // The profile's least distance from the cam's centre.
        let base_radius_m = points
            .iter()
            .map(|p| p.profile_m[0].hypot(p.profile_m[1]))
            .fold(f64::INFINITY, f64::min);
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
        }
    }
}
