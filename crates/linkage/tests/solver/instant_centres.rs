//! Instant centres by Kennedy's theorem (found from the pose alone) against two
//! references built here from the solver's velocities, in every shipped scene at 36
//! crank angles:
//! - each centre is where the two links' velocity fields agree (the relative velocity
//!   there is zero; a centre at infinity: no relative rotation, and the relative
//!   translation at right angles to its direction);
//! - the velocities a teacher gets from the centres (angular velocity ratios
//!   ω_j / ω_i = P_ij P_1i / P_ij P_1j from the crank's speed, then v = ω × r about
//!   each link's centre with the frame) equal the solver's to 1e-9 relative.
//!
//! Where Kennedy's lines all coincide (the quick return with its rocker upright) a
//! centre comes from the velocities instead; the test counts those poses.

use crate::common;

use common::{SCENES, cycle, kinematics};
use linkage::instant_centres::{Centre, FoundBy, InstantCentres, instant_centres};
use linkage::motion::perp;
use linkage::scene::SolverPath;
use linkage::{LinkId, Mechanism, Solution, Vec2};

/// Below this conditioning the pose is a dead point, where the crank no longer
/// drives the chain and the ratios are 0/0.
const DEAD: f64 = 1e-3;

fn point(c: &Centre) -> Option<Vec2> {
    match c {
        Centre::At([x, y]) => Some(Vec2::new(*x, *y)),
        Centre::AtInfinity(_) => None,
    }
}

/// Velocity of the material point of link `k` at `x`, from the solver.
fn velocity_of(s: &Solution, k: LinkId, x: &Vec2) -> Vec2 {
    s.links[k].material_point_at(x).velocity
}

fn check_against_velocity_fields(m: &Mechanism, s: &Solution, ic: &InstantCentres, what: &str) {
    let w_scale = s
        .links
        .iter()
        .map(|l| l.omega_rad_s.abs())
        .fold(0.0, f64::max);
    let v_scale = w_scale * m.size_m;
    for c in &ic.centres {
        let [i, j] = c.links;
        let dw = s.links[j].omega_rad_s - s.links[i].omega_rad_s;
        match c.centre {
            Centre::At([x, y]) => {
                let p = Vec2::new(x, y);
                let rel = (velocity_of(s, j, &p) - velocity_of(s, i, &p)).norm();
                assert!(
                    rel <= 1e-9 * v_scale,
                    "{what} P{i}{j}: relative velocity {rel:e}"
                );
                // Where the links turn relative to each other, the centre is one
                // point: found here as the zero of the relative velocity field.
                if dw.abs() > 1e-3 * w_scale {
                    let o = Vec2::zeros();
                    let dv0 = velocity_of(s, j, &o) - velocity_of(s, i, &o);
                    // dv0 + dw perp(x) = 0, perp(x) = (-x.y, x.x)
                    let reference = Vec2::new(-dv0.y / dw, dv0.x / dw);
                    let err = (reference - p).norm();
                    assert!(
                        err <= 1e-9 * m.size_m * w_scale / dw.abs(),
                        "{what} P{i}{j}: {p:?} vs {reference:?}"
                    );
                }
            }
            Centre::AtInfinity([dx, dy]) => {
                assert!(
                    dw.abs() <= 1e-9 * w_scale,
                    "{what} P{i}{j} at infinity, but dω = {dw:e}"
                );
                let o = Vec2::zeros();
                let dv = velocity_of(s, j, &o) - velocity_of(s, i, &o);
                let along = dv.dot(&Vec2::new(dx, dy)).abs();
                assert!(
                    along <= 1e-9 * v_scale,
                    "{what} P{i}{j}: translation along {along:e}"
                );
            }
        }
    }
}

/// Each link's angular velocity from the crank's by the ratio theorem: P_ij has the
/// same velocity on i and j, so ω_i (P_ij − P_gi) = ω_j (P_ij − P_gj) along the line
/// that holds the three centres.
fn omega_from_centres(m: &Mechanism, s: &Solution, ic: &InstantCentres) -> Vec<f64> {
    let (g, input) = (m.ground, m.driver.link);
    let w_in = s.links[input].omega_rad_s;
    let centre = |a: LinkId, b: LinkId| ic.between(a, b).expect("every centre found").centre;
    m.link_ids()
        .map(|j| {
            if j == g {
                return 0.0;
            }
            if j == input {
                return w_in;
            }
            match (centre(input, j), centre(g, j), centre(g, input)) {
                (_, Centre::AtInfinity(_), _) => 0.0,
                (Centre::AtInfinity(_), _, _) => w_in,
                (Centre::At(pij), Centre::At(pgj), Centre::At(pgi)) => {
                    let pij = Vec2::from(pij);
                    let (r_i, r_j) = (pij - Vec2::from(pgi), pij - Vec2::from(pgj));
                    w_in * r_i.dot(&r_j) / r_j.norm_squared()
                }
                (_, _, Centre::AtInfinity(_)) => panic!("the crank turns about its pivot"),
            }
        })
        .collect()
}

