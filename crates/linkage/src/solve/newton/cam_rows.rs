//! The cam joints as rows of Newton's system: one equation each, the follower's
//! coordinate (an arm's angle, a slider's travel on its ground guide) minus the rest
//! and the program's lift at the cam link's angle. Its Jacobian row is the
//! coordinate's rate for a unit rate of each tree joint less the lift's slope times
//! the cam's; its acceleration bias is the same equation differentiated twice with
//! the coordinates' second derivatives zero.

use super::Solver;
use crate::angles::unwrap_near;
use crate::model::{CamJoint, FollowerGuide};
use crate::motion::{LinkMotion, Vec2};

/// The follower's coordinate: an arm's angle (rad), a slider's travel along its ground
/// guide from the guide's point (m).
fn coordinate(cam: &CamJoint, links: &[LinkMotion]) -> f64 {
    let f = &links[cam.follower];
    match &cam.guide {
        FollowerGuide::Arm { .. } => f.angle_rad(),
        FollowerGuide::Slide {
            through_world,
            direction,
            slider_local,
            ..
        } => (f.world(slider_local) - through_world).dot(direction),
    }
}

impl Solver<'_> {
    /// The cam rows' residuals from row `first` of `out`; returns their max-norm
    /// (rad, or metres per metre of the mechanism's size).
    pub(super) fn cam_residuals(&self, links: &[LinkMotion], out: &mut [f64], first: usize) -> f64 {
        let mut worst: f64 = 0.0;
        for (j, cam) in self.model.cams.iter().enumerate() {
            let lift = cam.follower_at(links[cam.cam].angle_rad()).s;
            let gap = coordinate(cam, links) - lift;
            let (r, relative) = match cam.guide {
                FollowerGuide::Arm { .. } => {
                    // The angle's gap by whole turns to within π of none.
                    let gap = unwrap_near(gap, 0.0);
                    (gap, gap)
                }
                FollowerGuide::Slide { .. } => (gap, gap / self.model.size_m),
            };
            out[first + j] = r;
            worst = worst.max(relative.abs());
        }
        worst
    }

    /// The cam rows of the Jacobian (from row `first`), and of the driver's column.
    pub(super) fn cam_jacobian_rows(&mut self, links: &[LinkMotion], first: usize) {
        for j in 0..self.model.cams.len() {
            let cam = &self.model.cams[j];
            let slope = cam.follower_at(links[cam.cam].angle_rad()).v;
            let on_follower = match &cam.guide {
                FollowerGuide::Slide { slider_local, .. } => {
                    links[cam.follower].world(slider_local)
                }
                FollowerGuide::Arm { .. } => Vec2::zeros(),
            };
            let centre = cam.centre;
            let (follower, cam_link, guide) = (cam.follower, cam.cam, cam.guide.clone());
            for k in 0..self.model.tree.len() {
                let (v, w) = self.unit_rate(k, follower, &on_follower);
                let rate = match &guide {
                    FollowerGuide::Arm { .. } => w,
                    FollowerGuide::Slide { direction, .. } => v.dot(direction),
                };
                let cam_rate = self.unit_rate(k, cam_link, &centre).1;
                let entry = rate - slope * cam_rate;
                if k == 0 {
                    self.work.rates[first + j] = entry;
                } else {
                    self.work.jac[(first + j, k - 1)] = entry;
                }
            }
        }
    }

    /// The cam rows' acceleration bias (from row `first` of `out`), after a motion
    /// pass with the coordinates' second derivatives zero.
    pub(super) fn cam_accelerations(&self, links: &[LinkMotion], out: &mut [f64], first: usize) {
        for (j, cam) in self.model.cams.iter().enumerate() {
            let c = &links[cam.cam];
            let m = cam.follower_at(c.angle_rad());
            let f = &links[cam.follower];
            let follower = match &cam.guide {
                FollowerGuide::Arm { .. } => f.alpha_rad_s2,
                FollowerGuide::Slide {
                    direction,
                    slider_local,
                    ..
                } => f.point(slider_local).acceleration.dot(direction),
            };
            out[first + j] = follower - m.a * c.omega_rad_s * c.omega_rad_s - m.v * c.alpha_rad_s2;
        }
    }
}
