//! Gauss–Legendre quadrature on an interval. The nodes are found by Newton's method
//! on the Legendre polynomial (a few lines, exact to round-off); a crate for one
//! table of four or eight numbers would add a dependency for less code than this.

/// Nodes and weights of the `n`-point rule on [-1, 1].
pub(crate) fn rule(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            // Tricomi's estimate of the i-th root, then Newton on P_n.
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut slope = 1.0;
            for _ in 0..100 {
                let (p, dp) = legendre(n, x);
                slope = dp;
                let dx = p / dp;
                x -= dx;
                if dx.abs() <= 1e-16 {
                    break;
                }
            }
            (x, 2.0 / ((1.0 - x * x) * slope * slope))
        })
        .collect()
}

/// P_n(x) and its derivative, by the three-term recurrence.
fn legendre(n: usize, x: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, x);
    for k in 2..=n {
        let k = k as f64;
        (p0, p1) = (p1, ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k);
    }
    let dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
    (p1, dp)
}

/// The points of `rule` mapped onto [a, b], with weights scaled to it.
pub(crate) fn on(rule: &[(f64, f64)], a: f64, b: f64) -> impl Iterator<Item = (f64, f64)> + '_ {
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    rule.iter().map(move |&(x, w)| (mid + half * x, half * w))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rule_integrates_polynomials_of_degree_2n_minus_1_exactly() {
        for n in [2, 4, 8] {
            let r = rule(n);
            for degree in 0..2 * n {
                let got: f64 = on(&r, 0.0, 2.0)
                    .map(|(x, w)| w * x.powi(degree as i32))
                    .sum();
                let exact = 2f64.powi(degree as i32 + 1) / (degree as f64 + 1.0);
                assert!(
                    (got - exact).abs() <= 1e-14 * exact,
                    "n {n} degree {degree}: {got} vs {exact}"
                );
            }
        }
    }
}
