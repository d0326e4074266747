//! The torques through a train: with a load on one member, the torque every member
//! with a given speed takes from outside (the motor's, a brake's) and the power each
//! member exchanges, for ideal gears or with the file's efficiencies.
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
//!
//! With efficiencies (a mesh's η, a stage's), the ideal multipliers first say which
//! side of each mesh drives, relative to the member holding it (the sign of the power
//! it takes from that side); the coefficient of the side the power reaches is then
//! η times its ideal one and the holder's bearing takes the difference, so that the
//! driven side gets η of what the driver gives in the relative motion: in series,
//! the textbooks' products of efficiencies; in a planetary set, the converted
//! train's efficiency where the power flows (for the ring held and the sun driving,
//! η = (1 + η^H z_r/z_s)/(1 + z_r/z_s)).

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
    /// The power lost in the meshes and stages, W: what the members take in, less
    /// what they give out (0 for ideal gears, as the file's efficiencies are absent).
    pub lost_w: f64,
}

const RPM: f64 = std::f64::consts::TAU / 60.0;

/// `sum` of `terms`, or 0 where it is round-off of their largest (torques or powers
/// that cancel).
fn zero_to_round_off(sum: f64, terms: &[f64]) -> f64 {
    let largest = terms.iter().fold(0.0_f64, |m, t| m.max(t.abs()));
    if sum.abs() <= 1e-12 * largest {
        0.0
    } else {
        sum
    }
}

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
        // Ideal first: the multipliers say which way power crosses each mesh and
        // stage (relative to the member holding it), and so which side its losses
        // come off; then the train with its efficiencies.
        let (ideal_torques, ideal, determinate) =
            self.balance(&self.rows, &held, load_at, torque_n_m)?;
        let lossless = super::train_rows::efficiencies(&self.file)
            .iter()
            .all(|&eta| eta >= 1.0);
        let torques = if lossless {
            ideal_torques
        } else if !determinate {
            // A loop of meshes or stages splits the load by the parts' stiffness,
            // which the train does not know: its losses cannot be apportioned.
            return Err(TrainError::LossesIndeterminate);
        } else {
            self.lossy_balance(ideal, solution, &held, load_at, torque_n_m)?
        };
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
        let frame = -torques.iter().sum::<f64>();
        let powers: Vec<f64> = members.iter().map(|m| m.power_w).collect();
        // The power lost, what the members take in less what they give out.
        let lost = powers.iter().sum::<f64>();
        Ok(TrainTorques {
            lost_w: zero_to_round_off(lost, &powers),
            loaded: loaded.into(),
            frame_n_m: zero_to_round_off(frame, &torques),
            members,
        })
    }

    /// The torques with losses: the sides power reaches taken from the ideal
    /// multipliers, then from the lossy ones until they agree. Where losses turn
    /// the power round in a mesh (a closed differential with low efficiencies) the
    /// sides are chosen anew; where no choice agrees with its own solution the train
    /// locks itself.
    fn lossy_balance(
        &self,
        ideal: Vec<f64>,
        solution: &TrainSolution,
        held: &[usize],
        load_at: usize,
        load: f64,
    ) -> Result<Vec<f64>, TrainError> {
        let mut rows = self.lossy_rows(&ideal, solution);
        for _ in 0..self.rows.len() + 2 {
            let (torques, lambda, _) = self.balance(&rows, held, load_at, load)?;
            let again = self.lossy_rows(&lambda, solution);
            if again == rows {
                return Ok(torques);
            }
            rows = again;
        }
        Err(TrainError::SelfLocking)
    }

    /// Solves Aᵀ λ − Σ_held e_i T_i = load for λ and the held members' torques, A
    /// `rows`; every member's torque from outside, λ, and whether λ is the only
    /// solution (no loop of meshes or stages that the load could go round).
    fn balance(
        &self,
        rows: &[Vec<f64>],
        held: &[usize],
        load_at: usize,
        load: f64,
    ) -> Result<(Vec<f64>, Vec<f64>, bool), TrainError> {
        let (n, r) = (self.file.members.len(), rows.len());
        let mut a = DMatrix::<f64>::zeros(n, r + held.len());
        for (k, row) in rows.iter().enumerate() {
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
        let rank = svd.singular_values.iter().filter(|&&v| v > tol).count();
        let determinate = rank == r + held.len();
        Ok((torques, x.rows(0, r).iter().copied().collect(), determinate))
    }

    /// The rows with their efficiencies: in each mesh or stage, the coefficient of
    /// the side that power reaches (relative to the member holding it) times η, the
    /// holder's changed so that the row's coefficients still sum to nothing (the
    /// bearings take the difference). Its power Σ c_i ω_i λ is then (1 − η) times
    /// the power the driving side gives, lost.
    fn lossy_rows(&self, ideal: &[f64], solution: &TrainSolution) -> Vec<Vec<f64>> {
        let speeds: Vec<f64> = solution.speeds_rpm.iter().map(|s| s.rpm).collect();
        let eta = super::train_rows::efficiencies(&self.file);
        // Side a's share of each row's torque (T = Aᵀλ is the torque from outside
        // that the row passes on) times its speed relative to the holder: positive
        // where a takes power in and drives the other side.
        let drives_a: Vec<f64> = self
            .rows
            .iter()
            .zip(&self.row_members)
            .zip(ideal)
            .map(|((row, ties), &lambda)| {
                let holder = ties.holder.map_or(0.0, |h| speeds[h]);
                ties.a
                    .map_or(0.0, |a| row[a] * lambda * (speeds[a] - holder))
            })
            .collect();
        let largest = drives_a.iter().fold(0.0_f64, |m, p| m.max(p.abs()));
        self.rows
            .iter()
            .zip(&self.row_members)
            .zip(drives_a.iter().zip(eta))
            .map(|((row, ties), (&power, eta))| {
                let mut row = row.clone();
                // A row that carries no power loses none (a second mesh of the same
                // gears, a gear running idle): left ideal, so that a loss cannot
                // make its multiplier free.
                if eta >= 1.0 || power.abs() <= 1e-8 * largest {
                    return row;
                }
                // A side on the frame has no column: the other is reached.
                let reached = if power > 0.0 || ties.a.is_none() {
                    ties.b
                } else {
                    ties.a
                };
                if let Some(r) = reached {
                    let before = row[r];
                    row[r] *= eta;
                    if let Some(h) = ties.holder {
                        row[h] += before - row[r];
                    }
                }
                row
            })
            .collect()
    }
}
