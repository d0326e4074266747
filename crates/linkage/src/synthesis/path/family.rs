//! A four-bar and its two cognates are one family: the three share their three
//! fixed pivots (A, D and Roberts' third pivot O = A + w (D − A), w the coupler
//! triangle's shape), and on each pivot turn two links, one of each of two members:
//! on A the crank a and |w| b, on D the rocker c and |1 − w| b, on O |1 − w| a and
//! |w| c. Those three pivots with their pairs of lengths name the family whichever
//! member the search found.

use super::geometry::CouplerFourBar;
use super::shape::complex;
use crate::motion::Vec2;

/// How close (in the targets' normalised units) two families' pivots and lengths must
/// be to be the same: far below any two distinct designs' difference, far above the
/// refinement's round-off.
const SAME: f64 = 1e-5;

/// A fixed pivot of a family and the lengths of the two links that turn on it
/// (shorter first).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Pivot {
    at: Vec2,
    links: [f64; 2],
}

/// The fixed pivots of a family, in the targets' normalised frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Family {
    pivots: [Pivot; 3],
}

impl Family {
    /// The family of `m` (in the targets' normalised frame).
    pub fn of(m: &CouplerFourBar) -> Self {
        // P = B + w (C − B) with C − B along the coupler frame's x-axis.
        let w = complex(m.point) / m.coupler;
        let one_minus = (nalgebra::Complex::new(1.0, 0.0) - w).norm();
        let o = m.a + (m.d - m.a) * w.re + crate::motion::perp(&(m.d - m.a)) * w.im;
        let pivot = |at: Vec2, x: f64, y: f64| Pivot {
            at,
            links: [x.min(y), x.max(y)],
        };
        Self {
            pivots: [
                pivot(m.a, m.crank, w.norm() * m.coupler),
                pivot(m.d, m.rocker, one_minus * m.coupler),
                pivot(o, one_minus * m.crank, w.norm() * m.rocker),
            ],
        }
    }

    /// Whether `other` has the same pivots with the same links, in any order.
    pub fn same_as(&self, other: &Self) -> bool {
        let close = |x: f64, y: f64, scale: f64| (x - y).abs() <= SAME * (1.0 + scale);
        self.pivots.iter().all(|p| {
            other.pivots.iter().any(|q| {
                (p.at - q.at).norm() <= SAME * (1.0 + p.at.norm())
                    && close(p.links[0], q.links[0], p.links[1])
                    && close(p.links[1], q.links[1], p.links[1])
            })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::cognates::cognates;
    use super::*;

    #[test]
    fn a_design_and_its_cognates_are_one_family_and_another_design_is_not() {
        let m = CouplerFourBar::from_params(&[0.0, 0.0, 4.0, 0.5, 1.2, 3.6, 3.0, 1.5, 1.1], true);
        let family = Family::of(&m);
        for c in cognates(&m, &[0.4]).expect("closes") {
            assert!(
                Family::of(&c.linkage).same_as(&family),
                "{:?}",
                c.turns_with
            );
        }
        let other = CouplerFourBar { rocker: 3.1, ..m };
        assert!(!Family::of(&other).same_as(&family));
    }
}
