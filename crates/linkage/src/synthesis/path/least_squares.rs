//! Levenberg–Marquardt for the small problems of path refinement (about 10 to 30
//! unknowns). Written here rather than taken from `levenberg-marquardt` or `argmin`:
//! both are built on nalgebra 0.34 or older while the solver uses 0.35, so either
//! would compile and ship a second nalgebra (into the WASM build too); and this
//! problem needs one thing they do not offer, residuals that may not exist (a trial
//! step where the loop does not close is refused like a step that raises the cost).

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
}

/// Minimises the sum of squares of `residuals(x, out)` from `x0`; `residuals`
/// returns false where they do not exist. `None` when they do not exist at `x0`.
pub fn minimise(
    x0: &[f64],
    m: usize,
    settings: Settings,
    mut residuals: impl FnMut(&[f64], &mut [f64]) -> bool,
) -> Option<Fitted> {
    let n = x0.len();
    let mut x = x0.to_vec();
    let mut r = vec![0.0; m];
    let mut evaluations = 1;
    if !residuals(&x, &mut r) {
        return None;
    }
    let mut cost = sum_sq(&r);
    let mut lambda = 1e-3;
    let mut trial_r = vec![0.0; m];
    for _ in 0..settings.iterations {
        if cost <= settings.cost_floor {
            break;
        }
        let (jac, used) = jacobian(&x, m, settings.step, &mut residuals);
        evaluations += used;
        let jt = jac.transpose();
        let jtj = &jt * &jac;
        let grad = &jt * DVector::from_column_slice(&r);
        let mut improved = false;
        // Raise the damping until a step lowers the cost (or it is hopeless).
        while lambda < 1e12 {
            let mut damped = jtj.clone();
            for i in 0..n {
                damped[(i, i)] += lambda * jtj[(i, i)].max(1e-12);
            }
            let Some(chol) = damped.cholesky() else {
                lambda *= 10.0;
                continue;
            };
            let delta = chol.solve(&(-&grad));
            let trial: Vec<f64> = x.iter().zip(delta.iter()).map(|(a, d)| a + d).collect();
            evaluations += 1;
            if residuals(&trial, &mut trial_r) {
                let trial_cost = sum_sq(&trial_r);
                if trial_cost < cost {
                    let tiny = (cost - trial_cost) <= 1e-15 * cost;
                    x = trial;
                    r.copy_from_slice(&trial_r);
                    cost = trial_cost;
                    lambda = (lambda * 0.2).max(1e-12);
                    improved = !tiny;
                    break;
                }
            }
            lambda *= 10.0;
        }
        if !improved {
            break;
        }
    }
    Some(Fitted {
        x,
        cost,
        evaluations,
    })
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
        };
        let fit = minimise(&[4.0], 1, settings, |x, r| {
            r[0] = x[0].sqrt() - 0.5;
            x[0] >= 0.0
        })
        .expect("exists at the start");
        assert!((fit.x[0] - 0.25).abs() < 1e-9, "{fit:?}");
    }
}
