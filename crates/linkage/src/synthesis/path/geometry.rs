//! The four-bar the path search varies: ground pivots A and D, crank AB, coupler
//! BC, rocker DC and a coupler point P fixed to BC, with C on a chosen side of
//! B→D. Written in closed form (two circles meeting) rather than through the
//! general solver: the search evaluates it millions of times, and its crank-angle
//! ranges and transmission angles have exact expressions used as constraints.

use std::f64::consts::PI;

use crate::motion::Vec2;

/// Number of real parameters of a [`CouplerFourBar`] (its branch aside).
pub const PARAMS: usize = 9;

/// A four-bar with a coupler point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CouplerFourBar {
    /// Crank pivot A.
    pub a: Vec2,
    /// Rocker pivot D.
    pub d: Vec2,
    /// Crank AB.
    pub crank: f64,
    /// Coupler BC.
    pub coupler: f64,
    /// Rocker DC.
    pub rocker: f64,
    /// The coupler point in the coupler's frame: origin B, x-axis along B→C.
    pub point: Vec2,
    /// Whether C is left of the directed line B→D.
    pub c_left_of_bd: bool,
}

/// Where the moving pins are at one crank angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pins {
    /// The crank pin B.
    pub b: Vec2,
    /// The rocker pin C.
    pub c: Vec2,
    /// The coupler point P.
    pub p: Vec2,
}

impl CouplerFourBar {
    /// From `[ax, ay, dx, dy, crank, coupler, rocker, px, py]` and the branch.
    pub fn from_params(x: &[f64], c_left_of_bd: bool) -> Self {
        Self {
            a: Vec2::new(x[0], x[1]),
            d: Vec2::new(x[2], x[3]),
            crank: x[4],
            coupler: x[5],
            rocker: x[6],
            point: Vec2::new(x[7], x[8]),
            c_left_of_bd,
        }
    }

    /// The same four-bar moved by a similarity that keeps orientation: its lengths
    /// and coupler point times `scale`, its ground pivots mapped by `place` (which
    /// must scale by `scale`: a turn, the scale and a shift). The coupler point is
    /// in the coupler's own frame, so it only scales.
    pub fn similar(&self, scale: f64, place: impl Fn(Vec2) -> Vec2) -> Self {
        Self {
            a: place(self.a),
            d: place(self.d),
            crank: self.crank * scale,
            coupler: self.coupler * scale,
            rocker: self.rocker * scale,
            point: self.point * scale,
            c_left_of_bd: self.c_left_of_bd,
        }
    }

    /// The parameters in the order [`Self::from_params`] reads them.
    pub fn params(&self) -> [f64; PARAMS] {
        [
            self.a.x,
            self.a.y,
            self.d.x,
            self.d.y,
            self.crank,
            self.coupler,
            self.rocker,
            self.point.x,
            self.point.y,
        ]
    }

    /// The pins at crank angle `theta` (rad, from the x-axis), or `None` where the
    /// loop does not close (or a length is not positive).
    pub fn pins_at(&self, theta: f64) -> Option<Pins> {
        self.pins_and_gap_at(theta)
            .filter(|&(_, gap)| gap == 0.0)
            .map(|(pins, _)| pins)
    }

    /// The coupler point at crank angle `theta`, or `None` where it does not close.
    pub fn point_at(&self, theta: f64) -> Option<Vec2> {
        self.pins_at(theta).map(|pins| pins.p)
    }

    /// The coupler point at crank angle `theta` with C pulled onto the line BD where
    /// the loop does not close, and by how much it fails to close (0 where it
    /// closes): continuous across the closing limits, for least squares to cross
    /// them. `None` only for a length that is not positive or B on D.
    pub fn point_and_gap_at(&self, theta: f64) -> Option<(Vec2, f64)> {
        self.pins_and_gap_at(theta).map(|(pins, gap)| (pins.p, gap))
    }