/// Every point's velocity from the centres: ω_j × (p − P_gj), or for a link that
/// translates, the velocity of its centre with a link that turns about a fixed one.
fn check_velocities_from_centres(m: &Mechanism, s: &Solution, ic: &InstantCentres, what: &str) {
    let g = m.ground;
    let omega = omega_from_centres(m, s, ic);
    let centre = |a: LinkId, b: LinkId| point(&ic.between(a, b).expect("found").centre);
    let v_scale = s
        .points
        .iter()
        .map(|p| p.velocity.norm())
        .fold(0.0, f64::max);
    for (j, link) in m.link_ids().zip(&m.links).filter(|(j, _)| *j != g) {
        let v_of = |p: &Vec2| -> Vec2 {
            if let Some(pgj) = centre(g, j) {
                return perp(&(p - pgj)) * omega[j];
            }
            let (pij, pgi, i) = m
                .link_ids()
                .filter(|&i| i != j && i != g)
                .find_map(|i| Some((centre(i, j)?, centre(g, i)?, i)))
                .expect("a turning link beside a translating one");
            perp(&(pij - pgi)) * omega[i]
        };
        for (pt, _) in &link.points {
            let p = s.points[*pt].position;
            let err = (v_of(&p) - s.points[*pt].velocity).norm();
            assert!(
                err <= 1e-9 * v_scale,
                "{what}: point {} on {}: {err:e} of {v_scale:e}",
                m.points[*pt].name,
                link.name
            );
        }
    }
}

#[test]
fn every_scene_has_every_centre_and_they_give_the_solver_s_velocities() {
    let (mut checked, mut by_velocities) = (0, Vec::new());
    for file in SCENES {
        let mut k = kinematics(file, SolverPath::Auto);
        let m = k.mechanism().clone();
        let n = m.links.len();
        for x in cycle(&k, 36) {
            let s = k.solve(x).expect("inside the cycle");
            let ic = instant_centres(&m, &s);
            let what = format!("{file} at {:.2} deg", x.to_degrees());
            if s.conditioning < DEAD {
                continue;
            }
            assert!(
                ic.unresolved.is_empty(),
                "{what}: unresolved {:?}",
                ic.unresolved
            );
            assert_eq!(ic.centres.len(), n * (n - 1) / 2, "{what}");
            check_against_velocity_fields(&m, &s, &ic, &what);
            check_velocities_from_centres(&m, &s, &ic, &what);
            checked += 1;
            if ic.centres.iter().any(|c| c.found_by == FoundBy::Velocities) {
                by_velocities.push(what);
            }
        }
    }
    assert!(checked >= 6 * 30, "{checked} poses checked");
    // Only the quick return's upright rocker (crank at 90 and 270 deg) needs them.
    assert_eq!(
        by_velocities,
        [
            "quick_return.ron at 90.00 deg",
            "quick_return.ron at 270.00 deg"
        ]
    );
}

#[test]
fn primary_centres_are_the_pins_and_a_slider_s_is_at_infinity_across_its_guide() {
    let mut k = kinematics("slider_crank.ron", SolverPath::Auto);
    let m = k.mechanism().clone();
    let s = k.solve(0.7).expect("assembles");
    let ic = instant_centres(&m, &s);
    for r in &m.revolutes {
        let c = ic.between(r.a, r.b).expect("a pin's centre");
        assert_eq!(c.found_by, FoundBy::Pin(r.point));
        assert_eq!(point(&c.centre), Some(s.points[r.point].position));
    }
    let slide = &m.sliders[0];
    let c = ic
        .between(slide.slider, slide.guide)
        .expect("the slider's centre");
    assert_eq!(c.found_by, FoundBy::Slide(0));
    let Centre::AtInfinity([dx, dy]) = c.centre else {
        panic!("{c:?}")
    };
    let guide = slide.direction(&s.links);
    assert!(guide.dot(&Vec2::new(dx, dy)).abs() < 1e-15);
    // The crank-block centre: where the rod's line meets the crank's, off the pins.
    let kennedy = ic
        .centres
        .iter()
        .filter(|c| matches!(c.found_by, FoundBy::Kennedy(_)));
    assert_eq!(kennedy.count(), 2, "P13 and P24 by Kennedy");
}
