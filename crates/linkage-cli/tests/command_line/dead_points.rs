//! The command line near dead points. A slider-crank whose rod is shorter than its
//! crank rocks between dead points, where the slider's speed has no bound: `sweep`
//! says which rows sit next to them and where they are (before, it printed a slider
//! speed of 679 m/s and an acceleration of -8.3e9 m/s² there without a word);
//! `report --format text` says the peaks are unbounded there, and on a crank that
//! turns it gives them located, against the in-line slider-crank's closed form.

use crate::common;

use common::scene;

fn data(file: &str) -> String {
    format!("{}/tests/data/{file}", env!("CARGO_MANIFEST_DIR"))
}

fn linkage(args: &[&str]) -> (bool, String, String) {
    let (code, out, err) = common::run_linkage(args);
    (code == Some(0), out, err)
}

/// The dead points of the rocker-slider: where the 60 mm rod stands square to the
/// guide, the 100 mm crank at ±asin(60/100) from the guide's far side.
fn dead_points_deg() -> [f64; 2] {
    let half = (60.0_f64 / 100.0).asin().to_degrees();
    [360.0 - half, 360.0 + half]
}

#[test]
fn a_sweep_next_to_dead_points_says_so_with_their_angles() {
    let (ok, out, err) = linkage(&["sweep", &data("rocker_slider.ron"), "--steps", "12"]);
    assert!(ok, "{err}");
    assert_eq!(out.lines().count(), 13, "a header and 12 rows");
    let [a, b] = dead_points_deg();
    let want = format!("dead points, {a:.4} deg and {b:.4} deg; rows 1 and 12");
    assert!(err.contains(&want), "{err}");
    let (ok, out, _) = linkage(&[
        "sweep",
        &data("rocker_slider.ron"),
        "--steps",
        "12",
        "--format",
        "json",
    ]);
    assert!(ok);
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    let dead: Vec<f64> = serde_json::from_value(v["dead_points_rad"].clone()).expect("two");
    assert!((dead[0].to_degrees() - a).abs() < 1e-9 && (dead[1].to_degrees() - b).abs() < 1e-9);
    assert_eq!(v["rows_next_to_dead_points"], serde_json::json!([0, 11]));
}

/// `--steps 12` on a crank that turns: twelve rows 30° apart from the start, the
/// turn's end (its start again) not repeated, as the help says.
#[test]
fn twelve_steps_of_a_full_turn_are_thirty_degrees_apart() {
    let (ok, out, err) = linkage(&["sweep", &scene("slider_crank.ron"), "--steps", "12"]);
    assert!(ok, "{err}");
    let inputs: Vec<f64> = out
        .lines()
        .skip(1)
        .map(|l| {
            l.split(',')
                .next()
                .expect("input")
                .parse::<f64>()
                .expect("a number")
        })
        .collect();
    assert_eq!(inputs.len(), 12);
    for (i, x) in inputs.iter().enumerate() {
        // Degrees to six digits, a turn's angles written between 0 and 360.
        let step = (x - inputs[0]).rem_euclid(360.0);
        assert!((step - 30.0 * i as f64).abs() < 1e-3, "{i}: {step}");
    }
    let (_, help, _) = linkage(&["sweep", "--help"]);
    assert!(help.contains("N = 12 gives 0, 30, …, 330 deg"), "{help}");
}

#[test]
fn the_text_report_says_the_peaks_are_unbounded_at_dead_points() {
    let (ok, out, err) = linkage(&["report", &data("rocker_slider.ron"), "--format", "text"]);
    assert!(ok, "{err}");
    assert!(
        out.contains("largest speed of slider: unbounded: the input's range ends at dead points, crank 323.13° and 36.87°"),
        "{out}"
    );
    assert!(out.contains("stroke of slider: 80 mm"), "{out}");
}

/// The in-line slider-crank (crank 50 mm, rod 200 mm, 300 rpm): the slider's
/// largest speed and acceleration, located, against the closed form s(φ) = r cos φ +
/// √(l² − r² sin² φ) differentiated here (the acceleration's largest size, r ω² (1 +
/// r/l), is at φ = 0; the speed's by a fine scan of the closed form).
#[test]
fn the_text_report_gives_located_peaks_that_match_the_closed_form() {
    let (ok, out, err) = linkage(&["report", &scene("slider_crank.ron"), "--format", "text"]);
    assert!(ok, "{err}");
    let (r, l, w) = (0.05_f64, 0.2_f64, 300.0 * std::f64::consts::TAU / 60.0);
    let speed = |phi: f64| {
        let (s, c) = phi.sin_cos();
        -r * w * s * (1.0 + r * c / (l * l - r * r * s * s).sqrt())
    };
    let (best, at) = (0..3_600_000)
        .map(|i| i as f64 * std::f64::consts::TAU / 3_600_000.0)
        .map(|phi| (speed(phi).abs(), phi))
        .fold((0.0, 0.0), |a, b| if b.0 > a.0 { b } else { a });
    let shown = out
        .lines()
        .find(|l| l.starts_with("largest speed of slider"))
        .expect("a speed line");
    let value: f64 = shown
        .split(": ")
        .nth(1)
        .and_then(|t| t.split(' ').next())
        .and_then(|t| t.parse().ok())
        .expect("a value");
    assert!(
        (value.abs() - best).abs() < 1e-3 * best,
        "{shown} vs {best}"
    );
    let angle: f64 = shown
        .rsplit("crank ")
        .next()
        .and_then(|t| t.trim_end_matches('°').parse().ok())
        .expect("an angle");
    let d = (angle - at.to_degrees()).rem_euclid(360.0);
    assert!(
        d.min(360.0 - d) < 1e-2,
        "{shown}: the closed form's at {}",
        at.to_degrees()
    );
    let acceleration = r * w * w * (1.0 + r / l);
    let want = format!(
        "largest acceleration of slider: -{:.2} m/s² at crank 0°",
        acceleration
    );
    assert!(out.contains(&want), "{out} wants {want}");
}
