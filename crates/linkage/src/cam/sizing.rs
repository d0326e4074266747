//! Sizing a disc cam: the smallest base circle that keeps the pressure angle within
//! a limit, and the follower's contact force with the spring preload that keeps it
//! on the cam at the cam's speed.
//!
//! The follower (mass m, or the arm's inertia I about its pivot) is pressed onto the
//! cam by a spring of rate k with preload F₀ and by a constant load P (a weight, a
//! process force) against its rise. Along its travel, the cam's normal force N at the
//! pressure angle φ balances them and the follower's inertia at a cam speed ω:
//!
//! N cos φ · r = m ω² s'' + k s + F₀ + P  (r = 1 translating; r = the arm for an
//! oscillating follower, with I for m and moments for forces).
//!
//! The follower stays on the cam while N ≥ 0, that is while F₀ ≥ −(m ω² s'' + k s + P):
//! the least preload is the largest of that over the turn.

use serde::Serialize;

use super::disc::{DiscCam, Follower};
use crate::error::{LinkageError, Result};
use crate::error::{Param, Valid};

/// What presses the follower onto the cam.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct FollowerLoad {
    /// The follower's mass, kg (translating), or its inertia about the pivot, kg·m²
    /// (oscillating).
    pub inertia: f64,
    /// The spring's rate, N/m (or N·m/rad).
    pub spring_rate: f64,
    /// The spring's force at the lowest position, N (or N·m).
    pub preload: f64,
    /// A constant load against the rise, N (or N·m).
    pub load: f64,
}

/// The contact at one cam angle.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Contact {
    /// Cam angle, rad.
    pub angle_rad: f64,
    /// The cam's normal force on the follower, N (negative: the follower leaves).
    pub force_n: f64,
}

impl DiscCam {
    /// The moment arm that turns the follower's load along its travel into the
    /// normal force: 1 for a translating follower, the arm for an oscillating one.
    fn lever(&self) -> f64 {
        match self.follower {
            Follower::Translating { .. } => 1.0,
            Follower::Oscillating { arm_m, .. } => arm_m,
        }
    }

    /// What the normal force must balance along the travel at `theta`, before the
    /// preload: m ω² s'' + k s + P.
    fn demand(&self, theta: f64, speed_rad_s: f64, l: &FollowerLoad) -> f64 {
        let m = self.program.at(theta);
        l.inertia * speed_rad_s * speed_rad_s * m.a + l.spring_rate * m.s + l.load
    }

    /// The cam's normal force on the follower at `theta`.
    pub fn contact(&self, theta: f64, speed_rad_s: f64, l: &FollowerLoad) -> Contact {
        let p = self.at(theta);
        let along = self.demand(theta, speed_rad_s, l) + l.preload;
        Contact {
            angle_rad: theta,
            force_n: along / (self.lever() * p.pressure_angle_rad.cos()),
        }
    }

    /// The least spring preload that keeps the follower on the cam at
    /// `speed_rad_s`: the largest −(m ω² s'' + k s + P) over the turn (0 if the load
    /// alone keeps it there), found by a scan and a golden-section search per
    /// segment.
    pub fn least_preload(&self, speed_rad_s: f64, l: &FollowerLoad) -> f64 {
        let f = |t: f64| -self.demand(t, speed_rad_s, l);
        self.program
            .spans()
            .into_iter()
            .map(|(a, b)| super::extremes::largest(&f, a, b).value)
            .fold(0.0, f64::max)
    }

    /// The smallest base circle (its radius, m) at which the pressure angle stays
    /// within `limit_rad` over the turn, found by bisection to 1e-12 relative. Where a
    /// roller keeps the angle within the limit on any base circle, the answer is the
    /// floor of the search, 1e-9 of the larger of the lift and the base radius.
    ///
    /// # Errors
    /// A limit outside (0°, 90°), or one no base circle up to 10⁴ times the lift
    /// reaches.
    pub fn smallest_base_radius(&self, limit_rad: f64) -> Result<f64> {
        if !(limit_rad > 0.0 && limit_rad < 0.5 * std::f64::consts::PI) {
            return Err(LinkageError::invalid(
                Param::PressureAngleLimit,
                limit_rad.to_degrees(),
                Valid::Between0And90,
            ));
        }
        let worst = |r: f64| -> Option<f64> {
            let cam = DiscCam::new(self.program.clone(), r, self.follower).ok()?;
            let x = cam.extremes();
            Some(
                x.pressure_by_segment
                    .iter()
                    .map(|e| e.value.abs())
                    .fold(0.0, f64::max),
            )
        };
        let fits = |r: f64| worst(r).is_some_and(|w| w <= limit_rad);
        let scale = self.program.largest_lift().max(self.base_radius_m);
        let mut hi = self.base_radius_m;
        while !fits(hi) {
            hi *= 2.0;
            if hi > 1e4 * scale {
                return Err(LinkageError::invalid(
                    Param::PressureAngleLimit,
                    limit_rad.to_degrees(),
                    Valid::BaseCircleUpTo {
                        most_m: 1e4 * scale,
                    },
                ));
            }
        }
        // A roller can keep the pressure angle within the limit on its own, down to
        // any base circle: then the floor is the answer.
        let floor = 1e-9 * scale;
        if fits(floor) {
            return Ok(floor);
        }
        let mut lo = floor;
        // Halving a bracket of at most 10⁴ · scale down to 1e-12 of itself takes
        // under 60 steps; the bound keeps a non-monotone case from looping.
        for _ in 0..200 {
            if hi - lo <= 1e-12 * hi {
                break;
            }
            let mid = 0.5 * (lo + hi);
            if fits(mid) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        Ok(hi)
    }
}
