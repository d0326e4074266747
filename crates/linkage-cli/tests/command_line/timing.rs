//! `linkage timing`: the paper-cup feed with its cam, as CSV, JSON and a sheet; the
//! bell crank's dwells where the cam's program has them; bad options refused.

use crate::common;

use common::run_linkage;

fn scene(file: &str) -> String {
    format!("{}/../../assets/scenes/{file}", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn the_cam_feeds_timing_shows_the_bell_cranks_dwells_and_the_sliders_stroke() {
    let file = scene("paper_cup_cam_feed.ron");
    let (code, json, err) = run_linkage(&["timing", &file, "--format", "json"]);
    assert_eq!(code, Some(0), "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).expect("json");
    let lanes = v["lanes"].as_array().expect("lanes");
    let names: Vec<&str> = lanes
        .iter()
        .map(|l| l["name"].as_str().expect("name"))
        .collect();
    assert_eq!(names, ["bell_crank", "slider"]);
    let dwells: Vec<[f64; 2]> = lanes[0]["dwells"]
        .as_array()
        .expect("dwells")
        .iter()
        .map(|d| [0, 1].map(|i| d[i].as_f64().expect("angle").to_degrees()))
        .collect();
    assert_eq!(dwells.len(), 2, "{dwells:?}");
    // The program: dwells from 110 to 180 and from 290 to the turn's end (1 deg steps).
    for (got, want) in dwells.iter().zip([[110.0, 180.0], [290.0, 359.0]]) {
        assert!((got[0] - want[0]).abs() <= 1.0 && (got[1] - want[1]).abs() <= 1.0);
    }
    let swing =
        lanes[0]["range"][1].as_f64().expect("hi") - lanes[0]["range"][0].as_f64().expect("lo");
    assert!((swing.to_degrees() - 8.0).abs() < 1e-9, "{swing}");

    let (code, csv, err) = run_linkage(&["timing", &file, "--samples", "24"]);
    assert_eq!(code, Some(0), "{err}");
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("shaft_deg,bell_crank_deg,bell_crank_share,slider_m,slider_share")
    );
    assert_eq!(lines.count(), 24);
}

#[test]
fn the_sheet_is_written_and_bad_options_are_refused_by_name() {
    let dir = std::env::temp_dir().join(format!("linkage-timing-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch dir");
    let svg = dir.join("timing.svg");
    let file = scene("paper_cup_cam_feed.ron");
    let path = svg.to_str().expect("a path");
    let (code, _, err) = run_linkage(&["timing", &file, "--svg", path]);
    assert_eq!(code, Some(0), "{err}");
    let text = std::fs::read_to_string(&svg).expect("the sheet");
    for part in [
        "Timing diagram",
        "bell_crank",
        "swing 8°",
        "stroke",
        "dwells shaded",
    ] {
        assert!(text.contains(part), "{part}");
    }
    let (code, _, err) = run_linkage(&["timing", &file, "--samples", "2"]);
    assert_ne!(code, Some(0));
    assert!(
        err.contains("--samples 2") && err.contains("4 to 100000"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
