//! The `four-bar` crate (four-bar-rs 7.0.5) on the same targets: its path synthesis
//! (`syn::FbSyn`: the targets' elliptic Fourier descriptors against each candidate's
//! coupler curve, so that placement, turn and scale come out of the descriptors) with
//! its differential evolution (`mh::De` with its defaults), as its authors use it.
//! The mode follows the targets as a user of it would choose: a whole turn is a
//! closed curve (`Closed`), an arc of a turning crank part of one (`Partial`), a
//! rocking crank's arc an open curve (`Open`). It fits shapes, not timing, so timed
//! cases are given to it as their points alone.
//!
//! Its error at each time budget is that of the best four-bar it held then, measured
//! as ours is and outside its clock: the largest distance from a target to that
//! four-bar's coupler curve (3,600 points), over the targets' size.

use std::time::Instant;

use four_bar::mh::pareto::Best as _;
use four_bar::{FourBar, mh, syn};

use crate::cases::{Case, size};

/// Points of the coupler curve a candidate is measured on.
const FINE: usize = 3600;

/// The largest distance from a target to `fb`'s coupler curve, over the targets' size.
fn error(fb: &FourBar, targets: &[[f64; 2]]) -> f64 {
    let curve = fb.curve(FINE);
    if curve.len() < 2 {
        return f64::INFINITY;
    }
    let s = size(targets);
    targets
        .iter()
        .map(|t| {
            curve
                .windows(2)
                .map(|w| to_segment(*t, w[0], w[1]))
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max)
        / s
}

fn to_segment(q: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (sx, sy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = sx * sx + sy * sy;
    let t = if len2 > 0.0 {
        (((q[0] - a[0]) * sx + (q[1] - a[1]) * sy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a[0] + t * sx - q[0]).hypot(a[1] + t * sy - q[1])
}

/// Four-bar's best error at each of `budgets` (s), running for `seconds` at most.
pub fn run<const B: usize>(case: &Case, seconds: f64, budgets: &[f64; B]) -> [f64; B] {
    let targets = &case.targets.points_m;
    let mode = if case.whole_turn {
        syn::Mode::Closed
    } else if case.truth.crank_turns() {
        syn::Mode::Partial
    } else {
        syn::Mode::Open
    };
    let func = syn::FbSyn::from_curve(targets.clone(), mode);
    let started = Instant::now();
    // (time, best four-bar then) after each generation; measured afterwards.
    let mut held: Vec<(f64, FourBar)> = Vec::new();
    let _ = mh::Solver::build(mh::De::default(), func)
        .seed(1)
        .task(|_| started.elapsed().as_secs_f64() >= seconds)
        .callback(|ctx| {
            let t = started.elapsed().as_secs_f64();
            let fb = ctx.best.as_result_fit().as_result().clone();
            held.push((t, fb));
        })
        .solve();
    let errors: Vec<(f64, f64)> = held
        .iter()
        .map(|(t, fb)| (*t, error(fb, targets)))
        .collect();
    budgets.map(|budget| {
        errors
            .iter()
            .filter(|(t, _)| *t <= budget)
            .map(|(_, e)| *e)
            .fold(f64::INFINITY, f64::min)
    })
}
