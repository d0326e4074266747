//! A guide line in world coordinates, and the motion of a point riding it (shared by
//! the sliding dyads).

use nalgebra::{UnitComplex, Vector2};

use super::parts::splat_rotation;
use crate::model::Prismatic;
use crate::motion::{LinkMotion, PointMotion, perp};
use crate::real::{Real, splat, splat_vec};

/// World data of a guide line: direction, the point of the line, the slider's rotation.
pub(super) struct GuideLine<T: Real> {
    pub(super) u: Vector2<T>,
    pub(super) through: Vector2<T>,
    pub(super) slider_rotation: UnitComplex<T>,
}

#[inline(always)]
pub(super) fn guide_line<T: Real>(slide: &Prismatic, links: &[LinkMotion<T>]) -> GuideLine<T> {
    let g = &links[slide.guide];
    GuideLine {
        u: g.rotation * splat_vec(&slide.direction_local),
        through: g.world(&slide.through_local),
        slider_rotation: g.rotation * splat_rotation(&slide.relative),
    }
}

/// Motion of a point riding a guide: the guide's coincident material point plus the
/// sliding velocity, plus the Coriolis term `2 ω_guide × v_rel`.
#[inline(always)]
pub(super) fn riding_point<T: Real>(
    on_guide: &PointMotion<T>,
    u: &Vector2<T>,
    omega_guide: T,
    s_dot: T,
    s_ddot: T,
) -> PointMotion<T> {
    PointMotion {
        position: on_guide.position,
        velocity: on_guide.velocity + u * s_dot,
        acceleration: on_guide.acceleration
            + perp(u) * (splat::<T>(2.0) * omega_guide * s_dot)
            + u * s_ddot,
    }
}