    /// The pins, C pulled onto BD where the loop does not close, and the gap.
    fn pins_and_gap_at(&self, theta: f64) -> Option<(Pins, f64)> {
        let (sin, cos) = theta.sin_cos();
        self.pins_and_gap_along(Vec2::new(cos, sin))
    }

    /// [`Self::point_and_gap_at`] with the crank along the unit vector `along`
    /// (callers stepping round the crank turn it by a fixed rotation instead of
    /// taking a sine and a cosine at every step).
    pub fn point_and_gap_along(&self, along: Vec2) -> Option<(Vec2, f64)> {
        self.pins_and_gap_along(along)
            .map(|(pins, gap)| (pins.p, gap))
    }

    /// The coupler point at crank angle `theta` and its derivative with respect to
    /// the crank angle (from the velocities: the coupler turns so that C moves
    /// square to DC), or `None` where the loop does not close or is at a dead point.
    pub fn point_and_tangent_at(&self, theta: f64) -> Option<(Vec2, Vec2)> {
        let pins = self.pins_at(theta)?;
        let (e, f) = (pins.c - pins.b, pins.c - self.d);
        let b_rate = crate::motion::perp(&(pins.b - self.a));
        // B' + ω (C − B)⊥ = ω_DC (C − D)⊥; the dot with C − D drops the right side.
        let turn = crate::motion::cross(&e, &f);
        if turn == 0.0 {
            return None;
        }
        let omega = -b_rate.dot(&f) / turn;
        Some((
            pins.p,
            b_rate + crate::motion::perp(&(pins.p - pins.b)) * omega,
        ))
    }

    fn pins_and_gap_along(&self, along: Vec2) -> Option<(Pins, f64)> {
        let (bc, dc) = (self.coupler, self.rocker);
        if !(self.crank > 0.0 && bc > 0.0 && dc > 0.0) {
            return None;
        }
        let b = self.a + along * self.crank;
        let e = self.d - b;
        let len2 = e.norm_squared();
        if len2 == 0.0 || !len2.is_finite() {
            return None;
        }
        let along = (bc * bc - dc * dc + len2) / (2.0 * len2);
        let h2 = bc * bc / len2 - along * along;
        let len = len2.sqrt();
        // Where h² < 0 the circles miss each other by this much.
        let gap = if h2 >= 0.0 {
            0.0
        } else {
            ((len - (bc + dc)).max(0.0) + ((bc - dc).abs() - len).max(0.0)).max(f64::MIN_POSITIVE)
        };
        let side = if self.c_left_of_bd { 1.0 } else { -1.0 };
        let c = b + e * along + Vec2::new(-e.y, e.x) * (side * h2.max(0.0).sqrt());
        let u = (c - b) / (c - b).norm().max(f64::MIN_POSITIVE);
        let p = b + u * self.point.x + Vec2::new(-u.y, u.x) * self.point.y;
        Some((Pins { b, c, p }, gap))
    }

    /// Ground length AD and the direction of A→D, rad.
    fn ground(&self) -> (f64, f64) {
        let g = self.d - self.a;
        (g.norm(), g.y.atan2(g.x))
    }

    /// The range of cos ψ, ψ the crank angle from A→D, over which the loop closes:
    /// BD² = a² + g² − 2ag cos ψ must lie within [(b − c)², (b + c)²].
    fn closing_cos_range(&self) -> (f64, f64) {
        let (g, _) = self.ground();
        let (a, b, c) = (self.crank, self.coupler, self.rocker);
        let twice = 2.0 * a * g;
        if twice == 0.0 {
            return (f64::INFINITY, f64::NEG_INFINITY);
        }
        let base = a * a + g * g;
        (
            (base - (b + c) * (b + c)) / twice,
            (base - (b - c) * (b - c)) / twice,
        )
    }

