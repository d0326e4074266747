//! Length edits checked cheaply. Whether a closed-form chain assembles at an input is
//! read off the closure margin of its groups (no solve, no error wording), and the
//! limit of a refused length is the root of that margin, found by regula falsi
//! (Illinois): about ten evaluations instead of forty full rebuilds by bisection.

use std::fmt;

use linkage::dyad::{DyadLabel, Shortfall};
use linkage::scene::LengthUnit;
use linkage::{Kinematics, LinkageError, Mechanism, SceneFile};

use super::Built;
use super::cam_curves::CamCurves;
use super::params::LengthParam;

/// Most margin evaluations (or bisections, for chains solved by Newton only) per limit:
/// bisection alone needs 47 over a 100-fold range to 1e-12.
const MAX_EVALUATIONS: usize = 100;

/// Relative width at which the limit counts as found: far below what a slider sets.
const LIMIT_RTOL: f64 = 1e-12;

/// Why a scene does not build at an input.
#[derive(Clone, Debug, PartialEq)]
pub enum NotAssembled {
    /// The scene is not a valid mechanism, or the solver failed.
    Solver(LinkageError),
    /// A closed-form group does not close.
    Open {
        /// The group as its user knows it (its links and inner point).
        dyad: Box<DyadLabel>,
        /// Its closure margin (negative: how far from closing).
        margin: f64,
        /// What falls short (pins too far apart, a guide out of reach).
        shortfall: Option<Box<Shortfall>>,
    },
}

impl fmt::Display for NotAssembled {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.words(LengthUnit::Metre, linkage_diagram::words::Lang::English))
    }
}

/// Builds `scene` at `input` with what an edit shows at once, or says why not: for a
/// closed-form chain that does not close, which group, without solving. The cam
/// curves before the edit, `earlier_cams`, are kept where a cam joint is unchanged.
///
/// # Errors
/// Why the scene does not build or assemble at `input`.
pub(crate) fn try_assemble(
    scene: &SceneFile,
    input: f64,
    earlier_cams: &[CamCurves],
) -> Result<Built, NotAssembled> {
    let mech = Mechanism::from_scene(scene).map_err(NotAssembled::Solver)?;
    let mut kin = Kinematics::new(mech).map_err(NotAssembled::Solver)?;
    if let Some(c) = kin.closure(input)
        && !c.assembles
        && let Some(dyad) = kin.dyad(c.group)
    {
        return Err(NotAssembled::Open {
            dyad: Box::new(dyad),
            margin: c.margin,
            shortfall: kin.shortfall(input, c.group).map(Box::new),
        });
    }
    Built::at(kin, input, earlier_cams).map_err(NotAssembled::Solver)
}

/// The value of `param` nearest `bad`, between `good` (where `scene` assembles at
/// `input`) and `bad`, at which the chain still assembles at `input`.
pub fn length_limit(
    scene: &SceneFile,
    param: &LengthParam,
    good: f64,
    bad: f64,
    input: f64,
) -> Option<f64> {
    let kin_with = |len: f64| -> Option<Kinematics> {
        let mut s = scene.clone();
        param.apply(&mut s, len).ok()?;
        Mechanism::from_scene(&s).and_then(Kinematics::new).ok()
    };
    let solves = |len: f64| kin_with(len).is_some_and(|mut k| k.solve(input).is_ok());
    if kin_with(good)?.closure(input).is_none() {
        // Newton only: no margin to follow, bisect on whether it solves.
        return Some(bisect(good, bad, solves));
    }
    // > 0 where the chain closes. A group that only touches tangency (a toggle the
    // length passes through, its margin ~0 on both sides) is not a limit: there the
    // chain still closes, so its margin counts as positive.
    let margin = |len: f64| -> Option<f64> {
        let c = kin_with(len)?.closure(input)?;
        Some(if c.assembles {
            c.margin.max(f64::MIN_POSITIVE)
        } else {
            c.margin
        })
    };
    // Brent–Dekker on the margin where it has a value at both ends (a length whose
    // scene always builds): about ten builds where regula falsi took twenty-three on
    // the cam feed, each a whole scene built. Else the safeguarded regula falsi.
    // Inside the tangency band (closing, margin <= 0) the limit is reached: there the
    // margin counts as its root, 0, or Brent–Dekker, given a tiny positive value with
    // no slope in it, crept up on the root by bisection (measured: 40 to 87 builds).
    // The root is the tangency itself, where the solve is singular: a billionth of
    // the bracket back towards the valid end it solves at once.
    let at_root = |len: f64| margin(len).map(|m| if m == f64::MIN_POSITIVE { 0.0 } else { m });
    let brent = match (margin(good), margin(bad)) {
        (Some(g), Some(b)) if g > 0.0 && b < 0.0 => {
            linkage::roots_util::refine(good, bad, |x| at_root(x).unwrap_or(f64::NAN))
                // A toggle the length passes through closes beyond it too: not a limit.
                .filter(|&root| margin(root + (bad - root) * 1e-9).is_none_or(|m| m < 0.0))
                .map(|root| root + (good - root) * 1e-9)
        }
        _ => None,
    };
    let found = brent.unwrap_or_else(|| illinois(good, bad, margin));
    // Next to a tangency the solver may still call the pose singular: step back
    // towards the valid value until it solves.
    (0..=12)
        .map(|k| found + (good - found) * if k == 0 { 0.0 } else { 10f64.powi(k - 13) })
        .find(|&len| solves(len))
}

