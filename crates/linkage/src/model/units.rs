//! The scene's lengths and angles in SI, and the checks every number passes: finite,
//! positive, an angle a double holds to 1e-11 rad.

use crate::error::SceneProblem;
use crate::error::{LinkageError, Result};
use crate::error::{Param, Valid};
use crate::model::MAX_ANGLE_RAD;
use crate::motion::Vec2;

/// The scene's lengths and angles in SI.
#[derive(Clone, Copy)]
pub(super) struct Units {
    /// Metres per scene length unit.
    pub(super) len: f64,
    /// Radians per scene angle unit.
    pub(super) ang: f64,
}

impl Units {
    /// A scene point, in metres; `ctx` names it where it is not finite (made only
    /// then: a scene is built for every edit and a length's limit search builds it
    /// dozens of times, and its names were a fifth of a build).
    pub(super) fn point(self, ctx: impl Fn() -> String, (x, y): (f64, f64)) -> Result<Vec2> {
        Ok(Vec2::new(
            finite_named(x, || format!("{}.x", ctx()))? * self.len,
            finite_named(y, || format!("{}.y", ctx()))? * self.len,
        ))
    }
}

pub(super) fn invalid(problem: SceneProblem) -> LinkageError {
    LinkageError::from(problem)
}

pub(super) fn finite(name: &str, v: f64) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(LinkageError::invalid(
            Param::Scene(name.to_string()),
            v,
            Valid::Finite,
        ))
    }
}

/// A scene angle `v` in the scene's unit (`rad_per_unit` radians each), in radians.
pub(super) fn scene_angle(name: &str, v: f64, rad_per_unit: f64) -> Result<f64> {
    let rad = finite(name, v)? * rad_per_unit;
    if rad.abs() <= MAX_ANGLE_RAD {
        Ok(rad)
    } else {
        let limit = MAX_ANGLE_RAD / rad_per_unit;
        Err(LinkageError::invalid(
            Param::Scene(name.to_string()),
            v,
            Valid::AngleWithin { limit },
        ))
    }
}

/// `v` if finite and positive, else the refusal naming it (`name` made only then).
pub(super) fn positive_named(v: f64, name: impl FnOnce() -> String) -> Result<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        positive(&name(), v)
    }
}

/// `v` if finite, else the refusal naming it (`name` made only then).
pub(super) fn finite_named(v: f64, name: impl FnOnce() -> String) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        finite(&name(), v)
    }
}

pub(super) fn positive(name: &str, v: f64) -> Result<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(LinkageError::invalid(
            Param::Scene(name.to_string()),
            v,
            Valid::Positive,
        ))
    }
}
