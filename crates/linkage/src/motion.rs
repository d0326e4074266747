//! Position, velocity and acceleration of points and links: what every solver returns.

use nalgebra::{UnitComplex, Vector2};

/// A plane vector in metres (or m/s, m/s²), world frame.
pub type Vec2 = Vector2<f64>;

/// The z-component of the cross product `a × b`.
#[inline]
pub fn cross(a: &Vec2, b: &Vec2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// `k × v`: `v` turned a quarter turn counter-clockwise.
#[inline]
pub fn perp(v: &Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

/// Position, velocity and acceleration of one point.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PointMotion {
    /// Position, m.
    pub position: Vec2,
    /// Velocity, m/s.
    pub velocity: Vec2,
    /// Acceleration, m/s².
    pub acceleration: Vec2,
}

/// Pose and motion of one rigid link: the rotation of its local frame and the
/// motion of its local origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinkMotion {
    /// Rotation of the link's local frame (stored as cos/sin, so no atan2 in the hot path).
    pub rotation: UnitComplex<f64>,
    /// Angular velocity, rad/s (counter-clockwise positive).
    pub omega_rad_s: f64,
    /// Angular acceleration, rad/s².
    pub alpha_rad_s2: f64,
    /// Motion of the local origin.
    pub origin: PointMotion,
}

impl Default for LinkMotion {
    fn default() -> Self {
        Self {
            rotation: UnitComplex::identity(),
            omega_rad_s: 0.0,
            alpha_rad_s2: 0.0,
            origin: PointMotion::default(),
        }
    }
}

impl LinkMotion {
    /// Angle of the local x-axis, rad, in (-π, π].
    pub fn angle_rad(&self) -> f64 {
        self.rotation.angle()
    }

    /// World position of a point given in link coordinates.
    #[inline]
    pub fn world(&self, local: &Vec2) -> Vec2 {
        self.origin.position + self.rotation * local
    }

    /// Full motion of a point fixed on the link, given in link coordinates.
    #[inline]
    pub fn point(&self, local: &Vec2) -> PointMotion {
        let r = self.rotation * local;
        self.point_at_offset(&r)
    }

    /// Motion of the material point of this link at world offset `r` from its origin.
    #[inline]
    pub fn point_at_offset(&self, r: &Vec2) -> PointMotion {
        let w = self.omega_rad_s;
        PointMotion {
            position: self.origin.position + r,
            velocity: self.origin.velocity + perp(r) * w,
            acceleration: self.origin.acceleration + perp(r) * self.alpha_rad_s2 - r * (w * w),
        }
    }

    /// Motion of the material point of this link that is at world position `p` now.
    #[inline]
    pub fn material_point_at(&self, p: &Vec2) -> PointMotion {
        self.point_at_offset(&(p - self.origin.position))
    }

    /// Places the link so that its local point `local` has motion `pin`, given
    /// rotation, angular velocity and angular acceleration.
    #[inline]
    pub fn from_pin(
        rotation: UnitComplex<f64>,
        omega_rad_s: f64,
        alpha_rad_s2: f64,
        local: &Vec2,
        pin: &PointMotion,
    ) -> Self {
        let to_origin = -(rotation * local);
        let partial = Self {
            rotation,
            omega_rad_s,
            alpha_rad_s2,
            origin: *pin,
        };
        Self {
            origin: partial.point_at_offset(&to_origin),
            ..partial
        }
    }
}

/// Relative motion of a prismatic joint: the slider's displacement along its guide.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SlideMotion {
    /// Displacement along the guide direction from the guide's reference point, m.
    pub displacement_m: f64,
    /// Rate of displacement, m/s.
    pub velocity_m_s: f64,
    /// Second derivative of displacement, m/s².
    pub acceleration_m_s2: f64,
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