    /// The arcs of crank angle over which the loop closes, as (start, length) in rad:
    /// one whole turn, one arc (the crank rocks through it and back), two arcs
    /// (a Grashof double-rocker's two circuits) or none.
    pub fn closing_arcs(&self) -> Vec<(f64, f64)> {
        let (lo, hi) = self.closing_cos_range();
        let (_, ground_dir) = self.ground();
        if lo > hi || lo > 1.0 || hi < -1.0 || !lo.is_finite() || !hi.is_finite() {
            return vec![];
        }
        match (lo <= -1.0, hi >= 1.0) {
            (true, true) => vec![(0.0, 2.0 * PI)],
            // cos ψ ≥ lo: about ψ = 0.
            (false, true) => {
                let half = lo.acos();
                vec![(ground_dir - half, 2.0 * half)]
            }
            // cos ψ ≤ hi: about ψ = π.
            (true, false) => {
                let edge = hi.acos();
                vec![(ground_dir + edge, 2.0 * (PI - edge))]
            }
            (false, false) => {
                let (near, far) = (hi.acos(), lo.acos());
                vec![
                    (ground_dir + near, far - near),
                    (ground_dir - far, far - near),
                ]
            }
        }
    }

    /// Whether the crank turns through a whole revolution (Grashof with the crank
    /// the shortest link, or a change-point linkage at its limit).
    pub fn crank_turns(&self) -> bool {
        let (lo, hi) = self.closing_cos_range();
        lo <= -1.0 && hi >= 1.0
    }

    /// How far the crank falls short of turning fully, as a length: 0 when it turns.
    pub fn turning_shortfall(&self) -> f64 {
        let (g, _) = self.ground();
        let (a, b, c) = (self.crank, self.coupler, self.rocker);
        ((g + a) - (b + c)).max(0.0) + ((b - c).abs() - (g - a).abs()).max(0.0)
    }

    /// The transmission angle (folded into [0, π/2]) where cos ψ = `cos_psi`.
    fn transmission_at_cos(&self, cos_psi: f64) -> f64 {
        let (g, _) = self.ground();
        let (a, b, c) = (self.crank, self.coupler, self.rocker);
        let bd2 = a * a + g * g - 2.0 * a * g * cos_psi;
        let mu = ((b * b + c * c - bd2) / (2.0 * b * c))
            .clamp(-1.0, 1.0)
            .acos();
        mu.min(PI - mu)
    }

    /// The transmission angle at crank angle `theta`, folded into [0, π/2].
    pub fn transmission_at(&self, theta: f64) -> f64 {
        let (_, ground_dir) = self.ground();
        self.transmission_at_cos((theta - ground_dir).cos())
    }

    /// The crank's travel through `thetas` without leaving the branch, if any: the
    /// shortest arc holding every angle over which the loop closes throughout.
    /// Returns the arc's start and length (rad).
    pub fn travel(&self, thetas: &[f64]) -> Option<(f64, f64)> {
        let mut sorted: Vec<f64> = thetas.iter().map(|t| t.rem_euclid(2.0 * PI)).collect();
        sorted.sort_by(f64::total_cmp);
        let n = sorted.len();
        // Each cyclic gap between neighbours is a candidate for the arc left out.
        let mut arcs: Vec<(f64, f64)> = (0..n)
            .map(|k| {
                let start = sorted[(k + 1) % n];
                let gap = (sorted[(k + 1) % n] - sorted[k]).rem_euclid(2.0 * PI);
                let gap = if n == 1 { 2.0 * PI } else { gap };
                (start, 2.0 * PI - gap)
            })
            .collect();
        arcs.sort_by(|x, y| x.1.total_cmp(&y.1));
        arcs.into_iter()
            .find(|&(start, len)| self.closes_over(start, len))
    }

