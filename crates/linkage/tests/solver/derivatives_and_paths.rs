//! Velocities and accelerations against central finite differences of positions,
//! and the closed-form path against Newton, on every shipped scene.

use crate::common;

use common::{SCENES, cycle, kinematics, motion_scales, wrap};
use linkage::dyad::{DyadKind, GroupLabel};
use linkage::polygon::{Component, Quantity};
use linkage::scene::SolverPath;
use linkage::{Kinematics, Solution};

fn solve(k: &mut Kinematics, x: f64) -> Solution {
    let w = k.mechanism().driver.speed_rad_s;
    let mut s = k.empty_solution();
    k.solve_into(x, w, &mut s)
        .unwrap_or_else(|e| panic!("{}: {e}", k.mechanism().name));
    s
}

/// Central differences with Richardson extrapolation, (4·D(h/2) − D(h))/3 with
/// h = 1e-4 rad: truncation O(h⁴)·|x⁽⁵⁾| ≈ 1e-16·size and round-off ≈ eps·size/h ≈
/// 2e-12·size, so 1e-8 of the scale leaves a wide margin while any wrong term (a
/// missing Coriolis or normal component) is of order 1. Positions next to a dead point
/// (conditioning < 0.3) are skipped: there derivatives grow like δ^(-k-1/2).
#[test]
fn velocities_and_accelerations_match_finite_differences() {
    let h = 1e-4;
    for file in SCENES {
        let mut k = kinematics(file, SolverPath::Auto);
        let w = k.mechanism().driver.speed_rad_s;
        let size = k.mechanism().size_m;
        let mut checked = 0;
        for x in cycle(&k, 97) {
            let s = solve(&mut k, x);
            if s.conditioning < 0.3 {
                continue; // next to a dead point the derivatives are unbounded
            }
            if common::near_cam_join(k.mechanism(), &s, 2.0 * h) {
                continue; // a cam's jerk jumps at its program's joins
            }
            let (lo, hi) = (solve(&mut k, x - h), solve(&mut k, x + h));
            let (lo2, hi2) = (solve(&mut k, x - h / 2.0), solve(&mut k, x + h / 2.0));
            let rich = |f: &dyn Fn(&Solution) -> f64| {
                let d1 = (f(&hi) - f(&lo)) / (2.0 * h);
                let d2 = (f(&hi2) - f(&lo2)) / h;
                (4.0 * d2 - d1) / 3.0
            };
            let (vs, as_) = (size * w.abs(), size * w * w);
            for p in 0..s.points.len() {
                let fd_v = linkage::Vec2::new(
                    rich(&|s| s.points[p].position.x),
                    rich(&|s| s.points[p].position.y),
                ) * w;
                let fd_a = linkage::Vec2::new(
                    rich(&|s| s.points[p].velocity.x),
                    rich(&|s| s.points[p].velocity.y),
                ) * w;
                let (v, a) = (s.points[p].velocity, s.points[p].acceleration);
                assert!(
                    (fd_v - v).amax() <= 1e-8 * vs.max(v.amax()),
                    "{file} v point {p} at {x}"
                );
                assert!(
                    (fd_a - a).amax() <= 1e-8 * as_.max(a.amax()),
                    "{file} a point {p} at {x}: {fd_a:?} vs {a:?}"
                );
            }
            for l in 0..s.links.len() {
                let theta = s.links[l].angle_rad();
                let fd_w = rich(&|q| wrap(q.links[l].angle_rad() - theta)) * w;
                let fd_al = rich(&|q| q.links[l].omega_rad_s) * w;
                assert!(
                    (fd_w - s.links[l].omega_rad_s).abs() <= 1e-8 * w.abs(),
                    "{file} omega link {l}"
                );
                assert!(
                    (fd_al - s.links[l].alpha_rad_s2).abs() <= 1e-8 * w * w,
                    "{file} alpha link {l}"
                );
            }
            checked += 1;
        }
        assert!(
            checked > 60,
            "{file}: only {checked} positions away from dead points"
        );
    }
}

