//! Path generation, checked by recovery: targets sampled from the coupler curves of
//! known four-bars (a crank-rocker, a double crank and a non-Grashof triple rocker),
//! timed and untimed, are met to 1e-6 of the targets' size with the default options;
//! the designs' scenes and their cognates' scenes, solved by the general solver, put
//! the coupler point on every target; untimed targets are met in their order.
//!
//! Regressions (issue 22, finding 2): with the default options the search missed an
//! ordinary crank-rocker whose pivots lay 1.5 times the targets' size away (1e-2 after
//! 3 million evaluations), counted a design's cognates as new solutions and so spent
//! its whole budget, and met untimed targets out of their order.

use linkage::synthesis::path::{
    CouplerFourBar, PathConstraints, PathDesign, PathLinkage, PathSearch, PathTargets,
    SearchOptions, TargetOrder, TurnsWith,
};
use linkage::{Kinematics, Mechanism, Vec2};

fn known(params: [f64; 9], left: bool) -> CouplerFourBar {
    CouplerFourBar::from_params(&params, left)
}

fn crank_rocker() -> CouplerFourBar {
    known([0.0, 0.0, 4.0, 0.5, 1.2, 3.6, 3.0, 1.5, 1.1], true)
}

fn double_crank() -> CouplerFourBar {
    known([0.0, 0.0, 1.0, 0.0, 2.5, 3.0, 2.8, -0.5, 1.2], false)
}

/// Non-Grashof (2.0 + 1.1 > 1.6 + 1.2): the crank rocks between ±78.6°.
fn triple_rocker() -> CouplerFourBar {
    known([0.0, 0.0, 1.6, 0.0, 2.0, 1.2, 1.1, 0.6, 0.8], true)
}

fn targets(m: &CouplerFourBar, degrees: &[f64], timed: bool) -> PathTargets {
    PathTargets {
        points_m: degrees
            .iter()
            .map(|d| {
                m.point_at(d.to_radians())
                    .expect("the known linkage closes")
                    .into()
            })
            .collect(),
        crank_deg: timed.then(|| degrees.to_vec()),
    }
}

fn size(t: &PathTargets) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in &t.points_m {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (hi[0] - lo[0]).hypot(hi[1] - lo[1])
}

fn search(t: &PathTargets, crank_turns: bool) -> PathDesign {
    let constraints = PathConstraints {
        crank_turns,
        ..PathConstraints::default()
    };
    let mut s = PathSearch::new(t, &constraints, SearchOptions::default()).expect("valid targets");
    let progress = s.run();
    assert!(
        progress.solutions >= 1,
        "no design within tolerance: {progress:?}"
    );
    s.designs()[0].clone()
}

/// A linkage's scene (the design's or a cognate's), solved by the general solver at
/// its crank angle at each target, puts P on the target (1e-6 of the targets' size).
fn check_scene(linkage: &PathLinkage, t: &PathTargets) {
    let mut k = Kinematics::new(Mechanism::from_scene(&linkage.scene(0.0)).expect("builds"))
        .expect("solves");
    let p = k.mechanism().point_index("P").expect("P on the coupler");
    let size = size(t);
    for (target, deg) in t.points_m.iter().zip(&linkage.crank_deg) {
        let at = k
            .solve(deg.to_radians())
            .expect("closes at a target")
            .points[p]
            .position;
        let miss = (at - Vec2::from(*target)).norm();
        assert!(
            miss <= 1e-6 * size,
            "misses {target:?} by {miss} (size {size})"
        );
    }
}