    /// The crank's travel through `thetas` met in their order, once round at most:
    /// the arc from the first angle to the last in the sense in which every next
    /// angle lies ahead of the one before (counter-clockwise or clockwise), if the
    /// loop closes throughout it. Returns the arc's counter-clockwise start and its
    /// length (rad); `None` when the angles are in neither order or the arc leaves the
    /// branch.
    pub fn ordered_travel(&self, thetas: &[f64]) -> Option<(f64, f64)> {
        let (first, last) = (*thetas.first()?, *thetas.last()?);
        let ahead = |sense: f64| -> f64 {
            thetas
                .windows(2)
                .map(|w| (sense * (w[1] - w[0])).rem_euclid(2.0 * PI))
                .sum()
        };
        let (ccw, cw) = (ahead(1.0), ahead(-1.0));
        let arc = if ccw < 2.0 * PI && ccw <= cw {
            (first, ccw)
        } else if cw < 2.0 * PI {
            (last, cw)
        } else {
            return None;
        };
        self.closes_over(arc.0, arc.1).then_some(arc)
    }

    /// The range of cos ψ over the crank arc from `start` through `len`.
    fn cos_range(&self, start: f64, len: f64) -> (f64, f64) {
        let (_, ground_dir) = self.ground();
        let psi0 = start - ground_dir;
        let (c0, c1) = (psi0.cos(), (psi0 + len).cos());
        let (mut lo, mut hi) = (c0.min(c1), c0.max(c1));
        // cos ψ peaks at ψ = 0 (mod 2π) and bottoms at ψ = π inside the arc.
        let holds = |at: f64| (at - psi0).rem_euclid(2.0 * PI) <= len;
        if holds(0.0) {
            hi = 1.0;
        }
        if holds(PI) {
            lo = -1.0;
        }
        (lo, hi)
    }

    /// Whether the loop closes at every crank angle of the arc.
    fn closes_over(&self, start: f64, len: f64) -> bool {
        let (lo, hi) = self.cos_range(start, len);
        let (ok_lo, ok_hi) = self.closing_cos_range();
        lo >= ok_lo && hi <= ok_hi
    }

    /// The least transmission angle over the crank arc (it is least where BD is
    /// longest or shortest, at the ends of the arc's range of cos ψ).
    pub fn least_transmission_over(&self, start: f64, len: f64) -> f64 {
        let (lo, hi) = self.cos_range(start, len);
        self.transmission_at_cos(lo)
            .min(self.transmission_at_cos(hi))
    }
}

