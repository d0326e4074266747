//! Extremes located, not sampled: the largest value of a curve that can be
//! evaluated anywhere (a torque, a force, an acceleration at any crank angle) is
//! bracketed on its samples and found by a golden-section search between the
//! neighbours of the best ones, to the rounding of the curve's value. On a one-degree
//! grid the die cutter's peak crank torque read 51 719.8 N·m; located, it is
//! 51 721.5 N·m at 42.58°.
//!
//! Golden-section rather than a root of the derivative: the curves here have no
//! derivative at hand (a torque from a Newton–Euler solve), and a maximum of |f| may
//! sit on a kink. A leaf module: it knows only closures.

use serde::Serialize;

/// A value and where it is.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Extreme {
    /// Where (a crank or cam angle, rad).
    pub angle_rad: f64,
    /// The value there.
    pub value: f64,
}

/// The golden ratio's conjugate, (√5 − 1)/2.
const GOLDEN: f64 = 0.618_033_988_749_894_8;

/// The largest `f` on `[a, b]` for an `f` with one maximum there, by golden-section
/// search until the bracket is √ε of the angle wide: at a smooth maximum `f` moves
/// by the square of the step, so its value is then found to its rounding (the angle
/// to about 1e-8 rad). The better end if `f` is largest there; `None` where `f` has no
/// value.
pub fn golden_max(mut f: impl FnMut(f64) -> Option<f64>, a: f64, b: f64) -> Option<Extreme> {
    let (mut lo, mut hi) = (a.min(b), a.max(b));
    let (mut x1, mut x2) = (hi - GOLDEN * (hi - lo), lo + GOLDEN * (hi - lo));
    let (mut f1, mut f2) = (f(x1)?, f(x2)?);
    for _ in 0..200 {
        if hi - lo <= 2.0 * f64::EPSILON.sqrt() * (1.0 + lo.abs().max(hi.abs())) {
            break;
        }
        if f1 < f2 {
            lo = x1;
            (x1, f1) = (x2, f2);
            x2 = lo + GOLDEN * (hi - lo);
            f2 = f(x2)?;
        } else {
            hi = x2;
            (x2, f2) = (x1, f1);
            x1 = hi - GOLDEN * (hi - lo);
            f1 = f(x1)?;
        }
    }
    let inner = if f1 >= f2 {
        Extreme {
            angle_rad: x1,
            value: f1,
        }
    } else {
        Extreme {
            angle_rad: x2,
            value: f2,
        }
    };
    // A maximum at an end of the bracket: the search creeps to it; the end itself
    // may be larger still.
    [a, b]
        .into_iter()
        .filter_map(|x| {
            f(x).map(|value| Extreme {
                angle_rad: x,
                value,
            })
        })
        .chain([inner])
        .max_by(|p, q| p.value.total_cmp(&q.value))
}

/// How many of the samples' local maxima are searched: a curve with two near-equal
/// humps may have its true peak in the lower-sampled one.
const CANDIDATES: usize = 3;

/// The largest value of `f`, sampled as `samples` (angle, value) in ascending
/// angle: the samples' best local maxima each refined by a golden-section search
/// between their neighbours. With a `period` (a turn) the curve repeats: the last
/// sample's neighbour is the first, a period on. Never less than the best sample;
/// `None` without samples.
pub fn locate_max(
    samples: &[[f64; 2]],
    period: Option<f64>,
    mut f: impl FnMut(f64) -> Option<f64>,
) -> Option<Extreme> {
    let n = samples.len();
    let best_sample = samples
        .iter()
        .filter(|s| s[1].is_finite())
        .max_by(|p, q| p[1].total_cmp(&q[1]))
        .map(|&[angle_rad, value]| Extreme { angle_rad, value })?;
    if n < 3 {
        return Some(best_sample);
    }
    let periodic = period.is_some();
    let neighbour = |i: usize, step: isize| -> Option<f64> {
        let j = i as isize + step;
        if (0..n as isize).contains(&j) {
            return Some(samples[j as usize][0]);
        }
        period.map(|p| {
            let wrapped = j.rem_euclid(n as isize) as usize;
            samples[wrapped][0] + p * step.signum() as f64
        })
    };
    let value = |i: usize, step: isize| -> f64 {
        let j = (i as isize + step).rem_euclid(n as isize) as usize;
        let inside = (0..n as isize).contains(&(i as isize + step));
        if inside || periodic {
            samples[j][1]
        } else {
            f64::NEG_INFINITY
        }
    };
    let mut humps: Vec<usize> = (0..n)
        .filter(|&i| samples[i][1] >= value(i, -1) && samples[i][1] >= value(i, 1))
        .collect();
    humps.sort_by(|&p, &q| samples[q][1].total_cmp(&samples[p][1]));
    humps.truncate(CANDIDATES);
    let mut best = best_sample;
    for i in humps {
        let a = neighbour(i, -1).unwrap_or(samples[i][0]);
        let b = neighbour(i, 1).unwrap_or(samples[i][0]);
        if let Some(e) = golden_max(&mut f, a, b)
            && e.value > best.value
        {
            best = e;
        }
    }
    Some(best)
}