fn recover(m: &CouplerFourBar, degrees: &[f64], timed: bool, crank_turns: bool) {
    let t = targets(m, degrees, timed);
    let design = search(&t, crank_turns);
    assert!(design.relative_error <= 1e-6, "{design:?}");
    let d = &design.linkage;
    if timed {
        for (got, want) in d.crank_deg.iter().zip(degrees) {
            let turned = got - d.crank_deg[0] - (want - degrees[0]);
            assert!(turned.abs() < 1e-9, "timing kept: {got} for {want}");
        }
    } else {
        let angles: Vec<f64> = d.crank_deg.iter().map(|a| a.to_radians()).collect();
        assert!(
            design.linkage().ordered_travel(&angles).is_some(),
            "in order: {:?}",
            d.crank_deg
        );
    }
    assert!(d.crank_turns || !crank_turns);
    check_scene(d, &t);
    // Both cognates trace the same curve through the targets; the one turning with
    // the crank keeps the timing.
    assert_eq!(design.cognates.len(), 2, "{design:?}");
    for c in &design.cognates {
        let on_its_branch = c.linkage.min_transmission_deg.is_some();
        if on_its_branch {
            check_scene(&c.linkage, &t);
        }
        if c.turns_with == TurnsWith::Crank && timed {
            for (got, want) in c.linkage.crank_deg.iter().zip(degrees) {
                let turned = got - c.linkage.crank_deg[0] - (want - degrees[0]);
                let turned = (turned + 180.0).rem_euclid(360.0) - 180.0;
                assert!(
                    turned.abs() < 1e-9,
                    "the cognate keeps the timing: {got} for {want}"
                );
            }
        }
    }
}

fn every(from: f64, step: f64, n: usize) -> Vec<f64> {
    (0..n).map(|k| from + step * k as f64).collect()
}

#[test]
fn a_crank_rocker_is_recovered_without_timing() {
    recover(&crank_rocker(), &every(10.0, 33.0, 10), false, true);
}

#[test]
fn a_crank_rocker_is_recovered_with_timing() {
    recover(&crank_rocker(), &every(10.0, 33.0, 10), true, true);
}

#[test]
fn a_double_crank_is_recovered_without_timing() {
    recover(&double_crank(), &every(-40.0, 30.0, 10), false, true);
}

#[test]
fn a_double_crank_is_recovered_with_timing() {
    recover(&double_crank(), &every(-40.0, 30.0, 10), true, true);
}

#[test]
fn a_triple_rocker_is_recovered_with_timing() {
    recover(&triple_rocker(), &every(-70.0, 15.5, 10), true, false);
}

#[test]
fn a_triple_rocker_is_recovered_without_timing() {
    recover(&triple_rocker(), &every(-70.0, 15.5, 10), false, false);
}

fn quick() -> SearchOptions {
    SearchOptions {
        solutions: 1,
        tolerance: 1e-7,
        ..SearchOptions::default()
    }
}

#[test]
fn the_same_seed_gives_the_same_designs_and_slices_change_nothing() {
    // Untimed: timed targets are met from the dyads before the evolution runs, the
    // same whatever the seed.
    let t = targets(&crank_rocker(), &every(10.0, 33.0, 10), false);
    let constraints = PathConstraints::default();
    let mut whole = PathSearch::new(&t, &constraints, quick()).expect("valid");
    whole.run();
    let mut sliced = PathSearch::new(&t, &constraints, quick()).expect("valid");
    let mut slices = 0;
    while !sliced.step(100).done {
        slices += 1;
    }
    assert!(slices > 3, "ran in {slices} slices");
    assert_eq!(whole.designs(), sliced.designs());
    let other = SearchOptions { seed: 2, ..quick() };
    let mut reseeded = PathSearch::new(&t, &constraints, other).expect("valid");
    reseeded.run();
    assert_ne!(
        whole.progress().evaluations,
        reseeded.progress().evaluations
    );
}

