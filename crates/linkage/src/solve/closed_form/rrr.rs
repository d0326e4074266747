//! The RRR dyad: two links pinned at their ends to known links, joined at a middle pin.

use nalgebra::{SimdBool, UnitComplex};

use super::branches::Branches;
use super::joints::{link_len, rev_local, rev_pin};
use super::parts::{Failure, GroupOk, Pair, Pin, check_margin, direction, splat_rotation};
use crate::dyad::Shortfall;
use crate::error::Result;
use crate::ids::{LinkId, PointId};
use crate::model::Mechanism;
use crate::motion::{LinkMotion, Vec2, cross, perp};
use crate::real::{Real, splat};

/// Two revolute links `i` (pinned at `a`) and `j` (pinned at `c`) joined at `mid`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Rrr {
    pub i: LinkId,
    pub j: LinkId,
    pub a: Pin,
    pub a_on_i: Vec2,
    pub mid_on_i: Vec2,
    pub mid_on_j: Vec2,
    pub c: Pin,
    pub c_on_j: Vec2,
    pub len_i: f64,
    pub len_j: f64,
    pub inv_len_i: f64,
    pub inv_len_j: f64,
    /// Inverse of the direction of `mid - a` in `i`'s coordinates.
    pub dir_i_inv: UnitComplex<f64>,
    /// Inverse of the direction of `mid - c` in `j`'s coordinates.
    pub dir_j_inv: UnitComplex<f64>,
    /// +1: `mid` left of a→c.
    pub sign: f64,
    /// The points of the end pins `a` and `c` (to name the branch).
    pub end_points: (PointId, PointId),
}

impl Rrr {
    #[inline(always)]
    pub(super) fn solve<T: Real>(
        &self,
        links: &mut [LinkMotion<T>],
        motion: bool,
        group: usize,
    ) -> std::result::Result<GroupOk<T>, Failure> {
        let pa = self.a.motion(links);
        let pc = self.c.motion(links);
        let d = pc.position - pa.position;
        let dist2 = d.norm_squared();
        let (l1, l2) = (self.len_i, self.len_j);
        if !dist2.simd_gt(T::zero()).all() {
            // Coincident end pins: the dyad is free to turn about them (equal
            // lengths) or cannot close at all.
            let margin = -((l1 - l2) / l1).abs();
            if margin < 0.0 {
                return Err(Failure::CannotAssemble { group, margin });
            }
            return Err(Failure::Singular { group });
        }
        let inv_dist = T::one() / dist2.simd_sqrt();
        let along = (splat::<T>(l1 * l1 - l2 * l2) + dist2) * (splat::<T>(0.5) * inv_dist);
        let ratio = along * splat(self.inv_len_i);
        let margin = T::one() - ratio * ratio;
        check_margin(margin, group)?;
        let h = splat::<T>(l1) * margin.simd_max(T::zero()).simd_sqrt();
        let dhat = d * inv_dist;
        let b = pa.position + dhat * along + perp(&dhat) * (splat::<T>(self.sign) * h);
        let r1 = b - pa.position;
        let r2 = b - pc.position;
        let rot_i = direction(&(r1 * splat::<T>(self.inv_len_i))) * splat_rotation(&self.dir_i_inv);
        let rot_j = direction(&(r2 * splat::<T>(self.inv_len_j))) * splat_rotation(&self.dir_j_inv);
        let conditioning = (cross(&r1, &r2) * splat(self.inv_len_i * self.inv_len_j)).simd_abs();
        let [wi, wj, ai, aj] = if motion {
            Pair::new(perp(&r1), -perp(&r2), group)?
                .rates(&(pc.velocity - pa.velocity), |wi, wj| {
                    pc.acceleration - pa.acceleration + r1 * (wi * wi) - r2 * (wj * wj)
                })
        } else {
            [T::zero(); 4]
        };
        links[self.i] = LinkMotion::from_pin(rot_i, wi, ai, &self.a_on_i, &pa);
        links[self.j] = LinkMotion::from_pin(rot_j, wj, aj, &self.c_on_j, &pc);
        Ok(GroupOk {
            margin,
            conditioning,
        })
    }
}

impl Rrr {
    /// How the dyad falls short with its end pins where `links` put them: their
    /// distance against the links' lengths.
    pub(super) fn shortfall(&self, links: &[LinkMotion], names: [String; 3]) -> Shortfall {
        let [a, c, inner] = names;
        let apart = (self.c.motion(links).position - self.a.motion(links).position).norm();
        Shortfall::Apart {
            ends: [a, c],
            inner,
            lengths: [self.len_i, self.len_j],
            apart,
        }
    }
}

/// Three pins: link `i` pinned at `ra` to known link `ki`, link `j` at `rc` to `kj`,
/// and the two at `rm`.
pub(super) fn rrr_group(
    m: &Mechanism,
    branches: &Branches<'_>,
    (i, ra, ki): (LinkId, usize, LinkId),
    rm: usize,
    (j, rc, kj): (LinkId, usize, LinkId),
) -> Result<(Rrr, PointId)> {
    let (a, a_on_i) = rev_pin(m, ra, ki, i);
    let (c, c_on_j) = rev_pin(m, rc, kj, j);
    let (mid_on_i, mid_on_j) = (rev_local(m, rm, i), rev_local(m, rm, j));
    let (len_i, dir_i) = link_len(m, a_on_i, mid_on_i, i, "two")?;
    let (len_j, dir_j) = link_len(m, c_on_j, mid_on_j, j, "two")?;
    let mid = m.revolutes[rm].point;
    let (pa, pc) = (m.revolutes[ra].point, m.revolutes[rc].point);
    let sign = branches.rrr_sign(mid, pa, pc)?;
    let group = Rrr {
        i,
        j,
        a,
        a_on_i,
        mid_on_i,
        mid_on_j,
        c,
        c_on_j,
        len_i,
        len_j,
        inv_len_i: 1.0 / len_i,
        inv_len_j: 1.0 / len_j,
        dir_i_inv: dir_i.inverse(),
        dir_j_inv: dir_j.inverse(),
        sign,
        end_points: (pa, pc),
    };
    Ok((group, mid))
}
