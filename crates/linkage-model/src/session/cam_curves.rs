//! A cam joint over its turn, for the cam panel and the cam's drawn outline: the
//! follower's lift, its rates and the cam's pressure angle and radii at every cam
//! angle. Made when the cam joint changes: an edit of the linkage around it (a
//! length, a mass) keeps the cam's curves, since they depend on the joint alone.

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
#[derive(Clone, Debug, PartialEq)]
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
    /// The joint these curves were made of, to tell whether an edit changed it.
    joint: CamJoint,
}

impl CamCurves {
    /// The curves of every cam joint of `m`, taken from `earlier` (the curves of the
    /// mechanism before an edit) for a joint the edit left as it was: the cam feed's
    /// two cams were a fifth of a length edit's CPU.
    pub fn of(m: &Mechanism, earlier: &[Self]) -> Vec<Self> {
        m.cams
            .iter()
            .map(|c| {
                let speed = Self::speed_of(m, c);
                earlier
                    .iter()
                    .find(|e| e.joint == *c && e.speed_rad_s == speed)
                    .cloned()
                    .unwrap_or_else(|| Self::of_joint(c, speed))
            })
            .collect()
    }

    /// The cam's speed for the rates (see [`Self::speed_rad_s`]).
    fn speed_of(m: &Mechanism, c: &CamJoint) -> f64 {
        if c.cam == m.driver.link {
            m.driver.speed_rad_s
        } else {
            1.0
        }
    }

    fn of_joint(c: &CamJoint, speed_rad_s: f64) -> Self {
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
            speed_rad_s,
            base_radius_m,
            largest_pressure,
            least_profile_radius,
            joint: c.clone(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::topology::CAM_OUTLINE;
    use super::super::{SceneEdit, Session};
    use super::*;

    /// What the session shows of its cams against what the joints give afresh.
    fn assert_fresh(s: &Session, context: &str) {
        let m = s.mechanism();
        assert_eq!(s.curves().cams, CamCurves::of(m, &[]), "{context}");
        for (c, outline) in m.cams.iter().zip(&s.topology().cam_profiles) {
            for (i, drawn) in outline.iter().enumerate() {
                let p = c.point_at(std::f64::consts::TAU * i as f64 / CAM_OUTLINE as f64);
                let made = c.centre_on_cam + linkage::Vec2::new(p.profile_m[0], p.profile_m[1]);
                assert_eq!(*drawn, made, "{context}: outline point {i}");
            }
        }
    }

    /// A length edit keeps the cams' curves, a cam edit makes them anew, and either
    /// way they, and the drawn outline, are what the cam joints give.
    #[test]
    fn kept_cam_curves_are_the_joints_own() {
        let mut s = Session::open_builtin("paper_cup_cam_feed").expect("opens");
        assert_fresh(&s, "opened");
        let v = s.lengths()[0].value(s.scene()).expect("a length");
        s.apply(SceneEdit::Length {
            index: 0,
            value: 1.01 * v,
        });
        assert!(s.message().is_none(), "{:?}", s.message());
        assert_fresh(&s, "a length edited");
        let before = s.curves().cams.clone();
        s.apply(SceneEdit::Cam {
            cam: 0,
            edit: super::super::cam_edit::CamEdit::Lift(0.9 * lift_of(&s)),
        });
        assert!(s.message().is_none(), "{:?}", s.message());
        assert_ne!(s.curves().cams[0], before[0], "the lift changed the cam");
        assert_fresh(&s, "the cam's lift edited");
    }

    /// The cam's largest lift in the scene's units, as the cam panel shows it.
    fn lift_of(s: &Session) -> f64 {
        s.scene().cams[0]
            .segments
            .iter()
            .filter_map(linkage::cam::SegmentSpec::lift)
            .fold(0.0, f64::max)
    }
}
