//! The parts every dyad is made of: its pins, why it fails, its margin, and the 2×2
//! system it ends in.

use nalgebra::{SimdBool, UnitComplex, Vector2};

use crate::ids::LinkId;
use crate::motion::{LinkMotion, PointMotion, Vec2, cross};
use crate::real::{Real, splat, splat_vec};

/// A pin: a point fixed on a link, given in that link's coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Pin {
    pub link: LinkId,
    pub local: Vec2,
    /// The link is ground: the pin stands still at `local` (no rotation to apply).
    pub on_ground: bool,
}

impl Pin {
    #[inline(always)]
    pub(super) fn motion<T: Real>(&self, links: &[LinkMotion<T>]) -> PointMotion<T> {
        if self.on_ground {
            PointMotion {
                position: splat_vec(&self.local),
                ..Default::default()
            }
        } else {
            links[self.link].point(&self.local)
        }
    }
}

/// Why a group could not be solved (cheap to build; named by [`ClosedForm::describe`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Failure {
    /// Assembly margin < 0 (dimensionless; how far from assembling).
    CannotAssemble { group: usize, margin: f64 },
    /// The velocity system is singular (the group's two directions are parallel).
    Singular { group: usize },
}

/// Result of one group: the assembly margin (> 0 assembles) and the conditioning.
#[derive(Clone, Copy, Debug)]
pub(super) struct GroupOk<T> {
    pub(super) margin: T,
    pub(super) conditioning: T,
}

/// The smallest lane of `x`, a NaN lane counting as -1 (it closes nothing).
#[inline(always)]
pub(super) fn worst_lane<T: Real>(x: T) -> f64 {
    (0..T::LANES)
        .map(|k| x.extract(k))
        .fold(f64::INFINITY, |w, v| {
            if v.is_nan() {
                -1.0_f64.min(w)
            } else {
                w.min(v)
            }
        })
}

/// Fails with `CannotAssemble` unless every lane's margin is above the slack
/// (a NaN margin fails too).
#[inline(always)]
pub(super) fn check_margin<T: Real>(margin: T, group: usize) -> std::result::Result<(), Failure> {
    if margin.simd_ge(splat(-TANGENT_SLACK)).all() {
        Ok(())
    } else {
        Err(Failure::CannotAssemble {
            group,
            margin: worst_lane(margin),
        })
    }
}

/// The 2×2 system `x1·c1 + x2·c2 = rhs` of one group, factored once and solved for
/// the velocity and the acceleration right-hand sides (one division in all).
pub(super) struct Pair<T: Real> {
    pub(super) c1: Vector2<T>,
    pub(super) c2: Vector2<T>,
    pub(super) inv_det: T,
}

impl<T: Real> Pair<T> {
    /// Fails with `Singular` when the columns are parallel (|sin| below 1e-14) in
    /// any lane.
    #[inline(always)]
    pub(super) fn new(
        c1: Vector2<T>,
        c2: Vector2<T>,
        group: usize,
    ) -> std::result::Result<Self, Failure> {
        let det = cross(&c1, &c2);
        // Compared squared: no square roots on the hot path.
        let floor = splat::<T>(1e-28) * c1.norm_squared() * c2.norm_squared();
        if !(det * det).simd_gt(floor).all() {
            return Err(Failure::Singular { group });
        }
        Ok(Self {
            c1,
            c2,
            inv_det: T::one() / det,
        })
    }

    #[inline(always)]
    pub(super) fn solve(&self, rhs: &Vector2<T>) -> (T, T) {
        (
            cross(rhs, &self.c2) * self.inv_det,
            cross(&self.c1, rhs) * self.inv_det,
        )
    }

    /// The group's two rates from the velocities' right-hand side `dv`, then their
    /// derivatives from the accelerations' right-hand side, which `rhs(first,
    /// second)` makes from the rates (centripetal and Coriolis terms): `[first,
    /// second, first', second']`. Every dyad ends its solve so.
    #[inline(always)]
    pub(super) fn rates(&self, dv: &Vector2<T>, rhs: impl FnOnce(T, T) -> Vector2<T>) -> [T; 4] {
        let (first, second) = self.solve(dv);
        let (first_dot, second_dot) = self.solve(&rhs(first, second));
        [first, second, first_dot, second_dot]
    }
}

/// The rotation whose x-axis is the unit vector `unit`.
#[inline(always)]
pub(super) fn direction<T: Real>(unit: &Vector2<T>) -> UnitComplex<T> {
    UnitComplex::from_cos_sin_unchecked(unit.x, unit.y)
}

/// `r` in every lane.
#[inline(always)]
pub(super) fn splat_rotation<T: Real>(r: &UnitComplex<f64>) -> UnitComplex<T> {
    UnitComplex::from_cos_sin_unchecked(splat(r.re), splat(r.im))
}

/// Margins between 0 and this are treated as exact tangency (rounding), not failure.
pub(crate) const TANGENT_SLACK: f64 = 1e-12;