#[test]
fn every_design_kept_meets_the_constraints() {
    let t = targets(&crank_rocker(), &every(10.0, 33.0, 6), false);
    let region = [[-1.0, -1.0], [5.0, 1.5]];
    let constraints = PathConstraints {
        crank_turns: true,
        min_transmission_deg: 35.0,
        ground_region_m: Some(region),
        one_branch: true,
        order: TargetOrder::AsGiven,
    };
    let options = SearchOptions {
        solutions: 3,
        max_evaluations: 400_000,
        ..SearchOptions::default()
    };
    let mut s = PathSearch::new(&t, &constraints, options).expect("valid");
    s.run();
    assert!(!s.designs().is_empty());
    let inside = |p: [f64; 2]| (0..2).all(|k| region[0][k] <= p[k] && p[k] <= region[1][k]);
    for design in s.designs() {
        let d = &design.linkage;
        assert!(d.crank_turns, "{d:?}");
        assert!(inside(d.pivot_a) && inside(d.pivot_d), "{d:?}");
        let mu = d.min_transmission_deg.expect("one branch");
        assert!(mu >= 35.0 - 1e-6, "{mu}");
        // The exact least transmission angle over the travel agrees with a fine sampling.
        let m = d.linkage();
        let angles: Vec<f64> = d.crank_deg.iter().map(|a| a.to_radians()).collect();
        let (start, len) = m.ordered_travel(&angles).expect("one branch, in order");
        let sampled = (0..=3600)
            .map(|k| {
                m.transmission_at(start + len * f64::from(k) / 3600.0)
                    .to_degrees()
            })
            .fold(f64::INFINITY, f64::min);
        assert!((sampled - mu).abs() < 1e-3, "{sampled} vs {mu}");
    }
    let errors: Vec<f64> = s.designs().iter().map(|d| d.relative_error).collect();
    assert!(
        errors.windows(2).all(|w| w[0] <= w[1]),
        "ranked: {errors:?}"
    );
}

#[test]
fn bad_targets_are_refused_with_their_cause() {
    let ok = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]];
    let refuse =
        |points: &[[f64; 2]], crank_deg: Option<Vec<f64>>, c: PathConstraints, want: &str| {
            let t = PathTargets {
                points_m: points.to_vec(),
                crank_deg,
            };
            let e = PathSearch::new(&t, &c, quick())
                .expect_err("refused")
                .to_string();
            assert!(e.contains(want), "{e}");
        };
    let c = PathConstraints::default;
    refuse(&ok[..2], None, c(), "3 to 20");
    refuse(&[[0.0, 0.0]; 21], None, c(), "3 to 20");
    refuse(
        &[[0.0, f64::NAN], [1.0, 0.0], [1.0, 1.0]],
        None,
        c(),
        "finite",
    );
    refuse(&[[2.0, 2.0]; 3], None, c(), "coincide");
    refuse(&ok, Some(vec![0.0, 10.0]), c(), "one per target");
    refuse(&ok, Some(vec![0.0, 10.0, f64::INFINITY]), c(), "finite");
    let tilted = PathConstraints {
        min_transmission_deg: 95.0,
        ..c()
    };
    refuse(&ok, None, tilted, "0 to 90");
    let empty = PathConstraints {
        ground_region_m: Some([[1.0, 0.0], [0.0, 1.0]]),
        ..c()
    };
    refuse(&ok, None, empty, "more than 0");
}

/// Ten untimed targets on the coupler curve of an ordinary crank-rocker whose ground
/// pivots lie 1.5 to 1.6 times the targets' size from their centroid: the default
/// options find it exactly. Before, the default region for the pivots (1.5 times the
/// size each way) left them out and the search ended at 1e-2 after 3 million
/// evaluations, whatever the seed.
#[test]
fn path_synthesis_finds_ordinary_four_bars_with_default_options() {
    let m = known([0.0, 0.0, 1.0, 0.0, 0.2, 1.0, 0.8, 0.5, 1.0], true);
    let t = targets(&m, &every(0.0, 36.0, 10), false);
    let (centre, size) = {
        let n = t.points_m.len() as f64;
        let c = t
            .points_m
            .iter()
            .fold(Vec2::zeros(), |c, p| c + Vec2::from(*p) / n);
        (c, self::size(&t))
    };
    let far = (m.a - centre).norm().min((m.d - centre).norm()) / size;
    assert!(far > 1.5, "the pivots lie beyond the old region: {far}");
    met_with_every_seed(&t);
}

/// A design and its two cognates are one family: asked for three families of an
/// over-determined problem (12 untimed targets: one curve, so one family), the search
/// ends when its restarts stop finding new ones, far short of its budget, with one
/// design. Before, the cognates counted as new solutions and every run spent its
/// whole budget.
#[test]
fn a_design_and_its_cognates_are_one_family_and_the_search_ends_when_no_new_one_comes() {
    let t = targets(&crank_rocker(), &every(5.0, 30.0, 12), false);
    let options = SearchOptions {
        solutions: 3,
        ..SearchOptions::default()
    };
    let mut s = PathSearch::new(&t, &PathConstraints::default(), options).expect("valid");
    let p = s.run();
    assert_eq!(p.solutions, 1, "{p:?}");
    assert!(p.evaluations < p.max_evaluations / 2, "{p:?}");
    let within: Vec<&PathDesign> = s
        .designs()
        .iter()
        .filter(|d| d.relative_error <= 1e-6)
        .collect();
    assert_eq!(within.len(), 1, "one family");
}

