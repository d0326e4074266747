//! The RPR dyad: two links pinned to known links, sliding on each other (the inverted
//! slider of a quick return).

use nalgebra::{SimdBool, UnitComplex};

use super::branches::Branches;
use super::joints::rev_pin;
use super::parts::{Failure, GroupOk, Pair, Pin, check_margin, direction, splat_rotation};
use crate::dyad::DyadKind;
use crate::dyad::Shortfall;
use crate::error::Result;
use crate::ids::{LinkId, PointId};
use crate::model::Mechanism;
use crate::motion::{LinkMotion, Vec2, cross, perp};
use crate::real::{Real, splat};

/// Two links pinned to known links, sliding on each other (inverted slider, quick return).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Rpr {
    /// The sliding link and its pin.
    pub slider: LinkId,
    pub s: Pin,
    pub s_on_slider: Vec2,
    /// The guide link and its pin.
    pub guide: LinkId,
    pub g: Pin,
    pub g_on_guide: Vec2,
    /// Signed distance of the guide pin from the line the slider pin runs on.
    pub offset: f64,
    pub dir_u: UnitComplex<f64>,
    pub relative: UnitComplex<f64>,
    /// +1: the slider pin lies ahead of the guide pin along the guide.
    pub sign: f64,
    /// The points of the slider's pin and the guide's pin (to word a refusal).
    pub points: (PointId, PointId),
}

impl Rpr {
    #[inline(always)]
    pub(super) fn solve<T: Real>(
        &self,
        links: &mut [LinkMotion<T>],
        motion: bool,
        group: usize,
    ) -> std::result::Result<GroupOk<T>, Failure> {
        let ps = self.s.motion(links);
        let pg = self.g.motion(links);
        let d = pg.position - ps.position;
        let dist = d.norm();
        if !dist.simd_gt(T::zero()).all() {
            // The pins coincide: no line through both, the guide's direction is free.
            return Err(Failure::CannotAssemble {
                group,
                margin: -1.0,
            });
        }
        let ratio = splat::<T>(self.offset) / dist;
        let margin = T::one() - ratio * ratio;
        check_margin(margin, group)?;
        let dhat = d / dist;
        // Along (+1) puts the slider pin ahead of the guide pin: (S - G)·U > 0.
        let cos_phi = splat::<T>(-self.sign) * margin.simd_max(T::zero()).simd_sqrt();
        let u = dhat * cos_phi + perp(&dhat) * (-ratio);
        let rot_guide =
            UnitComplex::from_cos_sin_unchecked(u.x, u.y) * splat_rotation(&self.dir_u.inverse());
        let rot_slider = rot_guide * splat_rotation(&self.relative);
        let r = ps.position - pg.position;
        let conditioning = (r.dot(&u) / dist).simd_abs();
        // The slide's own rate and its derivative are the riding point's business.
        let [w, _, al, _] = if motion {
            Pair::new(perp(&r), u, group)?.rates(&(ps.velocity - pg.velocity), |w, sd| {
                ps.acceleration - pg.acceleration + r * (w * w)
                    - perp(&u) * (splat::<T>(2.0) * w * sd)
            })
        } else {
            [T::zero(); 4]
        };
        links[self.guide] = LinkMotion::from_pin(rot_guide, w, al, &self.g_on_guide, &pg);
        links[self.slider] = LinkMotion::from_pin(rot_slider, w, al, &self.s_on_slider, &ps);
        Ok(GroupOk {
            margin,
            conditioning,
        })
    }
}

impl Rpr {
    /// How the dyad falls short with its pins where `links` put them: their
    /// distance against the guide's offset from its pin.
    pub(super) fn shortfall(&self, links: &[LinkMotion], names: [String; 2]) -> Shortfall {
        let [slider_pin, guide_pin] = names;
        let apart = (self.g.motion(links).position - self.s.motion(links).position).norm();
        Shortfall::Slot {
            guide_pin,
            slider_pin,
            offset: self.offset.abs(),
            apart,
        }
    }
}

/// A slider between two pins: prismatic joint `p` between its slider and guide, each
/// pinned to a known link (`i` pinned at `ra` to `ki`, the other at `rc` to `kc`).
pub(super) fn rpr_group(
    m: &Mechanism,
    branches: &Branches<'_>,
    i: LinkId,
    (ra, ki): (usize, LinkId),
    p: usize,
    (rc, kc): (usize, LinkId),
) -> Result<(Rpr, PointId)> {
    let slide = m.sliders[p].clone();
    let (s_rev, s_known, g_rev, g_known) = if slide.slider == i {
        (ra, ki, rc, kc)
    } else {
        (rc, kc, ra, ki)
    };
    let (s, s_on_slider) = rev_pin(m, s_rev, s_known, slide.slider);
    let (g, g_on_guide) = rev_pin(m, g_rev, g_known, slide.guide);
    let q_line = slide.through_local + slide.relative * (s_on_slider - slide.slider_local);
    let offset = cross(&slide.direction_local, &(g_on_guide - q_line));
    let sign = branches.slide_sign(slide.point, DyadKind::Rpr, "sliding joint")?;
    let group = Rpr {
        slider: slide.slider,
        s,
        s_on_slider,
        guide: slide.guide,
        g,
        g_on_guide,
        offset,
        dir_u: direction(&slide.direction_local),
        relative: slide.relative,
        sign,
        points: (m.revolutes[s_rev].point, m.revolutes[g_rev].point),
    };
    Ok((group, slide.point))
}
