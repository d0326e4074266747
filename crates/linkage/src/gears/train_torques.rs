//! The torques through a train: with a load on one member, the torque every member
//! with a given speed takes from outside (the motor's, a brake's) and the power each
//! member exchanges, for ideal gears (no friction).
//!
//! The external torques are the constraint rows' multipliers: T = Aᵀ λ, where row k
//! of A is mesh k's Willis relation z_A (ω_A − ω_C) + σ z_B (ω_B − ω_C) = 0 (or a
//! stage's), and λ_k is the tooth force times half the module; the torque of mesh k
//! on gear A is z_A λ_k, on B σ z_B λ_k, and on the carrier C holding both axes
//! −(z_A + σ z_B) λ_k through the planet's bearing. A member whose speed is not
//! given (a planet, an idler, the carrier of a set driven at its sun) takes no
//! torque from outside but the load; the members with given speeds take whatever
//! balances it. The power Σ T_i ω_i is then zero (Aω = 0), which the tests check
//! together with the textbooks' closed forms.

use nalgebra::{DMatrix, DVector};
use serde::Serialize;

use super::train::Train;
use super::train_results::{TrainError, TrainSolution};

/// A member's torque from outside and its power.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MemberTorque {
    /// The member.
    pub member: String,
    /// The torque on it from outside the train (the load, a motor, a brake),
    /// counter-clockwise positive seen from the front, N·m.
    pub torque_n_m: f64,
    /// The power it takes in, T ω, W (negative where it gives power out).
    pub power_w: f64,
}

/// Every member's torque with a load on one.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TrainTorques {
    /// The loaded member.
    pub loaded: String,
    /// Each member, in the file's order.
    pub members: Vec<MemberTorque>,
    /// The torque the frame takes (the housing's reaction), N·m: the sum of the
    /// members' torques reversed.
    pub frame_n_m: f64,
}

const RPM: f64 = std::f64::consts::TAU / 60.0;

impl Train {
    /// The torques with `torque_n_m` on `loaded` (from outside, counter-clockwise
    /// positive) at the speeds of `solution`.
    ///
    /// # Errors
    /// `loaded` not a member, or one whose speed is given (a load there goes
    /// straight to what drives or holds it); a train whose inputs do not fix it.
    pub fn torques(
        &self,
        solution: &TrainSolution,
        loaded: &str,
        torque_n_m: f64,
    ) -> Result<TrainTorques, TrainError> {
        let n = self.file.members.len();
        let load_at = self.index(loaded).ok_or_else(|| TrainError::Unknown {
            what: crate::error::TrainField::Load,
            name: loaded.into(),
            kind: crate::error::NameKind::Members,
        })?;
        let held: Vec<usize> = self
            .file
            .inputs
            .iter()
            .filter_map(|i| self.index(&i.member))
            .collect();
        if held.contains(&load_at) {
            return Err(TrainError::LoadWhereSpeedGiven {
                member: loaded.into(),
            });
        }
        let torques = self.balance(&held, load_at, torque_n_m)?;
        let members = self
            .file
            .members
            .iter()
            .zip(&torques)
            .zip(&solution.speeds_rpm)
            .map(|((m, &t), w)| MemberTorque {
                member: m.name.clone(),
                torque_n_m: t,
                power_w: t * w.rpm * RPM,
            })
            .collect::<Vec<_>>();
        debug_assert_eq!(members.len(), n);
        // The housing's reaction, 0 where the members' torques cancel to round-off
        // (a planetary set whose brake is a member held by an input).
        let frame: f64 = -torques.iter().sum::<f64>();
        let largest = torques.iter().fold(0.0_f64, |m, t| m.max(t.abs()));
        Ok(TrainTorques {
            loaded: loaded.into(),
            frame_n_m: if frame.abs() <= 1e-12 * largest {
                0.0
            } else {
                frame
            },
            members,
        })
    }

    /// Solves Aᵀ λ − Σ_held e_i T_i = load for λ and the held members' torques;
    /// every member's torque from outside.
    fn balance(&self, held: &[usize], load_at: usize, load: f64) -> Result<Vec<f64>, TrainError> {
        let (n, r) = (self.file.members.len(), self.rows.len());
        let mut a = DMatrix::<f64>::zeros(n, r + held.len());
        for (k, row) in self.rows.iter().enumerate() {
            for (i, &v) in row.iter().enumerate() {
                a[(i, k)] = v;
            }
        }
        for (j, &i) in held.iter().enumerate() {
            a[(i, r + j)] = -1.0;
        }
        let mut b = DVector::<f64>::zeros(n);
        b[load_at] = load;
        let svd = a.clone().svd(true, true);
        let tol = 1e-10 * svd.singular_values.max().max(1.0);
        let tied = || TrainError::InputsTied {
            member: self.file.members[load_at].name.clone(),
        };
        let x = svd.solve(&b, tol).map_err(|_| tied())?;
        if (&a * &x - &b).norm() > 1e-9 * load.abs().max(f64::MIN_POSITIVE) {
            return Err(tied());
        }
        // A member neither loaded nor held takes nothing from outside (its row of
        // the system says so, to round-off); the held ones what they were solved for.
        let mut torques = vec![0.0; n];
        torques[load_at] = load;
        for (j, &i) in held.iter().enumerate() {
            // Round-off of a zero (a held member the load does not reach) as 0.
            let t = x[r + j];
            torques[i] = if t.abs() <= 1e-12 * load.abs() {
                0.0
            } else {
                t
            };
        }
        Ok(torques)
    }
}
