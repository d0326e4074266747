//! The polygon equations of a cam's follower, by the equivalent linkage: at each
//! instant the roller's centre R keeps its distance from K, the pitch curve's centre
//! of curvature (a point of the cam), to second order, so the cam joint acts as a
//! link KR pinned to the cam at K and to the follower at R. Then
//! v_R = v_K + v_RK and a_R = a_K + a_RK^n + a_RK^t, as for a four-bar's coupler.

use super::parts::Term;
use super::terms::{known_point, relative, riding};
use crate::Solution;
use crate::model::{CamJoint, FollowerGuide, Mechanism};
use crate::motion::{PointMotion, cross};

/// Beyond this many mechanism sizes a pitch curve counts as straight (an inflection):
/// its centre of curvature has gone to infinity and the equivalent link with it.
const STRAIGHT_RADIUS: f64 = 1e6;

/// The two sides of the follower's equation: R as the follower moves it, and R as K
/// and the equivalent link KR move it; `None` where the pitch curve is straight.
pub(super) fn cam_sides(
    m: &Mechanism,
    s: &Solution,
    cam: &CamJoint,
    accel: bool,
) -> Option<(Vec<Term>, Vec<Term>)> {
    let angle = s.links[cam.cam].angle_rad();
    let contact = cam.contact(angle);
    let curved = contact.pitch_radius_m.abs() < STRAIGHT_RADIUS * m.size_m;
    if !curved {
        return None;
    }
    let r_name = m.points[cam.roller].name.as_str();
    let pr = s.links[cam.follower].point(&cam.roller_local);
    let k_world = contact.roller - contact.normal * contact.pitch_radius_m;
    let cam_link = &s.links[cam.cam];
    let pk: PointMotion = cam_link.point_at_offset(&(k_world - cam_link.origin.position));
    let r = pr.position - pk.position;
    let omega = cross(&r, &(pr.velocity - pk.velocity)) / r.norm_squared();
    let alpha =
        cross(&r, &(pr.acceleration - pk.acceleration + r * omega * omega)) / r.norm_squared();
    // The follower's motion is what the construction finds: R about the arm's pivot
    // (or along the guide) with its magnitude unknown.
    let lhs = match &cam.guide {
        FollowerGuide::Arm {
            pivot, pivot_world, ..
        } => {
            let o_name = &m.points[m.revolutes[*pivot].point].name;
            let follower = &s.links[cam.follower];
            let r_o = pr.position - pivot_world;
            let (w, a) = (follower.omega_rad_s, follower.alpha_rad_s2);
            relative(r_name, o_name, r_o, w, a, true, accel)
        }
        FollowerGuide::Slide { .. } => riding(m, s, m.ground, r_name, &pr, accel),
    };
    let mut rhs = known_point(m, s, cam.cam, "K", &pk, accel);
    rhs.extend(relative(r_name, "K", r, omega, alpha, false, accel));
    Some((lhs, rhs))
}
