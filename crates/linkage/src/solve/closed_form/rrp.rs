//! The RRP dyad: a link pinned to a known link and to a slider on a known guide.

use nalgebra::UnitComplex;

use super::branches::Branches;
use super::guide::{guide_line, riding_point};
use super::joints::{link_len, rev_local, rev_pin};
use super::parts::{Failure, GroupOk, Pair, Pin, check_margin, direction, splat_rotation};
use crate::dyad::DyadKind;
use crate::dyad::Shortfall;
use crate::error::Result;
use crate::ids::{LinkId, PointId};
use crate::model::{Mechanism, Prismatic};
use crate::motion::{LinkMotion, Vec2, cross, perp};
use crate::real::{Real, splat, splat_vec};

/// Link `i` pinned at `a`, joined at `mid` to slider `j` on a guide of a known link.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Rrp {
    pub i: LinkId,
    pub j: LinkId,
    pub a: Pin,
    pub a_on_i: Vec2,
    pub mid_on_j: Vec2,
    pub len_i: f64,
    pub inv_len_i: f64,
    /// Inverse of the direction of `mid - a` in `i`'s coordinates.
    pub dir_i_inv: UnitComplex<f64>,
    pub slide: Prismatic,
    /// +1: `mid` ahead along the guide of the foot of the perpendicular from `a`.
    pub sign: f64,
    /// The points of the pin `a` and of `mid` (to word a refusal).
    pub points: (PointId, PointId),
}

impl Rrp {
    #[inline(always)]
    pub(super) fn solve<T: Real>(
        &self,
        links: &mut [LinkMotion<T>],
        motion: bool,
        group: usize,
    ) -> std::result::Result<GroupOk<T>, Failure> {
        let pa = self.a.motion(links);
        let line = guide_line(&self.slide, links);
        let u = line.u;
        let b0 = line.through
            + line.slider_rotation * splat_vec(&(self.mid_on_j - self.slide.slider_local));
        let w = b0 - pa.position;
        let l1 = self.len_i;
        let off = cross(&w, &u) * splat(self.inv_len_i);
        let margin = T::one() - off * off;
        check_margin(margin, group)?;
        let s = -w.dot(&u) + splat::<T>(self.sign * l1) * margin.simd_max(T::zero()).simd_sqrt();
        let b = b0 + u * s;
        let r1 = b - pa.position;
        let rot_i = direction(&(r1 * splat::<T>(self.inv_len_i))) * splat_rotation(&self.dir_i_inv);
        let conditioning = (r1.dot(&u) * splat(self.inv_len_i)).simd_abs();
        let guide = links[self.slide.guide];
        let on_guide = guide.material_point_at(&b);
        let [wi, sd, ai, sdd] = if motion {
            Pair::new(perp(&r1), -u, group)?.rates(&(on_guide.velocity - pa.velocity), |wi, sd| {
                on_guide.acceleration + perp(&u) * (splat::<T>(2.0) * guide.omega_rad_s * sd)
                    - pa.acceleration
                    + r1 * (wi * wi)
            })
        } else {
            [T::zero(); 4]
        };
        let pb = riding_point(&on_guide, &u, guide.omega_rad_s, sd, sdd);
        links[self.i] = LinkMotion::from_pin(rot_i, wi, ai, &self.a_on_i, &pa);
        links[self.j] = LinkMotion::from_pin(
            line.slider_rotation,
            guide.omega_rad_s,
            guide.alpha_rad_s2,
            &self.mid_on_j,
            &pb,
        );
        Ok(GroupOk {
            margin,
            conditioning,
        })
    }
}

impl Rrp {
    /// How the dyad falls short with its pin and guide where `links` put them: the
    /// pin's distance from the line the slider's pin runs on, against the link.
    pub(super) fn shortfall(&self, links: &[LinkMotion], names: [String; 2]) -> Shortfall {
        let [end, inner] = names;
        let pa = self.a.motion(links);
        let line = guide_line(&self.slide, links);
        let on_line = line.through
            + line.slider_rotation * splat_vec(&(self.mid_on_j - self.slide.slider_local));
        Shortfall::Guide {
            end,
            inner,
            length: self.len_i,
            offset: cross(&(on_line - pa.position), &line.u).abs(),
        }
    }
}

/// Pin, pin, slider: link `i` pinned at `ra` to known link `ki` and at `rm` to link
/// `j`, which slides in prismatic joint `p` on a known guide.
pub(super) fn rrp_group(
    m: &Mechanism,
    branches: &Branches<'_>,
    (i, ra, ki): (LinkId, usize, LinkId),
    rm: usize,
    (j, p): (LinkId, usize),
) -> Result<Option<(Rrp, PointId)>> {
    let slide = m.sliders[p].clone();
    if slide.slider != j {
        return Ok(None);
    }
    let (a, a_on_i) = rev_pin(m, ra, ki, i);
    let (mid_on_i, mid_on_j) = (rev_local(m, rm, i), rev_local(m, rm, j));
    let (len_i, dir_i) = link_len(m, a_on_i, mid_on_i, i, "two")?;
    let mid = m.revolutes[rm].point;
    let sign = branches.slide_sign(mid, DyadKind::Rrp, "slider joint")?;
    let group = Rrp {
        i,
        j,
        a,
        a_on_i,
        mid_on_j,
        len_i,
        inv_len_i: 1.0 / len_i,
        dir_i_inv: dir_i.inverse(),
        slide,
        sign,
        points: (m.revolutes[ra].point, mid),
    };
    Ok(Some((group, mid)))
}
