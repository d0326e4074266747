//! Levenberg–Marquardt for the small problems of path refinement (about 10 to 30
//! unknowns). Written here rather than taken from `levenberg-marquardt` or `argmin`:
//! both are built on nalgebra 0.34 or older while the solver uses 0.35, so either
//! would compile and ship a second nalgebra (into the WASM build too); and this
//! problem needs one thing they do not offer, residuals that may not exist (a trial
//! step where the loop does not close is refused like a step that raises the cost).

use std::collections::VecDeque;

use nalgebra::{DMatrix, DVector};

/// How a refinement ended.
#[derive(Clone, Debug, PartialEq)]
pub struct Fitted {
    /// The unknowns at the end.
    pub x: Vec<f64>,
    /// Sum of squared residuals at the end.
    pub cost: f64,
    /// Residual evaluations used (the Jacobian's included).
    pub evaluations: u64,
}

/// Settings of a refinement.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Most iterations.
    pub iterations: usize,
    /// Stop once the cost falls below this.
    pub cost_floor: f64,
    /// Central-difference step of the Jacobian.
    pub step: f64,
    /// Stop when the cost has not fallen below this share of itself over the last
    /// [`STALL_WINDOW`] iterations (1 for never).
    pub stall: f64,
}

/// The share of a step at which its geodesic acceleration is probed.
const ACCELERATION_PROBE: f64 = 0.1;
/// The largest bend kept, as a share of the step (Transtrum's α, halved: his test
/// is twice the bend against the step).
const MAX_BEND: f64 = 0.375;

/// Iterations over which [`Settings::stall`] judges progress.
pub const STALL_WINDOW: usize = 25;

/// A refinement under way, advanced an iteration at a time ([`Minimiser::iterate`]),
/// so that a caller that must keep drawing frames can spread it over them.
#[derive(Clone, Debug)]
pub struct Minimiser {
    x: Vec<f64>,
    r: Vec<f64>,
    cost: f64,
    lambda: f64,
    settings: Settings,
    /// The cost at the last iterations, for the stall rule.
    history: VecDeque<f64>,
    iterations: usize,
    evaluations: u64,
    done: bool,
}

impl Minimiser {
    /// A refinement of the sum of squares of the `m` residuals from `x0`; `None` when
    /// they do not exist there.
    pub fn new(
        x0: &[f64],
        m: usize,
        settings: Settings,
        residuals: &mut impl FnMut(&[f64], &mut [f64]) -> bool,
    ) -> Option<Self> {
        let mut r = vec![0.0; m];
        if !residuals(x0, &mut r) {
            return None;
        }
        Some(Self {
            x: x0.to_vec(),
            cost: sum_sq(&r),
            r,
            lambda: 1e-3,
            settings,
            history: VecDeque::with_capacity(STALL_WINDOW + 1),
            iterations: 0,
            evaluations: 1,
            done: false,
        })
    }

    /// Whether it has ended (converged, stalled, or out of iterations).
    pub fn is_done(&self) -> bool {
        self.done
    }

    /// The residuals where it stands.
    pub fn residuals(&self) -> &[f64] {
        &self.r
    }

    /// Where it stands.
    pub fn fitted(&self) -> Fitted {
        Fitted {
            x: self.x.clone(),
            cost: self.cost,
            evaluations: self.evaluations,
        }
    }

    /// One iteration (a Jacobian and the damped steps until one lowers the cost);
    /// returns the evaluations it used.
    pub fn iterate(&mut self, residuals: &mut impl FnMut(&[f64], &mut [f64]) -> bool) -> u64 {
        let before = self.evaluations;
        if self.done || self.stops() {
            self.done = true;
            return 0;
        }
        self.iterations += 1;
        let (jac, used) = jacobian(&self.x, self.r.len(), self.settings.step, residuals);
        self.evaluations += used;
        let jt = jac.transpose();
        let jtj = &jt * &jac;
        let grad = &jt * DVector::from_column_slice(&self.r);
        let mut trial_r = vec![0.0; self.r.len()];
        let mut improved = false;
        // Raise the damping until a step lowers the cost (or it is hopeless).
        while self.lambda < 1e12 {
            let mut damped = jtj.clone();
            for i in 0..self.x.len() {
                damped[(i, i)] += self.lambda * jtj[(i, i)].max(1e-12);
            }
            let Some(chol) = damped.cholesky() else {
                self.lambda *= 10.0;
                continue;
            };
            let delta = chol.solve(&(-&grad));
            let delta = self.accelerated(&jac, &chol, delta, residuals);
            let trial: Vec<f64> = self
                .x
                .iter()
                .zip(delta.iter())
                .map(|(a, d)| a + d)
                .collect();
            self.evaluations += 1;
            if residuals(&trial, &mut trial_r) {
                let trial_cost = sum_sq(&trial_r);
                if trial_cost < self.cost {
                    let tiny = (self.cost - trial_cost) <= 1e-15 * self.cost;
                    self.x = trial;
                    self.r.copy_from_slice(&trial_r);
                    self.cost = trial_cost;
                    self.lambda = (self.lambda * 0.2).max(1e-12);
                    improved = !tiny;
                    break;
                }
            }
            self.lambda *= 10.0;
        }
        self.done = !improved;
        self.evaluations - before
    }

