//! The integrators a dynamic run can use, as data: their names and stability limits.
//! A leaf, so that a refusal (`error/`) can name the method it concerns; the
//! integrators themselves are in `dynamics/`.

use serde::Serialize;

/// Integration method.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Method {
    /// The paper's energy increments: ½J₁w₁² = ½J₀w₀² + M₀Δφ, dt = 2Δφ/(w₀ + w₁); first
    /// order, steps of Δφ in the coordinate.
    EnergyIncrement,
    /// Semi-implicit (symplectic) Euler; first order, bounded energy error.
    SemiImplicitEuler,
    /// Classical fourth-order Runge–Kutta, fixed step.
    Rk4,
    /// Implicit midpoint rule, fixed step: A-stable and symplectic, for stiff springs.
    ImplicitMidpoint,
    /// Adaptive Dormand–Prince 5(4) with dense output.
    Dp5,
    /// Adaptive Dormand–Prince 8(5,3) with seventh-order dense output.
    Dop853,
}

impl Method {
    /// Every method, in order of increasing order of accuracy (for tables).
    pub const ALL: [Method; 6] = [
        Method::EnergyIncrement,
        Method::SemiImplicitEuler,
        Method::ImplicitMidpoint,
        Method::Rk4,
        Method::Dp5,
        Method::Dop853,
    ];

    /// Whether the step size follows from rtol/atol.
    pub fn is_adaptive(self) -> bool {
        matches!(self, Method::Dp5 | Method::Dop853)
    }

    /// Short name, as the CLI spells it.
    pub fn label(self) -> &'static str {
        match self {
            Method::EnergyIncrement => "energy",
            Method::SemiImplicitEuler => "euler",
            Method::Rk4 => "rk4",
            Method::ImplicitMidpoint => "implicit",
            Method::Dp5 => "dp5",
            Method::Dop853 => "dop853",
        }
    }

    /// Largest h·|λ| for which the method is stable on an undamped oscillation
    /// (λ on the imaginary axis); `None` for the unconditionally stable implicit rule
    /// and for the energy method, which steps in the coordinate, not in time.
    pub fn stability_limit(self) -> Option<f64> {
        match self {
            // Symplectic Euler on x'' = −ω²x is stable for hω < 2.
            Method::SemiImplicitEuler => Some(2.0),
            // RK4's stability region meets the imaginary axis at 2√2.
            Method::Rk4 => Some(2.0 * std::f64::consts::SQRT_2),
            // Adaptive methods keep themselves stable by shrinking the step; these
            // are where |R(iy)| first exceeds 1 (checked in the tests from the
            // tableaus), for the cost warning. DP5 hugs the imaginary axis only to 1.
            Method::Dp5 => Some(0.997),
            Method::Dop853 => Some(5.96),
            Method::EnergyIncrement | Method::ImplicitMidpoint => None,
        }
    }
}