/// Untimed targets are met in the order given, once round the curve: twenty targets
/// round a closed coupler curve, under several seeds, in either direction. Before,
/// a search could meet them out of order (a 234° crank jump between neighbours).
#[test]
fn untimed_targets_are_met_in_their_order_once_round() {
    let mut t = targets(&double_crank(), &every(3.0, 18.0, 20), false);
    for reversed in [false, true] {
        if reversed {
            t.points_m.reverse();
        }
        for seed in 1..=3 {
            let options = SearchOptions {
                seed,
                ..SearchOptions::default()
            };
            let mut s = PathSearch::new(&t, &PathConstraints::default(), options).expect("valid");
            assert!(s.run().solutions >= 1);
            let d = &s.designs()[0];
            let angles: Vec<f64> = d.linkage.crank_deg.iter().map(|a| a.to_radians()).collect();
            assert!(
                d.linkage().ordered_travel(&angles).is_some(),
                "seed {seed}: {:?}",
                d.linkage.crank_deg
            );
        }
    }
}

/// Any order, asked for, keeps the search that ignores the order (the nine-point
/// problem, as it was tested before targets kept their order).
#[test]
fn any_order_when_asked_meets_untimed_targets_wherever_they_are_nearest() {
    let t = targets(&crank_rocker(), &every(10.0, 33.0, 9), false);
    let any = PathConstraints {
        order: TargetOrder::Any,
        ..PathConstraints::default()
    };
    let mut s = PathSearch::new(&t, &any, SearchOptions::default()).expect("valid");
    assert!(s.run().solutions >= 1);
    assert!(s.designs()[0].relative_error <= 1e-6);
}

/// The hard family's case that the search's seed decided (issue 31): a crank-rocker
/// with a small crank and its coupler point far outside the coupler, twelve untimed
/// targets on part of its cycle. With seed 1 the search ended at 1.2e-6 of the
/// targets' size after 3 million evaluations, the place it came near steered away
/// from and its refinement crawling along a long curved valley; met by three seeds of
/// four. Now met by every seed (the refinement follows the valley with geodesic
/// acceleration; a near miss is no longer steered away from).
#[test]
fn a_small_crank_with_a_far_coupler_point_is_found_whatever_the_seed() {
    let points_m = vec![
        [-0.024367253591821195, 0.014578395941006003],
        [-0.02391930027854472, 0.014944667588007245],
        [-0.023205433277046217, 0.015515093509588126],
        [-0.02263010026271721, 0.01596092174814789],
        [-0.02184270291177695, 0.0165485902894713],
        [-0.02104402962254159, 0.017117029083239886],
        [-0.02058331956351484, 0.017432425469157492],
        [-0.019750689371570693, 0.017980881098770052],
        [-0.019103662662429646, 0.018390941640542877],
        [-0.018611588178509976, 0.01869734492974855],
        [-0.01808500876440768, 0.019032411266578692],
        [-0.017948427619317957, 0.019130773896431887],
    ];
    let t = PathTargets {
        points_m,
        crank_deg: None,
    };
    met_with_every_seed(&t);
}

/// Default options meet `t` to 1e-6 of its size with seeds 1, 2 and 3.
fn met_with_every_seed(t: &PathTargets) {
    for seed in 1..=3 {
        let options = SearchOptions {
            seed,
            ..SearchOptions::default()
        };
        let mut s = PathSearch::new(t, &PathConstraints::default(), options).expect("valid");
        let p = s.run();
        assert!(p.solutions >= 1, "seed {seed}: {p:?}");
        assert!(s.designs()[0].relative_error <= 1e-6, "seed {seed}");
    }
}
