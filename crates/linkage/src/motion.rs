//! Position, velocity and acceleration of points and links: what every solver returns.
//!
//! The types are generic over the number type: `f64` for one position, or
//! [`crate::real::Lanes`] for several positions solved together in SIMD lanes
//! (the same code, see [`crate::LaneSolution`]). The default is `f64`.

use nalgebra::{UnitComplex, Vector2};

use crate::real::{Real, splat_vec};

/// A plane vector in metres (or m/s, m/s²), world frame.
pub type Vec2 = Vector2<f64>;

/// The z-component of the cross product `a × b`.
#[inline]
pub fn cross<T: Real>(a: &Vector2<T>, b: &Vector2<T>) -> T {
    a.x * b.y - a.y * b.x
}

/// `k × v`: `v` turned a quarter turn counter-clockwise.
#[inline]
pub fn perp<T: Real>(v: &Vector2<T>) -> Vector2<T> {
    Vector2::new(-v.y, v.x)
}

/// Position, velocity and acceleration of one point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointMotion<T: Real = f64> {
    /// Position, m.
    pub position: Vector2<T>,
    /// Velocity, m/s.
    pub velocity: Vector2<T>,
    /// Acceleration, m/s².
    pub acceleration: Vector2<T>,
}

impl<T: Real> Default for PointMotion<T> {
    #[inline(always)]
    fn default() -> Self {
        // Built lane by lane: nalgebra's generic `zeros` is not inlined for SIMD lanes.
        let zero = Vector2::new(T::zero(), T::zero());
        Self {
            position: zero,
            velocity: zero,
            acceleration: zero,
        }
    }
}

/// Pose and motion of one rigid link: the rotation of its local frame and the
/// motion of its local origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinkMotion<T: Real = f64> {
    /// Rotation of the link's local frame (stored as cos/sin, so no atan2 in the hot path).
    pub rotation: UnitComplex<T>,
    /// Angular velocity, rad/s (counter-clockwise positive).
    pub omega_rad_s: T,
    /// Angular acceleration, rad/s².
    pub alpha_rad_s2: T,
    /// Motion of the local origin.
    pub origin: PointMotion<T>,
}

impl<T: Real> Default for LinkMotion<T> {
    #[inline(always)]
    fn default() -> Self {
        Self {
            rotation: UnitComplex::identity(),
            omega_rad_s: T::zero(),
            alpha_rad_s2: T::zero(),
            origin: PointMotion::default(),
        }
    }
}

impl LinkMotion {
    /// Angle of the local x-axis, rad, in (-π, π].
    pub fn angle_rad(&self) -> f64 {
        self.rotation.angle()
    }
}

impl<T: Real> LinkMotion<T> {
    /// World position of a point given in link coordinates.
    #[inline(always)]
    pub fn world(&self, local: &Vec2) -> Vector2<T> {
        self.origin.position + self.rotation * splat_vec(local)
    }

    /// Full motion of a point fixed on the link, given in link coordinates.
    #[inline(always)]
    pub fn point(&self, local: &Vec2) -> PointMotion<T> {
        // Points at the origin are common (a link's frame usually sits on a pin).
        if *local == Vec2::zeros() {
            return self.origin;
        }
        let r = self.rotation * splat_vec(local);
        self.point_at_offset(&r)
    }

    /// Motion of the material point of this link at world offset `r` from its origin.
    #[inline(always)]
    pub fn point_at_offset(&self, r: &Vector2<T>) -> PointMotion<T> {
        let w = self.omega_rad_s;
        PointMotion {
            position: self.origin.position + r,
            velocity: self.origin.velocity + perp(r) * w,
            acceleration: self.origin.acceleration + perp(r) * self.alpha_rad_s2 - r * (w * w),
        }
    }

    /// Motion of the material point of this link that is at world position `p` now.
    #[inline(always)]
    pub fn material_point_at(&self, p: &Vector2<T>) -> PointMotion<T> {
        self.point_at_offset(&(p - self.origin.position))
    }

    /// Places the link so that its local point `local` has motion `pin`, given
    /// rotation, angular velocity and angular acceleration.
    #[inline(always)]
    pub fn from_pin(
        rotation: UnitComplex<T>,
        omega_rad_s: T,
        alpha_rad_s2: T,
        local: &Vec2,
        pin: &PointMotion<T>,
    ) -> Self {
        let placed = Self {
            rotation,
            omega_rad_s,
            alpha_rad_s2,
            origin: *pin,
        };
        // A frame whose origin is the pin itself (the usual case) needs no offset.
        if *local == Vec2::zeros() {
            return placed;
        }
        let to_origin = -(rotation * splat_vec(local));
        Self {
            origin: placed.point_at_offset(&to_origin),
            ..placed
        }
    }
}

/// Relative motion of a prismatic joint: the slider's displacement along its guide.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SlideMotion<T: Real = f64> {
    /// Displacement along the guide direction from the guide's reference point, m.
    pub displacement_m: T,
    /// Rate of displacement, m/s.
    pub velocity_m_s: T,
    /// Second derivative of displacement, m/s².
    pub acceleration_m_s2: T,
}

/// One solved position of a whole mechanism.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Solution {
    /// Input (crank) angle, rad.
    pub input_rad: f64,
    /// Input angular speed used for velocities and accelerations, rad/s.
    pub input_speed_rad_s: f64,
    /// Motion of every link, indexed like `Mechanism::links` (ground included).
    pub links: Vec<LinkMotion>,
    /// Motion of every named point, indexed like `Mechanism::points`.
    pub points: Vec<PointMotion>,
    /// Relative motion of every prismatic joint, indexed like `Mechanism::sliders`.
    pub slides: Vec<SlideMotion>,
    /// Smallest |sin| of the angle between the two unknown directions of any group
    /// (1 = well conditioned, 0 = dead point). Below about 1e-6 velocities lose digits.
    pub conditioning: f64,
}