/// Both paths on every scene over 720 positions: positions to 1e-12 of the size,
/// velocities and accelerations to 1e-12 of the largest in that position. Next to a
/// dead point (the flipper's range ends 1e-7 rad from one) round-off is amplified by
/// 1/conditioning per derivative, so the bound is 1e-12/conditioning² (conditioning is
/// 0.3 to 1 away from dead points, so there this is 1e-12 within a factor of 10).
#[test]
fn closed_form_and_newton_agree_to_1e12() {
    for file in SCENES {
        let mut cf = kinematics(file, SolverPath::ClosedForm);
        let mut nw = kinematics(file, SolverPath::Newton);
        assert_eq!(nw.path(), linkage::PathKind::Newton);
        let size = cf.mechanism().size_m;
        let mut worst: f64 = 0.0;
        for x in cycle(&cf, 720) {
            let (a, b) = (solve(&mut cf, x), solve(&mut nw, x));
            let amplification = 1.0 / a.conditioning.min(1.0).powi(2);
            let mut here: f64 = 0.0;
            let (vmax, amax) = motion_scales(&a, size);
            let w = a.input_speed_rad_s.abs();
            for (p, q) in a.points.iter().zip(&b.points) {
                here = here
                    .max((p.position - q.position).amax() / size)
                    .max((p.velocity - q.velocity).amax() / vmax)
                    .max((p.acceleration - q.acceleration).amax() / amax);
            }
            let wmax = a
                .links
                .iter()
                .map(|l| l.omega_rad_s.abs())
                .fold(w, f64::max);
            let almax = a
                .links
                .iter()
                .map(|l| l.alpha_rad_s2.abs())
                .fold(w * w, f64::max);
            for (p, q) in a.links.iter().zip(&b.links) {
                here = here
                    .max(wrap(p.angle_rad() - q.angle_rad()).abs())
                    .max((p.omega_rad_s - q.omega_rad_s).abs() / wmax)
                    .max((p.alpha_rad_s2 - q.alpha_rad_s2).abs() / almax);
            }
            worst = worst.max(here / amplification);
        }
        assert!(worst < 1e-12, "{file}: paths differ by {worst:e}");
    }
}

/// Every polygon equation closes: Σ lhs = Σ rhs to round-off, and the quick-return's
/// acceleration polygon holds the Coriolis term of the block on the turning rocker,
/// equal to 2 ω × v_rel computed here from the solution.
#[test]
fn polygon_equations_close_and_show_coriolis() {
    for file in SCENES {
        let mut k = kinematics(file, SolverPath::ClosedForm);
        for x in cycle(&k, 37) {
            let s = solve(&mut k, x);
            let scale = s
                .points
                .iter()
                .map(|p| p.acceleration.amax().max(p.velocity.amax()))
                .fold(1e-300, f64::max);
            for eq in linkage::polygon::polygons(&k, &s) {
                assert!(
                    eq.residual() <= 1e-12 * scale,
                    "{file}: {} residual {}",
                    eq.equation,
                    eq.residual()
                );
            }
        }
    }
    let mut k = kinematics("quick_return.ron", SolverPath::ClosedForm);
    let s = solve(&mut k, 0.7);
    let eqs = linkage::polygon::polygons(&k, &s);
    let acc = eqs
        .iter()
        .find(|e| {
            e.kind == Quantity::Acceleration
                && matches!(&e.group, GroupLabel::Dyad(d) if d.kind == DyadKind::Rpr)
        })
        .expect("RPR accel");
    let cor = acc
        .rhs
        .iter()
        .find(|t| t.symbol.component == Component::Coriolis)
        .expect("Coriolis term");
    let m = k.mechanism();
    let (rocker, b) = (
        m.link_index("rocker").expect("rocker"),
        m.point_index("B").expect("B"),
    );
    let on_rocker = s.links[rocker].material_point_at(&s.points[b].position);
    let v_rel = s.points[b].velocity - on_rocker.velocity;
    let expect = 2.0 * s.links[rocker].omega_rad_s * v_rel.norm();
    assert!(
        (cor.magnitude - expect.abs()).abs() < 1e-12 * expect.abs(),
        "{} vs {expect}",
        cor.magnitude
    );
    assert!(
        cor.magnitude > 0.1,
        "non-trivial Coriolis term at this position"
    );
}
