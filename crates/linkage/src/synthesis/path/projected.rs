//! The refinement of untimed targets with their crank angles eliminated (variable
//! projection, Golub and Pereyra): for given linkage numbers each target's angle is
//! its foot point on the coupler curve, found afresh from the same starting angles,
//! and only the nine numbers are left to least squares. Refined jointly, the angles
//! and the numbers crawl along a curved valley (measured: thousands of
//! Levenberg–Marquardt iterations from a start inside the true solution's basin);
//! projected, the same starts converge in a few dozen.

use super::geometry::{CouplerFourBar, PARAMS};
use super::problem::Problem;
use crate::motion::Vec2;

/// Newton steps of a foot point.
const FOOT_STEPS: usize = 12;

/// The foot point on `m`'s curve of `target` from crank angle `theta`: the angle
/// where the miss is across the curve, by Gauss–Newton along the tangent. `None`
/// where the curve does not close on the way.
fn foot(m: &CouplerFourBar, target: Vec2, mut theta: f64) -> Option<f64> {
    for _ in 0..FOOT_STEPS {
        let (p, tangent) = m.point_and_tangent_at(theta)?;
        let reach = tangent.norm_squared();
        if reach.is_nan() || reach <= 0.0 {
            return Some(theta);
        }
        let step = (-(p - target).dot(&tangent) / reach).clamp(-0.2, 0.2);
        theta += step;
        if step.abs() <= 1e-15 * (1.0 + theta.abs()) {
            break;
        }
    }
    m.point_at(theta).map(|_| theta)
}

impl Problem {
    /// Residuals of the linkage numbers `params` on branch `left` with each target's
    /// crank angle its foot point from `start` (written into `angles`): each target's
    /// miss, then the turning shortfall, the pivots outside the region and the
    /// transmission deficit, as [`Problem::residuals`] orders them (its closing gaps
    /// are zero here). False where a length is not positive or a foot point is not
    /// on the closing curve.
    pub fn projected_residuals(
        &self,
        params: &[f64],
        left: bool,
        start: &[f64],
        angles: &mut [f64],
        out: &mut [f64],
    ) -> bool {
        let m = CouplerFourBar::from_params(&params[..PARAMS], left);
        for (i, target) in self.targets.iter().enumerate() {
            let Some(theta) = foot(&m, *target, start[i]) else {
                return false;
            };
            let Some(p) = m.point_at(theta) else {
                return false;
            };
            angles[i] = theta;
            out[3 * i] = p.x - target.x;
            out[3 * i + 1] = p.y - target.y;
            out[3 * i + 2] = 0.0;
        }
        self.constraint_residuals(&m, angles, out);
        true
    }
}
