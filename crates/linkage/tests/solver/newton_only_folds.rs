//! A chain without a closed form is analysed, not assumed: its branch is traced to
//! its folds, which give the assembly range, and the report, the sweep and a solve
//! outside the range follow from it. Checked against an independent reference
//! written here: a Newton solver on the triad's two loop closures in absolute link
//! angles (its Jacobian checked by finite differences), folds solved as the
//! extended system F = 0, J v = 0, v·v₀ = 1, and swings and K from a dense trace.

use crate::common;

use common::triad::Triad;
use linkage::analysis::{assembly_ranges_of, report};
use linkage::{Kinematics, LinkageError, Mechanism, Vec2};
use nalgebra::{DMatrix, DVector, Matrix4, Vector4};

const TAU: f64 = std::f64::consts::TAU;

/// Unit vector at `a` and its derivative.
fn e(a: f64) -> Vec2 {
    Vec2::new(a.cos(), a.sin())
}
fn de(a: f64) -> Vec2 {
    Vec2::new(-a.sin(), a.cos())
}
/// `v` turned by `a`.
fn turn(v: Vec2, a: f64) -> Vec2 {
    Vec2::new(a.cos() * v.x - a.sin() * v.y, a.sin() * v.x + a.cos() * v.y)
}

/// The reference: unknowns θ = (θ₁ of l1, θₜ of the triad, θ₂ of l2, θ₃ of l3),
/// equations Q₂ and Q₃ reached both through the triad and through l2, l3.
struct Reference {
    t: Triad,
    len: [f64; 3],
}

impl Reference {
    fn new(t: Triad) -> Self {
        Self {
            t,
            len: t.lengths(),
        }
    }

    fn q1(&self, th: &Vector4<f64>, x: f64) -> Vec2 {
        e(x) * self.t.crank + e(th[0]) * self.len[0]
    }

    fn f(&self, th: &Vector4<f64>, x: f64) -> Vector4<f64> {
        let q1 = self.q1(th, x);
        let a = q1 + turn(self.t.q2 - self.t.q1, th[1]) - self.t.g2 - e(th[2]) * self.len[1];
        let b = q1 + turn(self.t.q3 - self.t.q1, th[1]) - self.t.g3 - e(th[3]) * self.len[2];
        Vector4::new(a.x, a.y, b.x, b.y)
    }

    /// ∂F/∂θ, analytic.
    fn jac(&self, th: &Vector4<f64>) -> Matrix4<f64> {
        let d1 = de(th[0]) * self.len[0];
        let (r2, r3) = (
            turn(self.t.q2 - self.t.q1, th[1]),
            turn(self.t.q3 - self.t.q1, th[1]),
        );
        let (d2, d3) = (-de(th[2]) * self.len[1], -de(th[3]) * self.len[2]);
        Matrix4::new(
            d1.x, -r2.y, d2.x, 0.0, //
            d1.y, r2.x, d2.y, 0.0, //
            d1.x, -r3.y, 0.0, d3.x, //
            d1.y, r3.x, 0.0, d3.y,
        )
    }

    /// ∂F/∂x.
    fn f_x(&self, x: f64) -> Vector4<f64> {
        let d = de(x) * self.t.crank;
        Vector4::new(d.x, d.y, d.x, d.y)
    }

    /// Plain Newton at fixed input; `None` if it does not converge.
    fn solve(&self, mut th: Vector4<f64>, x: f64) -> Option<Vector4<f64>> {
        for _ in 0..40 {
            let f = self.f(&th, x);
            if f.amax() < 1e-15 {
                return Some(th);
            }
            th -= self.jac(&th).lu().solve(&f)?;
        }
        (self.f(&th, x).amax() < 1e-13).then_some(th)
    }

    /// dθ/dx by the implicit function theorem.
    fn rate(&self, th: &Vector4<f64>, x: f64) -> Vector4<f64> {
        -self.jac(th).lu().solve(&self.f_x(x)).expect("regular")
    }

    /// The start pose, exact: the pins are placed there at x = 0.
    fn start(&self) -> Vector4<f64> {
        let t = &self.t;
        let ang = |a: Vec2, b: Vec2| (b - a).y.atan2((b - a).x);
        Vector4::new(ang(t.p1(), t.q1), 0.0, ang(t.g2, t.q2), ang(t.g3, t.q3))
    }

    /// Poses from the start in steps of `dx` (sign gives the direction) until
    /// Newton fails or det J changes sign (a fold), or `span` is covered.
    fn trace(&self, dx: f64, span: f64) -> Vec<(f64, Vector4<f64>)> {
        let mut out = vec![(0.0, self.start())];
        let sign = self.jac(&self.start()).determinant().signum();
        while out.len() as f64 * dx.abs() < span {
            let (x, th) = *out.last().expect("the start pose");
            let guess = th + self.rate(&th, x) * dx;
            match self.solve(guess, x + dx) {
                Some(next) if self.jac(&next).determinant().signum() == sign => {
                    out.push((x + dx, next))
                }
                _ => break,
            }
        }
        out
    }

