//! Seed 2 (die cutter): the synthesized six-bar meets the paper's requirements; the
//! committed scene is what the synthesis gives; the "as printed" lengths report the
//! stroke and K they really give; the paper's v_B uses the motor speed.

use crate::common;

use common::{kinematics, mechanism, scene_text};
use linkage::analysis::{Stroke, TimeRatioNote, report};
use linkage::scene::{SceneFile, SolverPath};
use linkage::synthesis::{DieCutterSpec, die_cutter, toggle_six_bar_scene};

fn spec() -> DieCutterSpec {
    DieCutterSpec {
        stroke_m: 0.05,
        k: 1.3,
        link_m: 0.6,
        crank_rpm: 50.0,
    }
}

#[test]
fn synthesized_die_cutter_meets_stroke_k_and_toggle_at_top() {
    let mut k = kinematics("die_cutter.ron", SolverPath::Auto);
    let r = report(&mut k).expect("report");
    let stroke = r.strokes_m["die"];
    assert!((stroke - 0.050).abs() <= 0.0005, "stroke {stroke} m");
    let kk = r.time_ratio.expect("K defined");
    assert!((kk - 1.3).abs() <= 0.005, "K {kk}");
    // The slower stroke is the upward working stroke.
    assert!(
        matches!(
            &r.time_ratio_note,
            Some(TimeRatioNote::Strokes { output, slower: Stroke::Rising, .. }) if output == "die"
        ),
        "{:?}",
        r.time_ratio_note
    );
    // Toggle at the top: the die's max limit, where C lies on DE (rocker and CE collinear).
    let top = r
        .toggles
        .iter()
        .find(|t| t.output == "die" && t.ratio == linkage::analysis::ToggleRatio::Zero)
        .expect("die toggle");
    let top_limit = r
        .limit_positions
        .iter()
        .find(|l| l.output == "die" && l.kind == linkage::analysis::Extreme::Max)
        .expect("top");
    assert!((top.input_rad - top_limit.input_rad).abs() < 1e-9);
    assert!(
        (top_limit.value - 1.2).abs() < 1e-9,
        "top of stroke at DE = 2L: {}",
        top_limit.value
    );
    assert!(
        top.collinear_joints
            .iter()
            .any(|j| j.point == "C" && j.links == ["rocker", "link_ce"]),
        "{:?}",
        top.collinear_joints
    );
    // The paper's bound: pressure angle <= 16.6 deg, i.e. transmission of the slider group >= 73.4 deg.
    let phi30 = (1.0 - 0.05 / 1.2_f64).asin();
    assert!((phi30.to_degrees() - 73.4).abs() < 0.01);
}

#[test]
fn committed_die_cutter_scene_matches_the_synthesis() {
    let synthesis = die_cutter(&spec()).expect("synthesis");
    let fresh = toggle_six_bar_scene(&synthesis, spec().crank_rpm);
    let committed = SceneFile::parse(&scene_text("die_cutter.ron")).expect("parse");
    assert_eq!(fresh.links.len(), committed.links.len());
    for (a, b) in fresh.links.iter().zip(&committed.links) {
        for ((na, pa), (nb, pb)) in a.points.iter().zip(&b.points) {
            assert_eq!(na, nb);
            assert!(
                (pa.0 - pb.0).abs() < 1e-9 && (pa.1 - pb.1).abs() < 1e-9,
                "{na}: {pa:?} vs {pb:?}"
            );
        }
    }
    assert_eq!(fresh.branches, committed.branches);
    // The paper's loads are the committed file's, not the synthesis's: the scene
    // it builds carries geometry only.
    assert_eq!(fresh.forces, Default::default());
    assert!(fresh.links.iter().all(|l| l.mass.is_none()));
    let loaded = fresh.with_loads_of(&committed);
    assert_eq!(loaded.forces, committed.forces);
    for (a, b) in loaded.links.iter().zip(&committed.links) {
        assert_eq!(
            (a.mass, a.centroid, a.inertia),
            (b.mass, b.centroid, b.inertia),
            "{}",
            a.name
        );
    }
    assert_eq!(loaded.links.last().and_then(|l| l.mass), Some(120.0));
}

#[test]
fn as_printed_variant_reports_what_its_lengths_give() {
    let mut k = kinematics("die_cutter_as_printed.ron", SolverPath::Auto);
    let r = report(&mut k).expect("report");
    // Independent: chord C1C2 from the printed AC1 = BC - AB, AC2 = BC + AB and θ (law of
    // cosines), swing ψ from the chord, stroke 2L(1 - sin(90° - ψ)).
    let (ab, bc, l) = (0.296_f64, 0.892_f64, 0.6_f64);
    let theta = std::f64::consts::PI * 0.3 / 2.3;
    let (n, f) = (bc - ab, bc + ab);
    let chord = (n * n + f * f - 2.0 * n * f * theta.cos()).sqrt();
    let swing = 2.0 * (chord / (2.0 * l)).asin();
    let stroke = 2.0 * l * (1.0 - (std::f64::consts::FRAC_PI_2 - swing).sin());
    assert!(
        (r.swings_rad["rocker"] - swing).abs() < 1e-9,
        "{} vs {swing}",
        r.swings_rad["rocker"]
    );
    assert!(
        (r.strokes_m["die"] - stroke).abs() < 1e-9,
        "{} vs {stroke}",
        r.strokes_m["die"]
    );
    assert!(
        r.strokes_m["die"] > 0.7,
        "the printed lengths give a stroke far from 50 mm"
    );
    assert!(
        (swing.to_degrees() - 69.0).abs() < 1.0,
        "about 69 deg, as mechanisms.md says"
    );
    assert!((r.time_ratio.expect("K") - 1.3).abs() < 0.005);
}

#[test]
fn printed_v_b_uses_the_motor_speed() {
    let mut m = mechanism("die_cutter_as_printed.ron");
    assert!(
        (m.driver.speed_rad_s - 5.236).abs() < 5e-4,
        "the crank turns at 50 rpm"
    );
    assert!(
        m.notes
            .iter()
            .any(|n| n.contains("151.8") && n.contains("5.236"))
    );
    m.driver.speed_rad_s = 151.8;
    let b = m.point_index("B").expect("B");
    let mut k = linkage::Kinematics::new(m).expect("kinematics");
    for deg in [0.0_f64, 50.0, 200.0] {
        let s = k.solve(deg.to_radians()).expect("solve");
        let v_b = s.points[b].velocity.norm();
        assert!((v_b - 44.93).abs() < 0.005, "v_B = {v_b} m/s");
    }
}
