//! Following one branch of the chain along the input: the continuation loop shared by
//! every solve, and the tracing of the branch to its folds (dead points of the input),
//! which gives a chain without a closed form its assembly range.
//!
//! A fold is where the branch turns back in the input: det J goes to zero there and,
//! beyond it, no pose on this branch exists. Natural-parameter continuation cannot
//! pass it, so a fold shows as a step that keeps failing (Newton diverges, or would
//! land on the other assembly mode, with the opposite sign of det J) however short it
//! is made. Halving the step is a bisection on "the branch still exists here", so
//! the last pose reached is the fold to within the shortest step.

use std::f64::consts::{PI, TAU};

use super::{CONTINUATION_STEP, FOLD_STEP, MAX_PREDICTED_CHANGE, Solver};
use crate::assembly::AssemblyRanges;
use crate::error::{AssemblyFailure, LinkageError, Result};
use crate::motion::LinkMotion;

/// Accepted steps in a row after which a halved step is doubled again (up to
/// [`CONTINUATION_STEP`]), so one hard spot does not slow the rest of the path.
const STEPS_BEFORE_GROWTH: u32 = 4;

/// Where a continuation stopped short of its target, and why.
#[derive(Debug)]
pub(super) struct Stop {
    /// The last input reached (a converged pose; the solver is left there).
    pub reached: f64,
    /// What failed beyond it.
    pub error: LinkageError,
}