    /// The fold near (x, θ): Newton on G(θ, x, v) = (F, J v, v·v₀ − 1) with a
    /// central-difference Jacobian.
    fn fold(&self, x: f64, th: Vector4<f64>) -> (f64, Vector4<f64>) {
        let svd = self.jac(&th).svd(true, true);
        let i = svd.singular_values.imin();
        let v0: Vector4<f64> = svd.v_t.expect("v").row(i).transpose();
        let g = |z: &DVector<f64>| -> DVector<f64> {
            let th = Vector4::new(z[0], z[1], z[2], z[3]);
            let v = Vector4::new(z[5], z[6], z[7], z[8]);
            let (f, jv) = (self.f(&th, z[4]), self.jac(&th) * v);
            DVector::from_iterator(
                9,
                f.iter().chain(jv.iter()).copied().chain([v.dot(&v0) - 1.0]),
            )
        };
        let mut z =
            DVector::from_iterator(9, th.iter().copied().chain([x]).chain(v0.iter().copied()));
        for _ in 0..30 {
            let r = g(&z);
            if r.amax() < 1e-14 {
                break;
            }
            let h = 1e-7;
            let mut jac = DMatrix::zeros(9, 9);
            for c in 0..9 {
                let (mut p, mut m) = (z.clone(), z.clone());
                p[c] += h;
                m[c] -= h;
                jac.set_column(c, &((g(&p) - g(&m)) / (2.0 * h)));
            }
            z -= jac.lu().solve(&r).expect("regular extended system");
        }
        assert!(
            g(&z).amax() < 1e-12,
            "the fold did not converge: {}",
            g(&z).amax()
        );
        (z[4], Vector4::new(z[0], z[1], z[2], z[3]))
    }

    /// Folds below and above the start (x, rad), with the poses there.
    fn folds(&self) -> [(f64, Vector4<f64>); 2] {
        [-1e-3, 1e-3].map(|dx| {
            let path = self.trace(dx, TAU);
            let (x, th) = *path.last().expect("the start pose");
            self.fold(x, th)
        })
    }
}

fn kinematics(t: &Triad) -> Kinematics {
    Kinematics::new(Mechanism::from_ron(&t.scene(0.0)).expect("valid scene")).expect("assembles")
}

#[test]
fn the_reference_jacobian_matches_finite_differences() {
    let r = Reference::new(Triad::locking());
    let (th, x, h) = (r.start() + Vector4::new(0.01, -0.02, 0.03, 0.01), 0.3, 1e-6);
    for c in 0..4 {
        let mut d = Vector4::zeros();
        d[c] = h;
        let fd = (r.f(&(th + d), x) - r.f(&(th - d), x)) / (2.0 * h);
        assert!((fd - r.jac(&th).column(c)).amax() < 1e-9, "column {c}");
    }
    let fd = (r.f(&th, x + h) - r.f(&th, x - h)) / (2.0 * h);
    assert!((fd - r.f_x(x)).amax() < 1e-9);
}

#[test]
fn a_newton_only_chain_is_traced_to_its_folds() {
    let t = Triad::locking();
    let [(lo, _), (hi, _)] = Reference::new(t).folds();
    let k = kinematics(&t);
    let [klo, khi] = k.traced_range().expect("the triad locks both ways");
    assert!((klo - lo).abs() < 1e-6, "low fold {klo} vs {lo} rad");
    assert!((khi - hi).abs() < 1e-6, "high fold {khi} vs {hi} rad");
    let ranges = assembly_ranges_of(&k);
    assert!(!ranges.full_rotation);
    let [[a, b]] = ranges.intervals[..] else {
        panic!("one interval: {ranges:?}")
    };
    assert!((a - lo.rem_euclid(TAU)).abs() < 1e-6 && (b - a - (hi - lo)).abs() < 1e-6);
}

#[test]
fn the_report_of_a_newton_only_chain_has_the_reference_swings() {
    let t = Triad::locking();
    let r = Reference::new(t);
    let [(lo, th_lo), (hi, th_hi)] = r.folds();
    // Dense trace between the folds: interior extremes are sampled to dx²·θ''/8.
    let mut poses: Vec<Vector4<f64>> = r.trace(-1e-4, -lo).into_iter().map(|p| p.1).collect();
    poses.extend(r.trace(1e-4, hi).into_iter().map(|p| p.1));
    poses.extend([th_lo, th_hi]);
    let swing = |i: usize| {
        let v = poses.iter().map(|p| p[i]);
        v.clone().fold(f64::MIN, f64::max) - v.fold(f64::MAX, f64::min)
    };
    let rep = report(&mut kinematics(&t)).expect("report");
    assert_eq!(rep.solver_path, linkage::PathKind::Newton);
    assert!(!rep.full_rotation);
    for (name, i) in [("l2", 2), ("l3", 3)] {
        let got = rep.swings_rad[name];
        assert!(
            (got - swing(i)).abs() < 1e-7,
            "{name}: swing {got} vs {}",
            swing(i)
        );
    }
    assert_eq!(rep.time_ratio, None, "no time ratio without a full turn");
    let [[a, b]] = rep.assembly_range_rad[..] else {
        panic!("{:?}", rep.assembly_range_rad)
    };
    assert!((b - a - (hi - lo)).abs() < 1e-6);
}