/// The last `x` from `good` towards `bad` with `ok(x)`, by bisection.
fn bisect(mut good: f64, mut bad: f64, ok: impl Fn(f64) -> bool) -> f64 {
    for _ in 0..MAX_EVALUATIONS {
        if converged(good, bad) {
            break;
        }
        let mid = 0.5 * (good + bad);
        if ok(mid) {
            good = mid;
        } else {
            bad = mid;
        }
    }
    good
}

/// The last `x` from `good` towards `bad` with `f(x) > 0`, by the Illinois variant of
/// regula falsi, safeguarded: where two steps did not halve the bracket (a margin of
/// very different size at its two ends) and where `f` has no value (the scene does
/// not build), the next step bisects.
fn illinois(mut good: f64, mut bad: f64, f: impl Fn(f64) -> Option<f64>) -> f64 {
    let (mut f_good, mut f_bad) = (f(good), f(bad));
    // Which end moved last: the Illinois rule halves the other end's value when the
    // same end moves twice, so that the bracket shrinks from both sides.
    let mut last_good = None;
    let mut widths = [f64::INFINITY; 2];
    for _ in 0..MAX_EVALUATIONS {
        if converged(good, bad) {
            break;
        }
        let width = (bad - good).abs();
        let slow = width > 0.5 * widths[0];
        widths = [widths[1], width];
        let x = match (f_good, f_bad) {
            (Some(fg), Some(fb)) if fg > 0.0 && fb < 0.0 && !slow => {
                let x = bad - fb * (bad - good) / (fb - fg);
                if x.is_finite() && between(x, good, bad) {
                    x
                } else {
                    0.5 * (good + bad)
                }
            }
            _ => 0.5 * (good + bad),
        };
        match f(x) {
            Some(fx) if fx > 0.0 => {
                good = x;
                f_good = Some(fx);
                if last_good == Some(true) {
                    f_bad = f_bad.map(|v| 0.5 * v);
                }
                last_good = Some(true);
            }
            fx => {
                bad = x;
                f_bad = fx;
                if last_good == Some(false) {
                    f_good = f_good.map(|v| 0.5 * v);
                }
                last_good = Some(false);
            }
        }
    }
    good
}

fn converged(a: f64, b: f64) -> bool {
    (a - b).abs() <= LIMIT_RTOL * a.abs().max(b.abs()).max(f64::MIN_POSITIVE)
}

fn between(x: f64, a: f64, b: f64) -> bool {
    x > a.min(b) && x < a.max(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn illinois_finds_the_last_good_point_of_a_smooth_margin() {
        // Margin 1 - (x/3)^2: assembles up to x = 3.
        let evaluations = std::cell::Cell::new(0);
        let f = |x: f64| {
            evaluations.set(evaluations.get() + 1);
            Some(1.0 - (x / 3.0).powi(2))
        };
        let x = illinois(1.0, 100.0, f);
        assert!((x - 3.0).abs() < 1e-10, "{x}");
        assert!(x <= 3.0, "the answer assembles");
        assert!(evaluations.get() < 40, "{} evaluations", evaluations.get());
    }

    #[test]
    fn a_margin_of_very_different_size_at_the_two_ends_still_converges() {
        // Barely positive at the start, hugely negative at the far end (a chain
        // opened at a toggle, a length pulled 100-fold): plain Illinois stalls.
        let f = |x: f64| {
            Some(
                1e-11 * (2500.0 - x)
                    - 1e-6 * (x - 454.0).max(0.0).powi(2) * (x > 2500.0) as u8 as f64,
            )
        };
        let x = illinois(454.0, 45_400.0, f);
        assert!((x - 2500.0).abs() < 1e-8, "{x}");
    }

    #[test]
    fn where_the_scene_does_not_build_it_bisects() {
        // No value beyond 5 (a length the scene refuses), assembles up to 4.
        let f = |x: f64| (x < 5.0).then_some(4.0 - x);
        let x = illinois(0.5, 50.0, f);
        assert!((x - 4.0).abs() < 1e-9, "{x}");
    }

    #[test]
    fn bisection_finds_the_last_good_point() {
        let x = bisect(1.0, 2.0, |x| x <= 1.25);
        assert!((x - 1.25).abs() < 1e-11, "{x}");
    }
}
