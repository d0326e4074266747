//! The PRP dyad: two sliders on known guides, pinned together.

use super::guide::{guide_line, riding_point};
use super::joints::rev_local;
use super::parts::{Failure, GroupOk, Pair};
use crate::ids::{LinkId, PointId};
use crate::model::{Mechanism, Prismatic};
use crate::motion::{LinkMotion, Vec2, cross, perp};
use crate::real::{Real, splat, splat_vec};

/// Two sliders on known guides, pinned together at `mid`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Prp {
    pub i: LinkId,
    pub j: LinkId,
    pub mid_on_i: Vec2,
    pub mid_on_j: Vec2,
    pub slide_i: Prismatic,
    pub slide_j: Prismatic,
}

impl Prp {
    #[inline(always)]
    pub(super) fn solve<T: Real>(
        &self,
        links: &mut [LinkMotion<T>],
        motion: bool,
        group: usize,
    ) -> std::result::Result<GroupOk<T>, Failure> {
        let li = guide_line(&self.slide_i, links);
        let lj = guide_line(&self.slide_j, links);
        let b_i0 = li.through
            + li.slider_rotation * splat_vec(&(self.mid_on_i - self.slide_i.slider_local));
        let b_j0 = lj.through
            + lj.slider_rotation * splat_vec(&(self.mid_on_j - self.slide_j.slider_local));
        let conditioning = cross(&li.u, &lj.u).simd_abs();
        let pair = Pair::new(li.u, -lj.u, group)?;
        let (s_i, _) = pair.solve(&(b_j0 - b_i0));
        let b = b_i0 + li.u * s_i;
        let gi = links[self.slide_i.guide];
        let gj = links[self.slide_j.guide];
        let on_i = gi.material_point_at(&b);
        let on_j = gj.material_point_at(&b);
        let [sd_i, sd_j, sdd_i, sdd_j] = if motion {
            pair.rates(&(on_j.velocity - on_i.velocity), |sd_i, sd_j| {
                let two = splat::<T>(2.0);
                on_j.acceleration + perp(&lj.u) * (two * gj.omega_rad_s * sd_j)
                    - on_i.acceleration
                    - perp(&li.u) * (two * gi.omega_rad_s * sd_i)
            })
        } else {
            [T::zero(); 4]
        };
        let pb_i = riding_point(&on_i, &li.u, gi.omega_rad_s, sd_i, sdd_i);
        let pb_j = riding_point(&on_j, &lj.u, gj.omega_rad_s, sd_j, sdd_j);
        links[self.i] = LinkMotion::from_pin(
            li.slider_rotation,
            gi.omega_rad_s,
            gi.alpha_rad_s2,
            &self.mid_on_i,
            &pb_i,
        );
        links[self.j] = LinkMotion::from_pin(
            lj.slider_rotation,
            gj.omega_rad_s,
            gj.alpha_rad_s2,
            &self.mid_on_j,
            &pb_j,
        );
        Ok(GroupOk {
            margin: T::one(),
            conditioning,
        })
    }
}

/// A pin between two sliders: link `i` sliding in `pi`, link `j` in `pj`, pinned
/// together at `rm`; `None` unless each slides on a known guide.
pub(super) fn prp_group(
    m: &Mechanism,
    (i, pi): (LinkId, usize),
    rm: usize,
    (j, pj): (LinkId, usize),
) -> Option<(Prp, PointId)> {
    let (si, sj) = (m.sliders[pi].clone(), m.sliders[pj].clone());
    let (si, sj) = if si.slider == i { (si, sj) } else { (sj, si) };
    if si.slider != i || sj.slider != j {
        return None;
    }
    let group = Prp {
        i,
        j,
        mid_on_i: rev_local(m, rm, i),
        mid_on_j: rev_local(m, rm, j),
        slide_i: si,
        slide_j: sj,
    };
    Some((group, m.revolutes[rm].point))
}
