//! `linkage gears pair`: the JSON (SI) of a shifted pair against the textbooks'
//! closed forms written here (working pressure angle from the shifts, contact ratio
//! by the tangent formula), the text in millimetres and degrees, and refusals in the
//! units typed, naming the gear and the valid range.

use crate::common;

use common::run_linkage;

fn json(args: &[&str]) -> serde_json::Value {
    let mut all = vec!["gears", "pair"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--format", "json"]);
    let (code, out, err) = run_linkage(&all);
    assert_eq!(code, Some(0), "{err}");
    serde_json::from_str(&out).expect("JSON")
}

fn number(v: &serde_json::Value, path: &[&str]) -> f64 {
    let mut at = v;
    for key in path {
        at = &at[*key];
    }
    at.as_f64().unwrap_or_else(|| panic!("{path:?} in {v}"))
}

/// z = 12 and 40, m = 2 mm, x = 0.3 and 0.2: inv α' = inv 20° + 2 tan 20° · 0.5/52,
/// a' = a cos 20°/cos α', the tips shortened by Δy·m, ε by the tangent formula.
#[test]
fn a_shifted_pair_is_the_textbooks() {
    let v = json(&[
        "--module", "2", "--teeth", "12", "40", "--shift", "0.3", "0.2",
    ]);
    let a20 = 20f64.to_radians();
    let inv = |x: f64| x.tan() - x;
    let target = inv(a20) + 2.0 * a20.tan() * 0.5 / 52.0;
    // Bisection for α', apart from the solver's Newton.
    let (mut lo, mut hi) = (0.0_f64, 1.5_f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if inv(mid) < target {
            lo = mid
        } else {
            hi = mid
        }
    }
    let aw = 0.5 * (lo + hi);
    assert!((number(&v, &["working_pressure_angle_rad"]) - aw).abs() < 1e-12);
    let a = 0.052;
    let centre = a * a20.cos() / aw.cos();
    assert!((number(&v, &["centre_m"]) - centre).abs() < 1e-15);
    // The tips cut down by Δy = x₁ + x₂ − y to keep the standard clearance.
    let dy = 0.5 - (centre - a) / 0.002;
    assert!((number(&v, &["tip_shortening"]) - dy).abs() < 1e-12);
    let term = |z: f64, x: f64| {
        let r = 0.001 * z;
        let ra = r + (1.0 + x - dy) * 0.002;
        let alpha_a = (r * a20.cos() / ra).acos();
        z * (alpha_a.tan() - aw.tan())
    };
    let eps = (term(12.0, 0.3) + term(40.0, 0.2)) / std::f64::consts::TAU;
    let ours = number(&v, &["contact_ratio"]);
    assert!((ours - eps).abs() < 1e-12, "{ours} vs {eps}");
    assert_eq!(v["issues"].as_array().map(Vec::len), Some(0), "{v}");
}

#[test]
fn the_text_is_in_millimetres_and_degrees_with_the_checks() {
    let (code, out, err) = run_linkage(&["gears", "pair", "--module", "3", "--teeth", "12", "30"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.starts_with("external pair: m = 3 mm, α = 20°"), "{out}");
    assert!(out.contains("centre distance a' (mm)"), "{out}");
    assert!(
        out.lines().any(|l| l.starts_with("pitch diameter d (mm)")
            && l.contains("36")
            && l.contains("90")),
        "{out}"
    );
    assert!(
        out.contains("check: the pinion is undercut by a rack cutter"),
        "{out}"
    );
}

#[test]
fn refusals_name_the_gear_the_number_and_its_range_in_the_units_typed() {
    let cases: [(&[&str], &str); 5] = [
        (&["--module", "2"], "required arguments were not provided"),
        (
            &["--module", "0", "--teeth", "20", "40"],
            "pinion: module 0 mm is outside the range 0.01 … 1000 mm",
        ),
        (
            &[
                "--module",
                "2",
                "--teeth",
                "20",
                "40",
                "--pressure-angle-deg",
                "50",
            ],
            "pinion: pressure angle 50° is outside the range 10 … 35°",
        ),
        (
            &[
                "--module",
                "2",
                "--teeth",
                "14",
                "31",
                "--centre-distance",
                "40",
            ],
            "centre distance 40 mm is outside the range 42.29 … 59.8 mm",
        ),
        (
            &["--module", "2", "--teeth", "40", "30", "--internal"],
            "the internal wheel's 30 teeth must be more than the pinion's 40",
        ),
    ];
    for (args, words) in cases {
        let mut all = vec!["gears", "pair"];
        all.extend_from_slice(args);
        let (code, _, err) = run_linkage(&all);
        assert_ne!(code, Some(0));
        assert!(err.contains(words), "{args:?}: {err}");
    }
}

/// `linkage train`: the die cutter's drive gives the crank 50 rpm and reduces the
/// drive's inertias to it; a planetary set with other inputs; refusals.
#[test]
fn train_speeds_ratios_and_refusals() {
    let file = common::repo("assets/trains/die_cutter_drive.ron");
    let (code, out, err) = run_linkage(&["train", &file, "--reduce-to", "crank"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.lines()
            .any(|l| l.starts_with("crank") && l.contains(" 50 ") && l.trim_end().ends_with("29")),
        "{out}"
    );
    assert!(
        out.contains("inertia reduced to crank: 1809 kg·m²"),
        "{out}"
    );
    let set = common::repo("assets/trains/planetary_ring_fixed.ron");
    let (code, out, err) = run_linkage(&[
        "train", &set, "--input", "sun", "1000", "--input", "carrier", "0", "--format", "json",
    ]);
    assert_eq!(code, Some(0), "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let ring = v["solution"]["speeds_rpm"][3]["rpm"]
        .as_f64()
        .expect("the ring's speed");
    assert!((ring + 250.0).abs() < 1e-9, "{ring}");
    let (code, _, err) = run_linkage(&["train", &set, "--input", "sun", "1000"]);
    assert_ne!(code, Some(0));
    assert!(err.contains("give 2 input speed(s) (1 given)"), "{err}");
}

/// `linkage gears profile`: 12 teeth unshifted are undercut and said to be; the SVG
/// and DXF are written; shifted by x_min they are not.
#[test]
fn a_cut_profile_is_written_and_its_undercut_said() {
    let dir = std::env::temp_dir().join(format!("linkage_gear_profile_{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let (svg, dxf) = (dir.join("g.svg"), dir.join("g.dxf"));
    let (svg_s, dxf_s) = (svg.display().to_string(), dxf.display().to_string());
    let args = [
        "gears", "profile", "--module", "2", "--teeth", "12", "--svg", &svg_s, "--dxf", &dxf_s,
    ];
    let (code, out, err) = run_linkage(&args);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains("undercut: the shift is 0.298 short of x_min = 0.2981"),
        "{out}"
    );
    let text = std::fs::read_to_string(&svg).expect("the SVG");
    assert!(
        text.contains("<polygon points=") && text.contains("z = 12, m = 2 mm"),
        "{}",
        &text[..300]
    );
    let drawing = std::fs::read_to_string(&dxf).expect("the DXF");
    assert!(drawing.contains("LWPOLYLINE") && drawing.contains("PROFILE"));
    let x_min = "0.29813332935693415";
    let (code, out, _) = run_linkage(&[
        "gears", "profile", "--module", "2", "--teeth", "12", "--shift", x_min, "--svg", &svg_s,
    ]);
    assert_eq!(code, Some(0));
    assert!(!out.contains("undercut"), "{out}");
    // Above 32.1° the basic rack's teeth are pointed: refused with the limit.
    let (code, _, err) = run_linkage(&[
        "gears",
        "profile",
        "--module",
        "2",
        "--teeth",
        "30",
        "--pressure-angle-deg",
        "34",
        "--svg",
        &svg_s,
    ]);
    assert_ne!(code, Some(0));
    assert!(
        err.contains("come to a point") && err.contains("below 32.1°"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// `linkage gears profile --internal`: a ring of 60 teeth cut by a pinion cutter of
/// 25, at the cutting centre distance (60 − 25)·2/2 = 35 mm, to the root diameter
/// 2·(35 + 25 + 2.5) = 125 mm; written as the ring's body; a cutter with as many
/// teeth as the ring is refused with the range.
#[test]
fn a_ring_is_cut_by_a_pinion_cutter() {
    let dir = std::env::temp_dir().join(format!("linkage_ring_profile_{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let svg = dir.join("ring.svg");
    let svg_s = svg.display().to_string();
    let ring = [
        "gears",
        "profile",
        "--module",
        "2",
        "--teeth",
        "60",
        "--internal",
    ];
    let (code, out, err) = run_linkage(&[&ring[..], &["--svg", &svg_s]].concat());
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains(
            "pinion cutter of 25 teeth at a centre distance of 35 mm, to a root diameter of 125 mm"
        ),
        "{out}"
    );
    let text = std::fs::read_to_string(&svg).expect("the SVG");
    assert!(text.contains("fill-rule=\"evenodd\"") && text.contains("internal, z = 60"));
    let (code, _, err) =
        run_linkage(&[&ring[..], &["--cutter-teeth", "60", "--svg", &svg_s]].concat());
    assert_ne!(code, Some(0));
    assert!(err.contains("needs 3 to 59 teeth"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A scene whose drive is a train: `linkage flywheel` counts the train's inertias
/// beside the flywheel, and a train that cannot drive the crank is refused naming
/// the key and the train's members.
#[test]
fn a_drive_train_joins_the_flywheel_sizing_and_is_refused_when_it_cannot_drive() {
    let file = common::repo("docs/examples/die_cutter_with_train.ron");
    let (code, out, err) = run_linkage(&["flywheel", &file, "--delta", "0.05"]);
    assert_eq!(code, Some(0), "{err}");
    // 1.6·29² + 3·10² + 4·5² + 63 kg·m², the train written out.
    assert!(
        out.contains("drive's rotor and train at crank 1.808600e3 kg·m²"),
        "{out}"
    );
    assert!(out.contains("on the motor shaft"), "{out}");
    let text = std::fs::read_to_string(&file).expect("read");
    let bad = std::env::temp_dir().join("linkage_bad_drive_train.ron");
    std::fs::write(
        &bad,
        text.replace("motor_member: \"motor\"", "motor_member: \"rotor\""),
    )
    .expect("write");
    let (code, _, err) = run_linkage(&["flywheel", bad.to_str().expect("path")]);
    assert_ne!(code, Some(0));
    assert!(
        err.contains("`motor_member` names `rotor`")
            && err.contains("motor, input_shaft, intermediate_shaft, crank"),
        "{err}"
    );
}

/// `linkage train --load`: a planetary set with its ring held, loaded at the carrier:
/// the sun takes the load over 1 + z_r/z_s, the ring's brake the rest, and the powers
/// cancel; a load where the speed is given is refused naming the member.
#[test]
fn train_torques_with_a_load() {
    let set = common::repo("assets/trains/planetary_ring_fixed.ron");
    let args = [
        "train", &set, "--load", "carrier", "-500", "--format", "json",
    ];
    let (code, out, err) = run_linkage(&args);
    assert_eq!(code, Some(0), "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let members = v["torques"]["members"].as_array().expect("members");
    let torque = |name: &str| {
        members
            .iter()
            .find(|m| m["member"] == name)
            .and_then(|m| m["torque_n_m"].as_f64())
            .expect("a member")
    };
    // z_sun 20, z_ring 80: 500/(1 + 4) on the sun, 400 on the ring.
    assert!((torque("sun") - 100.0).abs() < 1e-9, "{out}");
    assert!((torque("ring") - 400.0).abs() < 1e-9, "{out}");
    let (code, text, err) = run_linkage(&["train", &set, "--load", "carrier", "-500"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(text.contains("the frame (housing) takes 0 N·m"), "{text}");
    let (code, _, err) = run_linkage(&["train", &set, "--load", "sun", "5"]);
    assert_ne!(code, Some(0));
    assert!(
        err.contains("the load is on `sun`, whose speed is given"),
        "{err}"
    );
}

/// `linkage train --load` with the file's efficiencies: the die cutter's drive with
/// a V-belt of 0.96 and meshes of 0.98 asks 1/(0.96·0.98²) more of its motor than
/// ideal gears (548.8 → 595.2 N·m) and says what is lost; an efficiency above 1 is
/// refused with its range.
#[test]
fn a_train_with_efficiencies_says_what_it_loses() {
    let text = std::fs::read_to_string(common::repo("assets/trains/die_cutter_drive.ron"))
        .expect("the drive");
    let lossy = text
        .replace(
            "meshes: [(\"z1\", \"z2\"), (\"z3\", \"z4\")],",
            "meshes: [(\"z1\", \"z2\"), (\"z3\", \"z4\")], mesh_efficiency: Some(0.98),",
        )
        .replace("ratio: 2.9)", "ratio: 2.9, efficiency: Some(0.96))");
    assert_ne!(lossy, text, "the efficiencies were put in");
    let dir = std::env::temp_dir().join(format!("linkage_train_eff_{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let file = dir.join("drive.ron");
    std::fs::write(&file, &lossy).expect("written");
    let f = file.display().to_string();
    let (code, out, err) = run_linkage(&["train", &f, "--load", "crank", "-15915.5"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains("motor                          595.249"),
        "{out}"
    );
    assert!(out.contains("(efficiency 0.92198)"), "{out}");
    std::fs::write(&file, lossy.replace("Some(0.98)", "Some(1.2)")).expect("written");
    let (code, _, err) = run_linkage(&["train", &f]);
    assert_ne!(code, Some(0));
    assert!(
        err.contains("mesh_efficiency 1.2 is outside the range 0.01 … 1"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