impl Solver<'_> {
    /// The input (unwrapped, on this branch) that `input_rad` means: on a traced
    /// limited branch the one turn of it inside the range (else an error naming the
    /// range), otherwise the shortest turn from the last input, so that a full cycle
    /// is continuous.
    pub(super) fn target(&self, input_rad: f64) -> Result<f64> {
        let last = self.state.last_input.unwrap_or(input_rad);
        let Some([lo, hi]) = self.state.range else {
            let delta = (input_rad - last + PI).rem_euclid(TAU) - PI;
            return Ok(last + delta);
        };
        // Round-off in reducing the angle must not push a range end out of the range.
        let slack = 1e-12 * (1.0 + lo.abs().max(hi.abs()));
        let x = lo + (input_rad - lo).rem_euclid(TAU);
        if x <= hi + slack {
            return Ok(x.min(hi));
        }
        if x - TAU >= lo - slack {
            return Ok(lo);
        }
        Err(LinkageError::CannotAssemble {
            input_deg: input_rad.to_degrees(),
            reason: AssemblyFailure::BranchFolds {
                lo_rad: lo,
                hi_rad: hi,
            },
            reachable: AssemblyRanges::between(lo, hi),
        })
    }

    /// Traces the branch of the current pose both ways from its input, and from then
    /// on solves only inside the range found (an input outside it is refused with the
    /// range named). Returns the range, or `None` when the input turns fully.
    ///
    /// # Errors
    /// The start pose itself does not solve.
    pub(super) fn trace_range(&mut self, links: &mut [LinkMotion]) -> Result<Option<[f64; 2]>> {
        let start = self.state.last_input.unwrap_or(0.0);
        self.correct(start, links)?;
        self.update_derivatives(links)?;
        // Each way from a copy of the start state; the workspace carries nothing.
        let mut forward = self.state.clone();
        let hi = match self
            .over(&mut forward)
            .continue_to(start + TAU, links, FOLD_STEP)
        {
            Ok(()) => {
                self.state.range = None;
                return Ok(None);
            }
            Err(stop) => stop.reached,
        };
        let mut backward = self.state.clone();
        let lo = self
            .over(&mut backward)
            .continue_to(start - TAU, links, FOLD_STEP)
            .map_or_else(|stop| stop.reached, |()| start - TAU)
            // A branch that does not come back to itself after a turn: one turn of it.
            .max(hi - TAU);
        self.state.range = Some([lo, hi]);
        Ok(self.state.range)
    }

    /// The same model and workspace over another continuation state.
    pub(super) fn over<'b>(&'b mut self, state: &'b mut super::Continuation) -> Solver<'b> {
        Solver {
            model: self.model,
            state,
            work: &mut *self.work,
        }
    }

    /// Continuation from the last input to `target` in steps of at most
    /// [`CONTINUATION_STEP`], each predicted to third order and corrected by Newton,
    /// halved down to `min_step` where a step fails or would change the assembly mode.
    /// On failure the solver is left at the last pose reached.
    pub(super) fn continue_to(
        &mut self,
        target: f64,
        links: &mut [LinkMotion],
        min_step: f64,
    ) -> std::result::Result<(), Stop> {
        let mut at = self.state.last_input.unwrap_or(target);
        let mut h = (target - at).signum() * CONTINUATION_STEP.min((target - at).abs());
        while at != target {
            let remaining = target - at;
            if h.abs() > remaining.abs() {
                h = remaining;
            }
            match self.step(at, h, links) {
                Ok(true) => {
                    at += h;
                    if self.state.steady_steps >= STEPS_BEFORE_GROWTH
                        && 2.0 * h.abs() <= CONTINUATION_STEP
                    {
                        h *= 2.0;
                    }
                }
                // The predicted change is too large: shorter, not a failure.
                Ok(false) => h *= 0.5,
                Err(error) => {
                    h *= 0.5;
                    if h.abs() < min_step {
                        self.state.last_input = Some(at);
                        return Err(Stop { reached: at, error });
                    }
                }
            }
            if (target - at).abs() <= 1e-15 * (1.0 + at.abs()) {
                at = target;
            }
        }
        self.state.last_input = Some(target);
        Ok(())
    }

    /// One continuation step from `at` by `h`: `Ok(true)` when taken, `Ok(false)` when
    /// the predictor says it is too long, an error when the correction fails or lands
    /// on the other assembly mode (the state is then restored to `at`).
    pub(super) fn step(&mut self, at: f64, h: f64, links: &mut [LinkMotion]) -> Result<bool> {
        let saved_sign = self.state.det_sign;
        self.work.saved.0.copy_from(&self.state.q);
        self.work.saved.1.copy_from(&self.state.dq);
        self.work.saved.2.copy_from(&self.state.ddq);
        // Third-order predictor q + q' h + q'' h²/2 + q''' h³/6, built in place: its
        // error of order h⁴ lets one chord step usually reach the tolerance (with the
        // h² term alone it took two).
        self.work.increment.copy_from(&self.state.dq);
        self.work.increment *= h;
        self.work.increment.axpy(0.5 * h * h, &self.state.ddq, 1.0);
        self.work
            .increment
            .axpy(h * h * h / 6.0, &self.state.jerk, 1.0);
        // Near a dead point the derivatives blow up: a large predicted change means the
        // step is too long for the branch to be followed safely.
        if self.relative_increment() > MAX_PREDICTED_CHANGE && h.abs() >= 2e-7 {
            return Ok(false);
        }
        self.state.q += &self.work.increment;
        let ok = self
            .correct(at + h, links)
            .and_then(|_| self.update_derivatives(links));
        // The sign of det J flips exactly where the solution passes to the other
        // assembly mode: refuse that step.
        let jumped = saved_sign != 0.0 && self.state.det_sign != saved_sign;
        if ok.is_err() || jumped {
            self.state.q.copy_from(&self.work.saved.0);
            self.state.dq.copy_from(&self.work.saved.1);
            self.state.ddq.copy_from(&self.work.saved.2);
            self.state.det_sign = saved_sign;
            // The factorization belongs to the failed pose: start the retry fresh.
            self.state.lu.invalidate();
            // Near a dead point q''' is not worth extrapolating.
            self.state.jerk.fill(0.0);
            self.state.steady_steps = 0;
            return Err(match ok {
                Err(e) => e,
                Ok(()) => LinkageError::BranchJump {
                    input_deg: (at + h).to_degrees(),
                },
            });
        }
        if self.state.steady_steps > 0 {
            // q''' ≈ (q''(at + h) - q''(at)) / h.
            self.state.jerk.copy_from(&self.state.ddq);
            self.state.jerk.axpy(-1.0 / h, &self.work.saved.2, 1.0 / h);
        }
        self.state.steady_steps = self.state.steady_steps.saturating_add(1);
        self.wrap_angles();
        Ok(true)
    }

    /// The largest predicted change of a coordinate: rad for a turning joint, and for
    /// a sliding one metres over the mechanism's size, so that steps are cut alike at
    /// every scale.
    pub(super) fn relative_increment(&self) -> f64 {
        self.model
            .tree
            .iter()
            .skip(1)
            .zip(self.work.increment.iter())
            .map(|(t, dq)| match t.kind {
                super::TreeKind::Revolute { .. } => dq.abs(),
                super::TreeKind::Prismatic { .. } => dq.abs() / self.model.size_m,
            })
            .fold(0.0, f64::max)
    }
}
