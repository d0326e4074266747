//! A cam joint's follower as a group of the decomposition: one link, placed as soon
//! as the cam's link is, since its coordinate is the program's lift at the cam's
//! angle. It always assembles and its velocity needs no system.

use super::parts::{Failure, GroupOk};
use crate::ids::LinkId;
use crate::model::CamJoint;
use crate::motion::LinkMotion;
use crate::real::Real;

/// The follower of one cam joint.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct CamFollow {
    /// Index into `Mechanism::cams`.
    pub(crate) joint: usize,
    /// The joint itself (the group solves without the mechanism).
    pub(crate) cam: CamJoint,
}

impl CamFollow {
    /// The follower.
    pub(crate) fn follower(&self) -> LinkId {
        self.cam.follower
    }

    /// Places the follower from the cam link's motion, lane by lane: the program is
    /// evaluated in `f64` (its segments branch on the angle).
    #[inline(always)]
    pub(super) fn solve<T: Real>(
        &self,
        links: &mut [LinkMotion<T>],
    ) -> std::result::Result<GroupOk<T>, Failure> {
        let cam = &links[self.cam.cam];
        let (mut q, mut q_dot, mut q_ddot) = (T::zero(), T::zero(), T::zero());
        for k in 0..T::LANES {
            let (re, im) = (cam.rotation.re.extract(k), cam.rotation.im.extract(k));
            let (w, alpha) = (cam.omega_rad_s.extract(k), cam.alpha_rad_s2.extract(k));
            let m = self.cam.follower_at(im.atan2(re));
            q.replace(k, m.s);
            q_dot.replace(k, m.v * w);
            q_ddot.replace(k, m.a * w * w + m.v * alpha);
        }
        links[self.cam.follower] = self.cam.place_follower(q, q_dot, q_ddot);
        Ok(GroupOk {
            margin: T::one(),
            conditioning: T::one(),
        })
    }
}