#[test]
fn a_newton_only_sweep_covers_exactly_the_assembly_range() {
    let t = Triad::locking();
    let [(lo, _), (hi, _)] = Reference::new(t).folds();
    let mut k = kinematics(&t);
    let sw = linkage::sweep::sweep(&mut k, 200).expect("sweep between the folds");
    let (first, last) = (sw.solutions[0].input_rad, sw.solutions[199].input_rad);
    // A sweep starts and ends a hair (1e-6 of the range) inside the dead points.
    let hair = 2e-6 * (hi - lo);
    assert!(
        (first - lo.rem_euclid(TAU)).abs() < hair,
        "first {first} vs {lo}"
    );
    assert!((last - first - (hi - lo)).abs() < 2.0 * hair, "last {last}");
    let size = 1.0;
    for s in &sw.solutions {
        let m = k.mechanism();
        let closure = m
            .revolutes
            .iter()
            .map(|j| (s.links[j.a].world(&j.a_local) - s.links[j.b].world(&j.b_local)).norm())
            .fold(0.0, f64::max);
        assert!(
            closure < 1e-12 * size,
            "closure {closure:e} at {}",
            s.input_rad
        );
    }
}

#[test]
fn a_newton_only_solve_outside_the_range_names_it() {
    let t = Triad::locking();
    let [(lo, _), (hi, _)] = Reference::new(t).folds();
    let mut k = kinematics(&t);
    let outside = 0.5 * (hi + lo + TAU);
    match k.solve(outside) {
        Err(LinkageError::CannotAssemble { reachable, .. }) => {
            let a = lo.rem_euclid(TAU).to_degrees();
            let b = a + (hi - lo).to_degrees();
            let want = format!("reachable input range: {a:.2}..{b:.2} deg");
            assert_eq!(reachable.to_string(), want);
        }
        other => panic!("expected the range named, got {other:?}"),
    }
    // ...and the solver is still on its branch afterwards.
    k.solve(0.5 * (hi + lo)).expect("inside the range again");
}

#[test]
fn a_fully_turning_newton_only_chain_has_the_reference_time_ratio() {
    // The first binary link at right angles to the line from Q1 to the triad's
    // instant centre, far from the fold: the crank turns fully.
    let t = Triad {
        crank: 0.05,
        q1: Vec2::new(0.07, 0.38),
        ..Triad::locking()
    };
    let r = Reference::new(t);
    let poses = r.trace(1e-3, TAU);
    assert!(
        poses.len() as f64 * 1e-3 >= TAU,
        "the reference turns fully"
    );
    // Limits of the main output (l3, the last link): zeros of dθ₃/dx, bisected.
    let rate3 = |x: f64, near: &Vector4<f64>| {
        let th = r.solve(*near, x).expect("on the branch");
        r.rate(&th, x)[3]
    };
    let mut limits = Vec::new();
    for w in poses.windows(2) {
        let [(x0, p0), (x1, _)] = [w[0], w[1]];
        let (mut a, mut b) = (x0, x1);
        if rate3(a, &p0).signum() == rate3(b, &p0).signum() {
            continue;
        }
        for _ in 0..60 {
            let m = 0.5 * (a + b);
            if rate3(m, &p0).signum() == rate3(a, &p0).signum() {
                a = m;
            } else {
                b = m;
            }
        }
        limits.push((0.5 * (a + b), rate3(x0, &p0) > 0.0));
    }
    let [(x_a, a_is_max), (x_b, _)] = limits[..] else {
        panic!("two limits expected: {limits:?}")
    };
    let (x_max, x_min) = if a_is_max { (x_a, x_b) } else { (x_b, x_a) };
    let rising = (x_max - x_min).rem_euclid(TAU);
    let k_ref = rising.max(TAU - rising) / rising.min(TAU - rising);

    let mut k = kinematics(&t);
    assert_eq!(k.traced_range(), None, "traced as a full turn");
    let rep = report(&mut k).expect("report");
    assert!(rep.full_rotation);
    let got = rep.time_ratio.expect("a time ratio");
    assert!((got - k_ref).abs() < 1e-9, "K {got} vs reference {k_ref}");
}
