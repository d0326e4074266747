//! The external Geneva wheel: a crank with a pin turns an n-slot wheel by one slot
//! per turn and holds it still for the rest. With λ = a/c = sin(π/n) (crank radius
//! over centre distance; the pin enters the slot radially) and the crank angle α
//! measured from the line of centres, the wheel turns while |α| ≤ π/2 − π/n by
//!
//! - β = atan(λ sin α / (1 − λ cos α)),
//! - β' = dβ/dα = λ (cos α − λ) / (1 − 2λ cos α + λ²),
//! - β'' = λ (λ² − 1) sin α / (1 − 2λ cos α + λ²)²,
//!
//! per radian and per radian² of crank (times ω and ω² at a crank speed ω). The
//! largest β'' is where cos α = −B + √(B² + 2), B = (1 + λ²)/(4λ).

use serde::Serialize;

use crate::error::{LinkageError, Result};
use crate::error::{Param, Valid};

const PI: f64 = std::f64::consts::PI;

/// An external Geneva drive.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Geneva {
    /// Slots of the wheel (at least 3).
    pub slots: u32,
    /// The crank's pin radius, m.
    pub crank_radius_m: f64,
}

/// The wheel's motion at one crank angle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct GenevaMotion {
    /// The wheel's angle from the middle of its index, rad (±π/n at the ends; held
    /// at its end value through the dwell).
    pub wheel_rad: f64,
    /// dβ/dα.
    pub ratio: f64,
    /// d²β/dα².
    pub acceleration: f64,
    /// Whether the pin is in a slot.
    pub indexing: bool,
}

impl Geneva {
    /// A drive of `slots` slots and a pin on `crank_radius_m`.
    ///
    /// # Errors
    /// Fewer than 3 slots, or a radius that is not finite and positive.
    pub fn new(slots: u32, crank_radius_m: f64) -> Result<Self> {
        if slots < 3 {
            return Err(LinkageError::invalid(
                Param::GenevaSlots,
                f64::from(slots),
                Valid::AtLeast(3),
            ));
        }
        if !(crank_radius_m.is_finite() && crank_radius_m > 0.0) {
            return Err(LinkageError::invalid(
                Param::GenevaCrankRadius,
                crank_radius_m,
                Valid::PositiveShort,
            ));
        }
        Ok(Self {
            slots,
            crank_radius_m,
        })
    }

    /// λ = a/c = sin(π/n).
    pub fn lambda(&self) -> f64 {
        (PI / f64::from(self.slots)).sin()
    }

    /// The centre distance, m.
    pub fn centre_distance_m(&self) -> f64 {
        self.crank_radius_m / self.lambda()
    }

    /// Half the crank angle of an index, rad: π/2 − π/n.
    pub fn half_index_rad(&self) -> f64 {
        0.5 * PI - PI / f64::from(self.slots)
    }

    /// The share of a crank turn the wheel stands still: 1/2 + 1/n.
    pub fn dwell_fraction(&self) -> f64 {
        0.5 + 1.0 / f64::from(self.slots)
    }

    /// The motion at crank angle `alpha` (rad from the line of centres).
    pub fn at(&self, alpha: f64) -> GenevaMotion {
        let a = (alpha + PI).rem_euclid(2.0 * PI) - PI;
        let half = self.half_index_rad();
        let l = self.lambda();
        if a.abs() > half {
            let end = PI / f64::from(self.slots);
            return GenevaMotion {
                wheel_rad: if a > 0.0 { end } else { -end },
                ..GenevaMotion::default()
            };
        }
        let (sn, cs) = a.sin_cos();
        let d = 1.0 - 2.0 * l * cs + l * l;
        GenevaMotion {
            wheel_rad: (l * sn).atan2(1.0 - l * cs),
            ratio: l * (cs - l) / d,
            acceleration: l * (l * l - 1.0) * sn / (d * d),
            indexing: true,
        }
    }

    /// The largest |d²β/dα²| and the crank angle where it is (the positive one).
    pub fn peak_acceleration(&self) -> (f64, f64) {
        let l = self.lambda();
        let b = (1.0 + l * l) / (4.0 * l);
        let alpha = (-b + (b * b + 2.0).sqrt()).clamp(-1.0, 1.0).acos();
        (
            alpha,
            self.at(-alpha)
                .acceleration
                .abs()
                .max(self.at(alpha).acceleration.abs()),
        )
    }
}
