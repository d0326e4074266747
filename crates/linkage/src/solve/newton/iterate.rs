//! Solving at one input: continuation to it or Newton iterations in place, then the
//! derivatives of the coordinates with respect to the input and the motion at the
//! input's speed.

use super::{FOLD_STEP, MIN_STEP, Solver};
use crate::error::{LinkageError, Result, Singularity};
use crate::motion::LinkMotion;

impl Solver<'_> {
    /// Solves at `input_rad` with input speed `speed_rad_s` (constant), writing every
    /// link's motion to `links`. Returns a conditioning estimate in [0, 1].
    pub(super) fn solve_links(
        &mut self,
        input_rad: f64,
        speed_rad_s: f64,
        links: &mut [LinkMotion],
    ) -> Result<f64> {
        if !input_rad.is_finite() || !speed_rad_s.is_finite() {
            let value = if input_rad.is_finite() {
                speed_rad_s
            } else {
                input_rad
            };
            return Err(LinkageError::invalid(
                crate::error::Param::NewtonInput,
                value,
                crate::error::Valid::InputFinite,
            ));
        }
        let target = self.target(input_rad)?;
        if self.state.last_input == Some(target) {
            // The same input again (or the pose was just set): correct in place.
            self.correct(target, links)?;
            self.update_derivatives(links)?;
        } else {
            // Inside a traced range the branch is known to reach its folds: follow it
            // as close to them as the trace did.
            let min_step = if self.state.range.is_some() {
                FOLD_STEP
            } else {
                MIN_STEP
            };
            self.continue_to(target, links, min_step)
                .map_err(|stop| stop.error)?;
        }
        // Final motion at the real speed: q̇ = ω q', q̈ = ω² q'' (constant input speed).
        let w = speed_rad_s;
        self.motion_pass(
            links,
            |k| if k == 0 { w } else { w * self.state.dq[k - 1] },
            |k| {
                if k == 0 {
                    0.0
                } else {
                    w * w * self.state.ddq[k - 1]
                }
            },
        );
        Ok(self.state.conditioning)
    }

    /// Newton iterations at fixed input from the current `q`.
    pub(super) fn correct(&mut self, input: f64, links: &mut [LinkMotion]) -> Result<()> {
        let mut res = std::mem::take(&mut self.work.res_buf);
        let outcome = self.iterate(input, links, &mut res);
        self.work.res_buf = res;
        outcome
    }

    /// The Newton loop of [`Self::correct`], with the residual buffer passed in.
    ///
    /// The first iterations reuse the LU of the previous converged pose (chord
    /// Newton): the predictor leaves an error of order h³ and the old Jacobian is off by
    /// order h, so each chord step gains about three digits; when a step gains less
    /// than one, a fresh Jacobian is factored and iterations are Newton's again.
    pub(super) fn iterate(
        &mut self,
        input: f64,
        links: &mut [LinkMotion],
        res: &mut [f64],
    ) -> Result<()> {
        let mut previous = f64::INFINITY;
        let mut fresh = !self.state.lu.is_valid();
        for iter in 0..=self.model.max_iterations {
            self.position_pass(input, links);
            let worst = self.residual(links, res);
            // Growing residual after a few steps: diverging (no solution near here).
            if !worst.is_finite() || (iter >= 4 && worst > previous) {
                return Err(self.diverged(input, iter, worst));
            }
            let slow = worst > 0.1 * previous;
            previous = worst;
            if worst <= self.model.tolerance {
                self.state.last_iterations = iter;
                return Ok(());
            }
            if iter == self.model.max_iterations {
                return Err(self.diverged(input, iter, worst));
            }
            if !fresh && (slow || iter >= 3) {
                self.state.lu.invalidate();
                // Judge divergence from here on by true Newton steps only.
                previous = f64::INFINITY;
            }
            if !self.state.lu.is_valid() {
                self.refactor(links);
                fresh = true;
            }
            let mut solved = self.newton_step(res);
            if !solved && !fresh {
                // The stale factorization is singular; the fresh one may not be.
                self.refactor(links);
                fresh = true;
                solved = self.newton_step(res);
            }
            if !solved {
                return Err(LinkageError::Singular {
                    input_deg: input.to_degrees(),
                    reason: Singularity::LoopJacobian,
                });
            }
            self.state.q += &self.work.rhs;
            // Near a dead point J is ill-conditioned and the residual floor can sit above
            // the tolerance; a step at round-off level means Newton has converged anyway.
            if fresh && self.work.rhs.amax() <= 4.0 * f64::EPSILON * (1.0 + self.state.q.amax()) {
                self.position_pass(input, links);
                // ...but only at a solution: outside the assembly range Newton also
                // stalls, at a least-residual pose that closes nothing.
                let worst = self.residual(links, res);
                if worst <= self.model.stall_residual {
                    self.state.last_iterations = iter + 1;
                    return Ok(());
                }
                return Err(self.diverged(input, iter + 1, worst));
            }
        }
        Err(self.diverged(input, self.model.max_iterations, f64::NAN))
    }

    /// Newton did not reach the tolerance at `input`.
    fn diverged(&self, input: f64, iterations: usize, residual: f64) -> LinkageError {
        LinkageError::NewtonDiverged {
            input_deg: input.to_degrees(),
            iterations,
            residual,
            tolerance: self.model.tolerance,
        }
    }

    /// Builds and factors the Jacobian at the current positions.
    pub(super) fn refactor(&mut self, links: &mut [LinkMotion]) {
        self.build_jacobian(links);
        self.state.lu.factor(&self.work.jac);
    }

    /// Solves `J Δ = −res` into `self.work.rhs` with the held factorization; false if singular.
    pub(super) fn newton_step(&mut self, res: &[f64]) -> bool {
        self.work.rhs.iter_mut().zip(res).for_each(|(r, v)| *r = -v);
        self.state.lu.solve_mut(&mut self.work.rhs)
    }

    /// Computes dq/d(input) and d²q/d(input)² at the converged pose.
    pub(super) fn update_derivatives(&mut self, links: &mut [LinkMotion]) -> Result<()> {
        let n = self.state.q.len();
        self.build_jacobian(links);
        self.state.lu.factor(&self.work.jac);
        let det = self.state.lu.determinant();
        self.state.det_sign = det.signum();
        let norms: f64 = self.work.jac.column_iter().map(|c| c.norm()).product();
        self.state.conditioning = if norms > 0.0 {
            (det.abs() / norms).min(1.0)
        } else {
            1.0
        };
        for r in 0..n {
            self.work.rhs[r] = -self.work.rates[r];
        }
        if !self.state.lu.solve_mut(&mut self.work.rhs) {
            return Err(LinkageError::Singular {
                input_deg: self.state.last_input.unwrap_or(0.0).to_degrees(),
                reason: Singularity::InputDeadPoint,
            });
        }
        self.state.dq.copy_from(&self.work.rhs);
        self.motion_pass(
            links,
            |k| if k == 0 { 1.0 } else { self.state.dq[k - 1] },
            |_| 0.0,
        );
        let mut bias = std::mem::take(&mut self.work.col_buf);
        self.cut_accelerations(links, &mut bias);
        self.work
            .rhs
            .iter_mut()
            .zip(&bias)
            .for_each(|(r, b)| *r = -b);
        self.work.col_buf = bias;
        self.state.lu.solve_mut(&mut self.work.rhs);
        self.state.ddq.copy_from(&self.work.rhs);
        Ok(())
    }
}
