//! Seed 1 (paper-cup feed): the paper's own closed-form formulas, written out here
//! independently of the solver, agree with both solver paths to 1e-12 over a cycle.
//!
//! Oracle: eqs. (2)-(4) position by the half-angle substitution with the branch sign
//! kept by continuity, (6)-(7) angular velocities, (9)-(10) angular accelerations
//! (re-derived from the loop (1) because the extracted text garbles them), and the
//! second loop l_DF sin φ3 + l_GF sin φ4 = l_DH, x_G = l_DF cos φ3 + l_GF cos φ4 (eq. 11).

use crate::common;

use common::{cycle, kinematics, mechanism, wrap};
use linkage::scene::SolverPath;

struct Oracle {
    l1: f64,
    l2: f64,
    l3: f64,
    l4: f64,
    l_df: f64,
    l_gf: f64,
    l_dh: f64,
}

struct State {
    phi2: f64,
    phi3: f64,
    w2: f64,
    w3: f64,
    e2: f64,
    e3: f64,
    x_g: f64,
    v_g: f64,
    a_g: f64,
}

impl Oracle {
    /// φ3 and φ2 from eqs. (3) and (4), picking the ± branch nearest the previous values.
    fn position(&self, phi1: f64, prev: Option<(f64, f64)>) -> (f64, f64) {
        let (l1, l2, l3, l4) = (self.l1, self.l2, self.l3, self.l4);
        let a = 2.0 * l1 * l3 * phi1.sin();
        let b = 2.0 * l3 * (l1 * phi1.cos() - l4);
        let c = l2 * l2 - l1 * l1 - l3 * l3 - l4 * l4 + 2.0 * l1 * l4 * phi1.cos();
        let root3 = (a * a + b * b - c * c).sqrt();
        let d = 2.0 * l1 * l2 * phi1.sin();
        let e = 2.0 * l2 * (l1 * phi1.cos() - l4);
        let f = l1 * l1 + l2 * l2 + l4 * l4 - l3 * l3 - 2.0 * l1 * l4 * phi1.cos();
        let root2 = (d * d + e * e - f * f).sqrt();
        let cands: Vec<(f64, f64)> = [1.0, -1.0]
            .iter()
            .map(|s| {
                (
                    2.0 * ((d + s * root2) / (e - f)).atan(),
                    2.0 * ((a + s * root3) / (b - c)).atan(),
                )
            })
            .collect();
        // Pairs must close the loop (1); of those, keep the one continuous with prev.
        let closes = |(p2, p3): (f64, f64)| {
            let x = l1 * phi1.cos() + l2 * p2.cos() - l3 * p3.cos() - l4;
            let y = l1 * phi1.sin() + l2 * p2.sin() - l3 * p3.sin();
            x.hypot(y)
        };
        let mut pairs = vec![];
        for &(p2, _) in &cands {
            for &(_, p3) in &cands {
                if closes((p2, p3)) < 1e-9 {
                    pairs.push((p2, p3));
                }
            }
        }
        let pick = |p: &(f64, f64)| match prev {
            Some((q2, q3)) => wrap(p.0 - q2).abs() + wrap(p.1 - q3).abs(),
            // The scene's branch: C above the line BD, i.e. the rocker above the ground.
            None => -p.1.sin(),
        };
        pairs
            .into_iter()
            .min_by(|x, y| pick(x).total_cmp(&pick(y)))
            .expect("the oracle four-bar assembles")
    }

    fn state(&self, phi1: f64, w1: f64, prev: Option<(f64, f64)>) -> State {
        let (l1, l2, l3) = (self.l1, self.l2, self.l3);
        let (phi2, phi3) = self.position(phi1, prev);
        // Eqs. (6), (7).
        let w2 = -w1 * l1 * (phi1 - phi3).sin() / (l2 * (phi2 - phi3).sin());
        let w3 = w1 * l1 * (phi1 - phi2).sin() / (l3 * (phi3 - phi2).sin());
        // Eqs. (9), (10) (constant ω1).
        let e2 = (-w1 * w1 * l1 * (phi1 - phi3).cos() - w2 * w2 * l2 * (phi2 - phi3).cos()
            + w3 * w3 * l3)
            / (l2 * (phi2 - phi3).sin());
        let e3 = (w1 * w1 * l1 * (phi1 - phi2).cos() + w2 * w2 * l2
            - w3 * w3 * l3 * (phi3 - phi2).cos())
            / (l3 * (phi3 - phi2).sin());
        // Second loop (eq. 11), G to the right of F.
        let (l_df, l_gf) = (self.l_df, self.l_gf);
        let phi4 = ((self.l_dh - l_df * phi3.sin()) / l_gf).asin();
        let w4 = -l_df * w3 * phi3.cos() / (l_gf * phi4.cos());
        let e4 = (l_df * (w3 * w3 * phi3.sin() - e3 * phi3.cos()) + l_gf * w4 * w4 * phi4.sin())
            / (l_gf * phi4.cos());
        let x_g = l_df * phi3.cos() + l_gf * phi4.cos();
        let v_g = -l_df * w3 * phi3.sin() - l_gf * w4 * phi4.sin();
        let a_g = -l_df * (e3 * phi3.sin() + w3 * w3 * phi3.cos())
            - l_gf * (e4 * phi4.sin() + w4 * w4 * phi4.cos());
        State {
            phi2,
            phi3,
            w2,
            w3,
            e2,
            e3,
            x_g,
            v_g,
            a_g,
        }
    }
}

#[test]
fn paper_formulas_agree_with_both_solver_paths_to_1e12() {
    let m = mechanism("paper_cup_feed.ron");
    // The oracle reads only the scene's lengths, in the paper's notation.
    let oracle = Oracle {
        l1: 0.05,
        l2: 0.18,
        l3: 0.12,
        l4: 0.20,
        l_df: 0.16,
        l_gf: 0.20,
        l_dh: 0.25,
    };
    let w1 = m.driver.speed_rad_s;
    let idx = |n: &str| m.link_index(n).expect("link");
    let (coupler, rocker) = (idx("coupler"), idx("rocker"));
    let g = m.point_index("G").expect("G");
    let d_x = 0.20;
    for path in [SolverPath::ClosedForm, SolverPath::Newton] {
        let mut k = kinematics("paper_cup_feed.ron", path);
        let mut prev = None;
        let mut worst: f64 = 0.0;
        for phi1 in cycle(&k, 3600) {
            let o = oracle.state(phi1, w1, prev);
            prev = Some((o.phi2, o.phi3));
            let s = k.solve(phi1).expect("assembles over the whole cycle");
            let (c, r) = (&s.links[coupler], &s.links[rocker]);
            // Scale: angles ~1 rad, ω ~ ω1, α ~ ω1², slider in m, m/s, m/s².
            let errs = [
                wrap(c.angle_rad() - o.phi2),
                wrap(r.angle_rad() - o.phi3),
                (c.omega_rad_s - o.w2) / w1,
                (r.omega_rad_s - o.w3) / w1,
                (c.alpha_rad_s2 - o.e2) / (w1 * w1),
                (r.alpha_rad_s2 - o.e3) / (w1 * w1),
                s.points[g].position.x - d_x - o.x_g,
                (s.points[g].velocity.x - o.v_g) / w1,
                (s.points[g].acceleration.x - o.a_g) / (w1 * w1),
            ];
            for e in errs {
                worst = worst.max(e.abs());
            }
        }
        assert!(
            worst < 1e-12,
            "{path:?}: worst scaled difference to the paper's formulas {worst:e}"
        );
    }
}
