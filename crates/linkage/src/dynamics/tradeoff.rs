//! The work–precision trade: for each method and tolerance (or step), the CPU time,
//! the right-hand-side evaluations and the error against a reference run at the
//! tightest tolerance.

use web_time::Instant;

use serde::Serialize;

use super::output::Simulation;
use super::run::simulate;
use super::settings::{Method, Settings};
use crate::error::Result;
use crate::solve::Kinematics;

/// One point of the work–precision diagram.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TradeoffRow {
    /// Method.
    pub method: Method,
    /// rtol for the adaptive methods (atol = rtol · `atol_ratio`), else the step.
    pub setting: f64,
    /// CPU seconds of one run without output (best of several).
    pub cpu_seconds: f64,
    /// Right-hand-side evaluations of that run.
    pub rhs_evaluations: usize,
    /// Accepted steps.
    pub steps: usize,
    /// Largest |q − q_ref| on the output grid and at the events, rad.
    pub max_q_error: f64,
    /// |t − t_ref| of the last event (the end stop), s; 0 without events.
    pub event_time_error: f64,
}

/// Largest difference of the input coordinate between two runs sampled on the same
/// output grid (over the grid times both reached), and at their final stop (there at
/// the reference's time, by the run's own rate: a stop is at the same angle in both,
/// the error is in its time); `f64::INFINITY` when only one of them stopped.
pub fn max_q_difference(run: &Simulation, reference: &Simulation) -> f64 {
    let on_grid = run
        .samples
        .iter()
        .zip(&reference.samples)
        .filter(|(a, b)| (a.t - b.t).abs() <= 1e-9 * (1.0 + b.t.abs()))
        .map(|(a, b)| (a.q - b.q).abs())
        .fold(0.0, f64::max);
    let stop = |s: &Simulation| s.events.last().filter(|e| e.stopped).map(|e| e.state);
    match (stop(run), stop(reference)) {
        (Some(a), Some(b)) => on_grid.max((a.q + a.q_dot * (b.t - a.t) - b.q).abs()),
        (None, None) => on_grid,
        _ => f64::INFINITY,
    }
}

/// Runs `settings` once on the output grid `grid_dt` (for the error) and repeatedly
/// without output (for the cost), and compares with `reference` (run on the same grid).
pub fn measure(
    k: &Kinematics,
    settings: &Settings,
    grid_dt: f64,
    reference: &Simulation,
) -> Result<TradeoffRow> {
    let mut on_grid = settings.clone();
    on_grid.output_dt = Some(grid_dt);
    let run = simulate(k, &on_grid)?;
    let mut bare = settings.clone();
    bare.output_dt = None;
    // Best of several runs, at least 20 ms in all, so that the clock's resolution and
    // one-off cache misses do not dominate.
    let timed = || -> Result<(Simulation, f64)> {
        let clock = Instant::now();
        let r = simulate(k, &bare)?;
        Ok((r, clock.elapsed().as_secs_f64()))
    };
    let (bare_run, mut best) = timed()?;
    let (mut total, mut repeats) = (best, 1);
    while repeats < 3 || (total < 0.02 && repeats < 10_000) {
        let (_, dt) = timed()?;
        best = best.min(dt);
        total += dt;
        repeats += 1;
    }
    let event_time_error = match (run.events.last(), reference.events.last()) {
        (Some(a), Some(b)) => (a.state.t - b.state.t).abs(),
        _ => 0.0,
    };
    Ok(TradeoffRow {
        method: settings.method,
        setting: if settings.method.is_adaptive() {
            settings.rtol
        } else {
            settings.step
        },
        cpu_seconds: best,
        rhs_evaluations: bare_run.stats.rhs_evaluations,
        steps: bare_run.stats.steps,
        max_q_error: max_q_difference(&run, reference),
        event_time_error,
    })
}

/// The reference: DOP853 at rtol 1e-13 on the output grid `grid_dt`.
pub fn reference_run(k: &Kinematics, base: &Settings, grid_dt: f64) -> Result<Simulation> {
    let mut s = base.clone();
    s.method = Method::Dop853;
    s.rtol = 1e-13;
    s.atol = 1e-15;
    s.step = 0.0;
    s.output_dt = Some(grid_dt);
    simulate(k, &s)
}

/// The settings a work–precision table sweeps: per method, tolerances (adaptive; atol
/// = rtol/100) or steps (fixed: Δt in s, Δφ in rad for the energy method).
pub fn default_plan() -> Vec<(Method, Vec<f64>)> {
    vec![
        (Method::EnergyIncrement, vec![1e-2, 3e-3, 1e-3, 3e-4, 1e-4]),
        (
            Method::SemiImplicitEuler,
            vec![1e-3, 3e-4, 1e-4, 3e-5, 1e-5],
        ),
        (Method::ImplicitMidpoint, vec![3e-3, 1e-3, 3e-4, 1e-4, 3e-5]),
        (Method::Rk4, vec![1e-2, 3e-3, 1e-3, 3e-4, 1e-4]),
        (Method::Dp5, vec![1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10]),
        (
            Method::Dop853,
            vec![1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11],
        ),
    ]
}

/// Settings for one entry of a plan, on top of `base` (t_end, stops, start speed).
pub fn plan_settings(base: &Settings, method: Method, setting: f64) -> Settings {
    let mut s = base.clone();
    s.method = method;
    if method.is_adaptive() {
        s.rtol = setting;
        s.atol = setting * 1e-2;
        s.step = 0.0;
    } else {
        s.step = setting;
    }
    s
}
