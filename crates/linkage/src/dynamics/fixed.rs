//! Fixed-step methods: semi-implicit Euler, classical RK4 and the flipper paper's
//! energy-increment method. Each ends with an evaluation at its end point, so the
//! next step starts from a known derivative.

use super::rhs::{Point, Rhs, State};
use crate::error::Result;

/// One semi-implicit (symplectic) Euler step: v first, then x with the new v.
pub(crate) fn euler(rhs: &mut Rhs, a: &Point, h: f64) -> Result<Point> {
    let v = a.y[1] + h * a.f[1];
    let y = [a.y[0] + h * v, v, a.y[2] + h * a.f[2]];
    rhs.point(a.t + h, y)
}

/// One classical RK4 step: three new stages and the end point.
pub(crate) fn rk4(rhs: &mut Rhs, a: &Point, h: f64) -> Result<Point> {
    let at = |k: &State, c: f64| -> State { std::array::from_fn(|i| a.y[i] + c * h * k[i]) };
    let k1 = a.f;
    let k2 = rhs.eval(&at(&k1, 0.5))?.0;
    let k3 = rhs.eval(&at(&k2, 0.5))?.0;
    let k4 = rhs.eval(&at(&k3, 1.0))?.0;
    let y = std::array::from_fn(|i| a.y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
    rhs.point(a.t + h, y)
}

/// One energy increment of `dx` in the direction of motion (from rest: the direction
/// the moment pushes): ½J₁v₁² = ½J₀v₀² + M₀Δx, Δt = 2Δx/(v₀ + v₁). Where the kinetic
/// energy would go negative the motion turns: the step ends at the turning point
/// ½J₀v₀² + M₀(x − x₀) = 0 with v = 0, and the next one goes back. `None` at rest in
/// equilibrium (no moment). One evaluation.
pub(crate) fn energy_increment(rhs: &mut Rhs, a: &Point, dx: f64) -> Result<Option<Point>> {
    let v0 = a.y[1];
    let direction = if v0 != 0.0 {
        v0.signum()
    } else {
        a.reduced.moment().signum()
    };
    if direction == 0.0 {
        return Ok(None);
    }
    let mut dq = direction * dx;
    // J at x does not depend on v; only the damping moment does, so one solve at x
    // serves the energy update and the end point.
    rhs.evaluations += 1;
    rhs.solve_position(a.y[0] + dq)?;
    let j1 = rhs.reduce_here(&[a.y[0] + dq, v0, 0.0])?.j;
    let kinetic0 = a.reduced.j * v0 * v0;
    let mut v2 = (kinetic0 + 2.0 * a.reduced.moment() * dq) / j1;
    if v2 < 0.0 {
        // The turning point lies inside this increment (the moment opposes v₀ there).
        dq = -kinetic0 / (2.0 * a.reduced.moment());
        v2 = 0.0;
        rhs.solve_position(a.y[0] + dq)?;
    }
    let x = a.y[0] + dq;
    let v = direction * v2.sqrt();
    let t = a.t + 2.0 * dq / (v0 + v);
    let mut y = [x, v, a.y[2]];
    let reduced = rhs.reduce_here(&y)?;
    // Non-conservative work by the trapezoid rule in x, the method's own order.
    y[2] += 0.5 * (a.reduced.m_nonconservative() + reduced.m_nonconservative()) * dq;
    let f = super::rhs::derivative(&y, &reduced);
    Ok(Some(Point { t, y, f, reduced }))
}