/// The smallest value of `f`: [`locate_max`] of its negative.
pub fn locate_min(
    samples: &[[f64; 2]],
    period: Option<f64>,
    mut f: impl FnMut(f64) -> Option<f64>,
) -> Option<Extreme> {
    let negated: Vec<[f64; 2]> = samples.iter().map(|&[x, y]| [x, -y]).collect();
    let e = locate_max(&negated, period, |x| f(x).map(|v| -v))?;
    Some(Extreme {
        angle_rad: e.angle_rad,
        value: -e.value,
    })
}

/// `n` samples of `f` over `[a, b)` (a turn from `a` when `b − a` is one), skipping
/// the angles where `f` has no value.
pub fn sample(n: usize, a: f64, b: f64, mut f: impl FnMut(f64) -> Option<f64>) -> Vec<[f64; 2]> {
    (0..n)
        .filter_map(|i| {
            let x = a + (b - a) * i as f64 / n as f64;
            f(x).map(|v| [x, v])
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// f = sin x + 0.3 sin 2x: its maximum is where cos x + 0.6 cos 2x = 0, a
    /// quadratic in cos x (1.2c² + c − 0.6 = 0), located to the rounding of f.
    #[test]
    fn a_maximum_is_located_where_its_derivative_vanishes() {
        let f = |x: f64| Some(x.sin() + 0.3 * (2.0 * x).sin());
        let c = (-1.0 + (1.0 + 4.0 * 1.2 * 0.6_f64).sqrt()) / (2.0 * 1.2);
        let x_true = c.acos();
        let exact = x_true.sin() + 0.3 * (2.0 * x_true).sin();
        let coarse = sample(36, 0.0, std::f64::consts::TAU, f);
        let e = locate_max(&coarse, Some(std::f64::consts::TAU), f).expect("a maximum");
        assert!(
            (e.value - exact).abs() <= 4.0 * f64::EPSILON,
            "{e:?} vs {exact}"
        );
        assert!(
            (e.angle_rad - x_true).abs() < 1e-7,
            "{} vs {x_true}",
            e.angle_rad
        );
        let best_sample = coarse
            .iter()
            .map(|s| s[1])
            .fold(f64::NEG_INFINITY, f64::max);
        assert!(
            e.value > best_sample + 1e-4,
            "the grid missed it by more than that"
        );
    }

    /// A peak straddling the turn's end (between the last sample and the first) is
    /// found across it; a minimum likewise.
    #[test]
    fn a_peak_across_the_end_of_the_turn_is_found() {
        let f = |x: f64| Some((x - 0.01).cos());
        let samples = sample(12, 0.3, 0.3 + std::f64::consts::TAU, f);
        let e = locate_max(&samples, Some(std::f64::consts::TAU), f).expect("a maximum");
        assert!((e.value - 1.0).abs() <= 2.0 * f64::EPSILON, "{e:?}");
        let e = locate_min(&samples, Some(std::f64::consts::TAU), f).expect("a minimum");
        assert!((e.value + 1.0).abs() <= 2.0 * f64::EPSILON, "{e:?}");
    }

    /// Two humps, the higher one sampled lower: both are searched.
    #[test]
    fn of_two_near_equal_humps_the_higher_one_wins() {
        let f = |x: f64| {
            Some((-(x - 1.05).powi(2) * 50.0).exp() + 0.999 * (-(x - 3.0).powi(2) * 50.0).exp())
        };
        let samples = sample(20, 0.0, 4.0, f);
        let e = locate_max(&samples, None, f).expect("a maximum");
        assert!(
            (e.angle_rad - 1.05).abs() < 1e-6 && (e.value - 1.0).abs() < 1e-12,
            "{e:?}"
        );
    }

    /// A maximum at the end of an open range stays there.
    #[test]
    fn a_maximum_at_the_end_of_an_open_range_is_the_end() {
        let f = |x: f64| Some(x);
        let e = locate_max(&sample(10, 0.0, 1.0, f), None, f).expect("a maximum");
        assert!((e.value - 0.9).abs() < 1e-15, "{e:?}");
    }
}