    /// The step `delta` with its geodesic acceleration (Transtrum and Sethna 2012):
    /// the residuals' second derivative along the step, from one more evaluation,
    /// bends the step to follow a curved valley. Where a four-bar's targets barely
    /// determine it, the valley to the exact design is long and curved, and plain
    /// steps crawled along it (a hard case took 200 000 evaluations from 2e-5 to
    /// 1e-6 of its size). Kept only where the bend is small beside the step.
    fn accelerated(
        &mut self,
        jac: &DMatrix<f64>,
        chol: &nalgebra::Cholesky<f64, nalgebra::Dyn>,
        delta: DVector<f64>,
        residuals: &mut impl FnMut(&[f64], &mut [f64]) -> bool,
    ) -> DVector<f64> {
        let h = ACCELERATION_PROBE;
        let probe: Vec<f64> = self
            .x
            .iter()
            .zip(delta.iter())
            .map(|(a, d)| a + h * d)
            .collect();
        let mut r_h = vec![0.0; self.r.len()];
        self.evaluations += 1;
        if !residuals(&probe, &mut r_h) {
            return delta;
        }
        let jd = jac * &delta;
        let rvv = DVector::from_iterator(
            self.r.len(),
            (0..self.r.len()).map(|i| 2.0 / h * ((r_h[i] - self.r[i]) / h - jd[i])),
        );
        let bend = chol.solve(&(-(jac.transpose() * rvv))) * 0.5;
        if bend.norm() <= MAX_BEND * delta.norm() {
            delta + bend
        } else {
            delta
        }
    }

    /// Whether to stop before another iteration: converged, out of iterations, or
    /// stalled. A start in a curved valley gains a little every step for hundreds of
    /// steps (the valley's floor leads to the solution) and one at a local minimum
    /// nothing: only the second stops here.
    fn stops(&mut self) -> bool {
        if self.cost <= self.settings.cost_floor || self.iterations >= self.settings.iterations {
            return true;
        }
        self.history.push_back(self.cost);
        if self.history.len() > STALL_WINDOW {
            let then = self.history.pop_front().unwrap_or(self.cost);
            return self.cost > self.settings.stall * then;
        }
        false
    }
}

/// Minimises the sum of squares of `residuals(x, out)` from `x0`; `residuals`
/// returns false where they do not exist. `None` when they do not exist at `x0`.
#[cfg(test)]
pub fn minimise(
    x0: &[f64],
    m: usize,
    settings: Settings,
    mut residuals: impl FnMut(&[f64], &mut [f64]) -> bool,
) -> Option<Fitted> {
    let mut lm = Minimiser::new(x0, m, settings, &mut residuals)?;
    while !lm.is_done() {
        lm.iterate(&mut residuals);
    }
    Some(lm.fitted())
}

fn sum_sq(r: &[f64]) -> f64 {
    r.iter().map(|v| v * v).sum()
}

/// The Jacobian by central differences (one-sided where one side does not exist),
/// and the evaluations it took.
fn jacobian(
    x: &[f64],
    m: usize,
    step: f64,
    residuals: &mut impl FnMut(&[f64], &mut [f64]) -> bool,
) -> (DMatrix<f64>, u64) {
    let n = x.len();
    let mut jac = DMatrix::zeros(m, n);
    let (mut plus, mut minus) = (vec![0.0; m], vec![0.0; m]);
    let mut probe = x.to_vec();
    let mut base = None;
    let mut used = 0;
    for j in 0..n {
        let h = step * x[j].abs().max(1.0);
        probe[j] = x[j] + h;
        let has_plus = residuals(&probe, &mut plus);
        probe[j] = x[j] - h;
        let has_minus = residuals(&probe, &mut minus);
        probe[j] = x[j];
        used += 2;
        let column: Vec<f64> = match (has_plus, has_minus) {
            (true, true) => (0..m).map(|i| (plus[i] - minus[i]) / (2.0 * h)).collect(),
            (true, false) | (false, true) => {
                let centre = base.get_or_insert_with(|| {
                    let mut r0 = vec![0.0; m];
                    used += 1;
                    residuals(x, &mut r0);
                    r0
                });
                let (side, sign) = if has_plus {
                    (&plus, 1.0)
                } else {
                    (&minus, -1.0)
                };
                (0..m).map(|i| sign * (side[i] - centre[i]) / h).collect()
            }
            (false, false) => vec![0.0; m],
        };
        jac.set_column(j, &DVector::from_vec(column));
    }
    (jac, used)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn it_fits_rosenbrock_as_least_squares() {
        // r = (10 (y − x²), 1 − x): the minimum is (1, 1) with no residual.
        let settings = Settings {
            iterations: 200,
            cost_floor: 1e-30,
            step: 1e-7,
            stall: 1.0,
        };
        let fit = minimise(&[-1.2, 1.0], 2, settings, |x, r| {
            r[0] = 10.0 * (x[1] - x[0] * x[0]);
            r[1] = 1.0 - x[0];
            true
        })
        .expect("defined everywhere");
        assert!(
            (fit.x[0] - 1.0).abs() < 1e-9 && (fit.x[1] - 1.0).abs() < 1e-9,
            "{fit:?}"
        );
    }

    #[test]
    fn it_refuses_steps_where_the_residuals_do_not_exist() {
        // r = √x − 0.5 exists only for x ≥ 0; from x = 4 it must not step below 0.
        let settings = Settings {
            iterations: 100,
            cost_floor: 1e-30,
            step: 1e-7,
            stall: 1.0,
        };
        let fit = minimise(&[4.0], 1, settings, |x, r| {
            r[0] = x[0].sqrt() - 0.5;
            x[0] >= 0.0
        })
        .expect("exists at the start");
        assert!((fit.x[0] - 0.25).abs() < 1e-9, "{fit:?}");
    }
}