/// The distance from `q` to the segment `s0`–`s1`, and where along it (0 to 1).
pub fn to_segment(q: Vec2, s0: Vec2, s1: Vec2) -> (f64, f64) {
    let seg = s1 - s0;
    let len2 = seg.norm_squared();
    let t = if len2 > 0.0 {
        ((q - s0).dot(&seg) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    ((s0 + seg * t - q).norm(), t)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whether `c` lies left of the directed line `a`→`b`.
    fn left_of(a: Vec2, b: Vec2, c: Vec2) -> bool {
        crate::motion::cross(&(b - a), &(c - a)) > 0.0
    }

    fn crank_rocker() -> CouplerFourBar {
        CouplerFourBar::from_params(&[0.0, 0.0, 4.0, 0.0, 1.0, 3.5, 3.0, 1.0, 1.0], true)
    }

    #[test]
    fn the_pins_keep_their_lengths() {
        let m = crank_rocker();
        for k in 0..36 {
            let pins = m
                .pins_at(f64::from(k) * 0.17)
                .expect("a crank-rocker closes");
            assert!(((pins.b - m.a).norm() - 1.0).abs() < 1e-12);
            assert!(((pins.c - pins.b).norm() - 3.5).abs() < 1e-12);
            assert!(((pins.c - m.d).norm() - 3.0).abs() < 1e-12);
            assert!(((pins.p - pins.b).norm() - 2f64.sqrt()).abs() < 1e-12);
            assert!(left_of(pins.b, m.d, pins.c));
        }
    }

    #[test]
    fn a_crank_rocker_turns_and_a_triple_rocker_does_not() {
        assert!(crank_rocker().crank_turns());
        let rocker = CouplerFourBar::from_params(&[0., 0., 2., 0., 1.8, 1.0, 1.5, 0., 0.], true);
        assert!(!rocker.crank_turns());
        assert!(rocker.turning_shortfall() > 0.0);
        // Its closing range is where the sampled loop closes.
        let (start, len) = rocker
            .travel(&[0.4, 1.2])
            .expect("both between 14° and 82°");
        for k in 0..=100 {
            let t = start + len * f64::from(k) / 100.0;
            assert!(rocker.pins_at(t).is_some(), "closes at {t}");
        }
        assert!(
            rocker.travel(&[0.5, -0.5]).is_none(),
            "ψ = 0 is between, where BD is too short"
        );
    }

    /// Against sampling: the loop closes inside every closing arc and not just
    /// outside them, for a crank that turns, one that rocks about ψ = 0 and about π,
    /// and a Grashof double-rocker's two circuits.
    #[test]
    fn the_closing_arcs_are_where_the_loop_closes() {
        let cases = [
            crank_rocker(),
            CouplerFourBar::from_params(&[0., 0., 1., 0., 0.8, 2.0, 0.5, 0., 0.], true),
            CouplerFourBar::from_params(&[0., 0., 1.0, 0.3, 2.5, 1.2, 2.0, 0., 0.], true),
            CouplerFourBar::from_params(&[0., 0., 2.0, 0.5, 2.2, 0.6, 1.9, 0., 0.], false),
        ];
        for m in cases {
            let arcs = m.closing_arcs();
            assert!(!arcs.is_empty(), "{m:?}");
            let inside = |t: f64| arcs.iter().any(|&(s, l)| (t - s).rem_euclid(2.0 * PI) <= l);
            for k in 0..3600 {
                let t = f64::from(k) * PI / 1800.0;
                // A margin of 1e-6 rad either side of each end.
                let near_end = arcs.iter().any(|&(s, l)| {
                    let d = (t - s).rem_euclid(2.0 * PI);
                    d.min(2.0 * PI - d) < 1e-6 || (d - l).abs() < 1e-6
                });
                if !near_end {
                    assert_eq!(m.pins_at(t).is_some(), inside(t), "{m:?} at {t}");
                }
            }
        }
    }

    /// Against central differences of the point itself (1e-7 of the size).
    #[test]
    fn the_tangent_is_the_derivative_of_the_coupler_point() {
        let m = crank_rocker();
        for k in 0..36 {
            let t = f64::from(k) * 0.17;
            let (p, tangent) = m.point_and_tangent_at(t).expect("closes");
            let h = 1e-6;
            let fd = (m.point_at(t + h).expect("closes") - m.point_at(t - h).expect("closes"))
                / (2.0 * h);
            assert!((p - m.point_at(t).expect("closes")).norm() == 0.0);
            assert!(
                (tangent - fd).norm() < 1e-7 * 4.0,
                "at {t}: {tangent} vs {fd}"
            );
        }
    }

    #[test]
    fn the_ordered_travel_is_the_arc_in_the_targets_order() {
        let m = crank_rocker();
        // Counter-clockwise across 0: from 350° through 40°.
        let (start, len) = m.ordered_travel(&[-0.17, 0.1, 0.4, 0.7]).expect("in order");
        assert!((start + 0.17).abs() < 1e-12 && (len - 0.87).abs() < 1e-12);
        // Clockwise: the same arc, walked the other way.
        let (start, len) = m.ordered_travel(&[0.7, 0.4, 0.1, -0.17]).expect("in order");
        assert!((start + 0.17).abs() < 1e-12 && (len - 0.87).abs() < 1e-12);
        // Out of order either way.
        assert!(m.ordered_travel(&[0.0, 0.4, 0.2, 0.6]).is_none());
    }

    #[test]
    fn the_least_transmission_angle_is_the_sampled_one() {
        let m = crank_rocker();
        let sampled = (0..=3600)
            .map(|k| m.transmission_at(f64::from(k) * PI / 1800.0))
            .fold(f64::INFINITY, f64::min);
        let exact = m.least_transmission_over(0.0, 2.0 * PI);
        assert!((exact - sampled).abs() < 1e-5, "{exact} vs {sampled}");
    }
}
