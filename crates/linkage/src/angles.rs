//! Angles followed across turns: a leaf, used by the solver (cam rows), the sweep and
//! the dynamics alike.

/// `angle` shifted by whole turns to be within π of `reference`.
pub fn unwrap_near(angle: f64, reference: f64) -> f64 {
    angle + ((reference - angle) / std::f64::consts::TAU).round() * std::f64::consts::TAU
}
