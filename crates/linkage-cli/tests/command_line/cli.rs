//! The CLI contract that outside scripts depend on: column names and order, JSON
//! keys, exit status and error messages.

use crate::common;

use common::scene;

/// Runs `linkage ARGS`; returns (success, stdout, stderr).
fn linkage(args: &[&str]) -> (bool, String, String) {
    let (code, out, err) = common::run_linkage(args);
    (code == Some(0), out, err)
}

/// The CSV a student pastes: whole degrees 0..359 on a full turn, lengths in the
/// scene's millimetres, every column named with its unit, plain decimals; the
/// numbers are JSON's (SI) in those units.
#[test]
fn sweep_csv_is_the_table_a_report_takes() {
    let (ok, out, err) = linkage(&["sweep", &scene("slider_crank.ron")]);
    assert!(ok, "{err}");
    let mut lines = out.lines();
    let header: Vec<&str> = lines.next().expect("header").split(',').collect();
    assert_eq!(header[0], "input (deg)");
    assert_eq!(
        &header[1..7],
        [
            "A x (mm)",
            "A y (mm)",
            "A vx (mm/s)",
            "A vy (mm/s)",
            "A ax (mm/s^2)",
            "A ay (mm/s^2)"
        ]
    );
    assert_eq!(
        &header[header.len() - 3..],
        [
            "slider angle (deg)",
            "slider omega (rad/s)",
            "slider alpha (rad/s^2)"
        ]
    );
    let cells: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(cells.len(), 360);
    for (i, row) in cells.iter().enumerate() {
        assert_eq!(row.len(), header.len());
        assert_eq!(row[0], i.to_string(), "whole degrees from 0");
        assert!(
            row.iter()
                .all(|c| !c.contains(['e', 'E']) && c.parse::<f64>().is_ok_and(f64::is_finite)),
            "plain decimals: {row:?}"
        );
    }
    // Row 30 against `at --input-deg 30` in JSON (m, m/s): |v_B| = 50 mm · 31.416 rad/s.
    let column = |name: &str| header.iter().position(|h| *h == name).expect(name);
    let value = |name: &str| cells[30][column(name)].parse::<f64>().expect("number");
    let vb = value("B vx (mm/s)").hypot(value("B vy (mm/s)"));
    let want = 50.0 * 10.0 * std::f64::consts::PI;
    assert!((vb - want).abs() < 1e-5 * want, "{vb} vs {want}");
    let (_, json, _) = linkage(&["at", &scene("slider_crank.ron"), "--input-deg", "30"]);
    let v: serde_json::Value = serde_json::from_str(&json).expect("json");
    let cx = v["points"]["C"]["position"][0].as_f64().expect("C x") * 1e3;
    assert!((value("C x (mm)") - cx).abs() < 1e-5 * cx.abs(), "{cx}");
}

#[test]
fn at_json_lists_every_instant_centre_with_how_it_was_found() {
    let (ok, out, err) = linkage(&[
        "at",
        &scene("slider_crank.ron"),
        "--input-deg",
        "90",
        "--format",
        "json",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    let ic = &v["instant_centres"];
    let centres = ic["centres"].as_array().expect("centres");
    // Four links (ground, crank, rod, slider): six centres, none unresolved.
    assert_eq!(centres.len(), 6, "{ic}");
    assert_eq!(ic["unresolved"].as_array().map(Vec::len), Some(0));
    let find = |a: &str, b: &str| {
        centres
            .iter()
            .find(|c| {
                c["links"] == serde_json::json!([a, b]) || c["links"] == serde_json::json!([b, a])
            })
            .unwrap_or_else(|| panic!("no centre {a}-{b} in {ic}"))
    };
    // The block slides on the ground: its centre is at infinity, across the guide (y).
    let slide = find("ground", "slider");
    assert_eq!(
        slide["at_infinity"][0].as_f64().map(f64::abs),
        Some(0.0),
        "{slide}"
    );
    // At 90 deg the crank pin moves along the guide as the block does: the rod
    // translates, and its centre with the ground is at infinity, across the guide
    // (the lines A-B and through C across the guide are parallel).
    let rod = find("ground", "rod");
    let d = rod["at_infinity"]
        .as_array()
        .unwrap_or_else(|| panic!("{rod}"));
    assert!(d[0].as_f64().expect("x").abs() < 1e-12, "{rod}");
    assert!(
        rod["found_by"]
            .as_str()
            .expect("text")
            .starts_with("Kennedy via "),
        "{rod}"
    );
    // Elsewhere it is a point: at 60 deg on the crank line, past B.
    let (ok, out, err) = linkage(&[
        "at",
        &scene("slider_crank.ron"),
        "--input-deg",
        "60",
        "--format",
        "json",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    let rod = v["instant_centres"]["centres"]
        .as_array()
        .expect("centres")
        .iter()
        .find(|c| c["links"] == serde_json::json!(["ground", "rod"]))
        .expect("P ground-rod")
        .clone();
    let at: Vec<f64> = rod["at"]
        .as_array()
        .expect("a point")
        .iter()
        .filter_map(|x| x.as_f64())
        .collect();
    let (c60, s60) = (60f64.to_radians().cos(), 60f64.to_radians().sin());
    let x_c = 0.05 * c60 + (0.2f64.powi(2) - (0.05 * s60).powi(2)).sqrt();
    // On the crank line (y = x tan 60°) at x = x_c (the line through C across the guide).
    assert!(
        (at[0] - x_c).abs() < 1e-12 && (at[1] - x_c * s60 / c60).abs() < 1e-12,
        "{at:?}"
    );
}

#[test]
fn at_json_adds_polygon_equations() {
    let (ok, out, err) = linkage(&[
        "at",
        &scene("die_cutter.ron"),
        "--input-deg",
        "30",
        "--format",
        "json",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    let polygons = v["polygons"].as_array().expect("polygons");
    let eqs: Vec<&str> = polygons
        .iter()
        .map(|p| p["equation"].as_str().unwrap_or(""))
        .collect();
    assert!(eqs.contains(&"v_C = v_B + v_CB"), "{eqs:?}");
    assert!(
        eqs.contains(&"a_C^n + a_C^t = a_B^n + a_B^t + a_CB^n + a_CB^t"),
        "{eqs:?}"
    );
    let term = &polygons[0]["rhs"][1];
    assert_eq!(term["symbol"], "v_CB");
    assert_eq!(term["magnitude_known"], false);
    assert_eq!(term["direction"], "perp CB");
    // CSV form: the sweep header and one row.
    let (ok, csv, _) = linkage(&[
        "at",
        &scene("die_cutter.ron"),
        "--input-deg",
        "30",
        "--format",
        "csv",
    ]);
    assert!(ok && csv.lines().count() == 2 && csv.starts_with("input (deg),"));
    assert!(
        csv.lines().nth(1).is_some_and(|row| row.starts_with("30,")),
        "{csv}"
    );
}

#[test]
fn report_has_the_contract_keys() {
    let (ok, out, err) = linkage(&["report", &scene("paper_cup_feed.ron")]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    for key in [
        "assembly_range_rad",
        "limit_positions",
        "strokes_m",
        "swings_rad",
        "time_ratio",
        "grashof",
        "transmission_angle_rad",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    for key in ["min", "max", "at"] {
        assert!(
            v["transmission_angle_rad"][key].is_f64(),
            "transmission_angle_rad.{key}"
        );
    }
    assert_eq!(v["grashof"]["class"], "crank-rocker");
    let (ok, out, _) = linkage(&["report", &scene("quick_return.ron")]);
    assert!(ok);
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    assert!(v["grashof"].is_null(), "no four-bar loop in the shaper");
}

#[test]
fn synth_commands_design_and_write_scenes() {
    let dir = scratch("linkage-cli-test");
    let out_scene = dir.join("cr.ron");
    let (ok, out, err) = linkage(&[
        "synth",
        "crank-rocker",
        "--rocker",
        "0.5",
        "--swing-deg",
        "45",
        "--k",
        "1.25",
        "--scene-out",
        out_scene.to_str().expect("utf-8 path"),
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    let (a, b) = (
        v["crank_m"].as_f64().expect("a"),
        v["coupler_m"].as_f64().expect("b"),
    );
    assert!(a > 0.0 && b > a);
    let (ok, rep, err) = linkage(&["report", out_scene.to_str().expect("path")]);
    assert!(ok, "{err}");
    let r: serde_json::Value = serde_json::from_str(&rep).expect("json");
    assert!((r["time_ratio"].as_f64().expect("K") - 1.25).abs() < 1e-6);
    let (ok, text, err) = linkage(&["synth", "die-cutter"]);
    assert!(ok, "{err}");
    assert!(linkage::Mechanism::from_ron(&text).is_ok());
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn errors_exit_nonzero_and_name_the_cause() {
    let cases: [(Vec<String>, &str); 6] = [
        (
            vec!["report".into(), "/no/such/scene.ron".into()],
            "cannot read scene",
        ),
        (
            vec![
                "at".into(),
                scene("gravity_flipper.ron"),
                "--input-deg".into(),
                "20".into(),
            ],
            "reachable input range: 34.30..117.66 deg",
        ),
        (
            vec![
                "sweep".into(),
                scene("slider_crank.ron"),
                "--branch".into(),
                "C=sideways".into(),
            ],
            "side must be",
        ),
        (
            vec![
                "sweep".into(),
                scene("slider_crank.ron"),
                "--steps".into(),
                "1".into(),
            ],
            "at least 2",
        ),
        (
            vec![
                "synth".into(),
                "crank-rocker".into(),
                "--rocker".into(),
                "0.5".into(),
                "--swing-deg".into(),
                "200".into(),
                "--k".into(),
                "1.2".into(),
            ],
            "(0, 180)",
        ),
        (
            vec![
                "at".into(),
                scene("slider_crank.ron"),
                "--input-deg".into(),
                "NaN".into(),
            ],
            "finite",
        ),
    ];
    for (args, needle) in cases {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let (ok, _, err) = linkage(&args);
        assert!(!ok, "{args:?} should fail");
        assert!(err.contains(needle), "{args:?}: `{needle}` not in `{err}`");
    }
    // A malformed scene names line and column.
    let bad = std::env::temp_dir().join(format!("linkage-bad-{}.ron", std::process::id()));
    std::fs::write(&bad, "Scene(\n  name: 12,\n)").expect("write");
    let (ok, _, err) = linkage(&["report", bad.to_str().expect("path")]);
    assert!(!ok && err.contains("line 2, column"), "{err}");
    let _ = std::fs::remove_file(bad);
}

#[test]
fn simulate_prints_a_uniform_grid_with_links_energy_and_events() {
    let (ok, out, err) = linkage(&[
        "simulate",
        &scene("gravity_flipper.ron"),
        "--dt",
        "1e-4",
        "--dt-out",
        "0.01",
    ]);
    assert!(ok, "{err}");
    let mut lines = out.lines();
    let header: Vec<&str> = lines.next().expect("header").split(',').collect();
    assert_eq!(
        &header[..5],
        ["t", "q", "q_dot", "link1_theta", "link1_omega"]
    );
    assert_eq!(header.last(), Some(&"energy_balance_j"));
    let t: Vec<f64> = lines
        .map(|l| l.split(',').next().expect("t").parse().expect("number"))
        .collect();
    assert!(
        t.windows(2)
            .take(t.len() - 2)
            .all(|w| ((w[1] - w[0]) - 0.01).abs() < 1e-12),
        "uniform grid"
    );
    let (ok, out, err) = linkage(&[
        "simulate",
        &scene("gravity_flipper.ron"),
        "--format",
        "json",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    let events = v["events"].as_array().expect("events");
    let event = events.last().expect("an event");
    assert_eq!(event["name"], "table end stop");
    assert_eq!(event["stopped"], true);
    // Link 1 nears its dead point at 34.3 deg before the stop at 35 deg: the run
    // switches to link 3's angle on the way.
    assert!(
        events
            .iter()
            .any(|e| e["name"] == "coordinate switch from link1 to link3"),
        "{events:?}"
    );
    assert!(event["links"]["table"]["theta"].is_f64() && event["links"]["link3"]["omega"].is_f64());
    assert!(v["stats"]["rhs_evaluations"].as_u64().expect("count") > 0);
    let (ok, _, err) = linkage(&["simulate", &scene("slider_crank.ron")]);
    assert!(!ok && err.contains("no link has a mass"), "{err}");
}

#[test]
fn tradeoff_writes_the_table_and_the_plot() {
    let png = std::env::temp_dir().join(format!("linkage_tradeoff_{}.png", std::process::id()));
    let (ok, out, err) = linkage(&[
        "tradeoff",
        &scene("gravity_flipper.ron"),
        "--png",
        png.to_str().expect("path"),
    ]);
    assert!(ok, "{err}");
    let mut lines = out.lines();
    assert_eq!(
        lines.next(),
        Some("method,setting,cpu_seconds,rhs_evaluations,steps,max_q_error_rad,event_time_error_s")
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    for method in ["energy", "euler", "implicit", "rk4", "dp5", "dop853"] {
        let errors: Vec<f64> = rows
            .iter()
            .filter(|r| r[0] == method)
            .map(|r| r[5].parse().expect("error"))
            .collect();
        assert!(errors.len() >= 5, "{method}");
        // Tighter settings come later in each method's rows: the last beats the first.
        assert!(errors.last() < errors.first(), "{method}: {errors:?}");
    }
    let bytes = std::fs::read(&png).expect("png written");
    assert_eq!(&bytes[1..4], b"PNG");
    let _ = std::fs::remove_file(png);
}

#[test]
fn kinetostatics_prints_torques_reactions_and_amplification() {
    let (ok, out, err) = linkage(&[
        "kinetostatics",
        &scene("die_cutter.ron"),
        "--steps",
        "72",
        "--format",
        "json",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    let columns = v["columns"].as_array().expect("columns");
    assert_eq!(columns[1], "torque_n_m");
    assert!(columns.iter().any(|c| c == "die_on_ground_couple"));
    assert_eq!(columns.last().expect("last"), "amplification");
    assert!(v["torque_agreement_relative"].as_f64().expect("number") < 1e-9);
    assert_eq!(v["rows"].as_array().expect("rows").len(), 72);
    let (ok, _, err) = linkage(&["kinetostatics", &scene("slider_crank.ron")]);
    assert!(!ok && err.contains("models kinematics only"), "{err}");
}

/// The couple columns follow the joints' kinds, not their names: a link named
/// `crank_on_shaft` puts no couple column on the revolutes it joins.
#[test]
fn a_link_named_like_a_slider_joint_gets_no_couple_column() {
    let text = std::fs::read_to_string(scene("die_cutter.ron")).expect("scene");
    let renamed = text.replace("\"crank\"", "\"crank_on_shaft\"");
    assert_ne!(renamed, text);
    let file = std::env::temp_dir().join(format!("linkage-on-{}.ron", std::process::id()));
    std::fs::write(&file, renamed).expect("write");
    let (ok, out, err) = linkage(&[
        "kinetostatics",
        file.to_str().expect("path"),
        "--steps",
        "4",
        "--format",
        "json",
    ]);
    let _ = std::fs::remove_file(&file);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    let columns: Vec<&str> = v["columns"]
        .as_array()
        .expect("columns")
        .iter()
        .map(|c| c.as_str().expect("text"))
        .collect();
    assert!(columns.iter().any(|c| c.contains("crank_on_shaft")));
    let couples: Vec<&str> = columns
        .iter()
        .copied()
        .filter(|c| c.ends_with("_couple"))
        .collect();
    assert_eq!(couples, ["die_on_ground_couple"]);
}

#[test]
fn a_newton_only_chain_at_outside_its_range_names_it_and_sweep_covers_it() {
    let file = format!(
        "{}/tests/data/triad_six_bar.ron",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&file).expect("fixture");
    let k = linkage::Kinematics::new(linkage::Mechanism::from_ron(&text).expect("valid"))
        .expect("assembles");
    let [lo, hi] = k.traced_range().expect("the triad locks both ways");
    let a = lo.rem_euclid(std::f64::consts::TAU).to_degrees();
    let b = a + (hi - lo).to_degrees();
    let (ok, _, err) = linkage(&["at", &file, "--input-deg", "120"]);
    assert!(!ok, "120 deg is outside the range");
    let want = format!("reachable input range: {a:.2}..{b:.2} deg");
    assert!(err.contains(&want), "{err}");
    let (ok, out, err) = linkage(&["sweep", &file, "--steps", "50", "--format", "json"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    let inputs: Vec<f64> = v["rows"]
        .as_array()
        .expect("rows")
        .iter()
        .map(|row| row[0].as_f64().expect("input_rad"))
        .collect();
    assert_eq!(inputs.len(), 50);
    // The sweep's ends are 1e-6 of the range inside the dead points.
    let width = hi - lo;
    assert!((inputs[0] - lo.rem_euclid(std::f64::consts::TAU)).abs() < 2e-6 * width);
    assert!((inputs[49] - inputs[0] - width).abs() < 3e-6 * width);
}

/// `synth function` through three angle pairs of a known crank-rocker (AB 0.4, BC 0.9,
/// CD 0.7, AD 1.0 m): it gives back the lengths, and the scene it writes puts C, at
/// each precision point, where the rocker angle says (`linkage at`).
#[test]
fn synth_function_designs_a_generator_through_its_points() {
    let (a, b, c, d) = (0.4f64, 0.9f64, 0.7f64, 1.0f64);
    let rocker = |theta: f64| {
        let (bx, by) = (a * theta.cos(), a * theta.sin());
        let (dx, dy) = (d - bx, -by);
        let dist = dx.hypot(dy);
        let along = (b * b - c * c + dist * dist) / (2.0 * dist);
        let up = (b * b - along * along).sqrt();
        let (ux, uy) = (dx / dist, dy / dist);
        (bx + along * ux - up * uy, by + along * uy + up * ux)
    };
    let dir = scratch("linkage-cli-fn");
    let csv = dir.join("points.csv");
    let mut rows = String::from("input_deg,output_deg\n");
    for t in [40.0f64, 55.0, 70.0] {
        let (cx, cy) = rocker(t.to_radians());
        rows += &format!("{t},{}\n", cy.atan2(cx - d).to_degrees());
    }
    std::fs::write(&csv, rows).expect("csv");
    let out_scene = dir.join("fn.ron");
    let (ok, out, err) = linkage(&[
        "synth",
        "function",
        "--points",
        csv.to_str().expect("path"),
        "--scene-out",
        out_scene.to_str().expect("path"),
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    for (key, want) in [("crank_m", a), ("coupler_m", b), ("rocker_m", c)] {
        let got = v[key].as_f64().expect(key);
        assert!((got - want).abs() < 1e-9, "{key}: {got}");
    }
    assert!(v["error_at_points_deg"].as_f64().expect("error") < 1e-9);
    for t in [40.0f64, 55.0, 70.0] {
        let (ok, at, err) = linkage(&[
            "at",
            out_scene.to_str().expect("path"),
            "--input-deg",
            &t.to_string(),
        ]);
        assert!(ok, "{err}");
        let s: serde_json::Value = serde_json::from_str(&at).expect("json");
        let p = &s["points"]["C"]["position"];
        let (cx, cy) = rocker(t.to_radians());
        let (x, y) = (p[0].as_f64().expect("x"), p[1].as_f64().expect("y"));
        assert!(
            (x - cx).abs() < 1e-9 && (y - cy).abs() < 1e-9,
            "at {t}: ({x}, {y}) vs ({cx}, {cy})"
        );
    }
    // A row that is no pair of numbers is named by its line.
    std::fs::write(&csv, "input_deg,output_deg\n40,10\n55,x\n70,30\n").expect("csv");
    let (ok, _, err) = linkage(&["synth", "function", "--points", csv.to_str().expect("path")]);
    assert!(!ok && err.contains("line 3"), "{err}");
    let _ = std::fs::remove_dir_all(dir);
}

/// `synth motion` through three positions of a body: the scene it writes carries the
/// body's reference point P through them (`linkage at` at the crank angles it gives).
#[test]
fn synth_motion_designs_a_four_bar_through_three_positions() {
    let dir = scratch("linkage-cli-motion");
    let csv = dir.join("poses.csv");
    let poses = [(0.0, 0.0, 0.0), (0.2, 0.1, 20.0), (0.35, 0.3, 45.0)];
    let rows: String = poses
        .iter()
        .map(|(x, y, a)| format!("{x},{y},{a}\n"))
        .collect();
    std::fs::write(&csv, format!("x_m,y_m,angle_deg\n{rows}")).expect("csv");
    let out_scene = dir.join("motion.ron");
    let (ok, out, err) = linkage(&[
        "synth",
        "motion",
        "--poses",
        csv.to_str().expect("path"),
        "--moving",
        "-0.1",
        "-0.15",
        "0.15",
        "-0.1",
        "--scene-out",
        out_scene.to_str().expect("path"),
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    assert!(v["check_miss_m"].as_f64().expect("miss") < 1e-9, "{out}");
    for (i, (x, y, _)) in poses.iter().enumerate() {
        let deg = v["crank_input_deg"][i].as_f64().expect("input");
        let (ok, at, err) = linkage(&[
            "at",
            out_scene.to_str().expect("path"),
            "--input-deg",
            &deg.to_string(),
        ]);
        assert!(ok, "{err}");
        let s: serde_json::Value = serde_json::from_str(&at).expect("json");
        let p = &s["points"]["P"]["position"];
        let (px, py) = (p[0].as_f64().expect("x"), p[1].as_f64().expect("y"));
        assert!(
            (px - x).abs() < 1e-9 && (py - y).abs() < 1e-9,
            "position {i}: ({px}, {py})"
        );
    }
    let (ok, _, err) = linkage(&[
        "synth",
        "motion",
        "--poses",
        csv.to_str().expect("path"),
        "--moving",
        "0",
        "0",
        "0",
        "0",
    ]);
    assert!(!ok && err.contains("one place"), "{err}");
    let _ = std::fs::remove_dir_all(dir);
}

/// An empty folder of this test run named after `name`.
fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a scratch folder");
    dir
}

/// The coupler point of a crank-rocker (A at the origin, D (4, 0.5); crank 1.2,
/// coupler 3.6, rocker 3.0; P at (1.5, 1.1) from B along BC, C left of B→D) at
/// crank angle `deg`, by two circles meeting.
fn known_coupler_point(deg: f64) -> (f64, f64) {
    let t = deg.to_radians();
    let (bx, by) = (1.2 * t.cos(), 1.2 * t.sin());
    let (ex, ey) = (4.0 - bx, 0.5 - by);
    let l2 = ex * ex + ey * ey;
    let along = (3.6f64.powi(2) - 3.0f64.powi(2) + l2) / (2.0 * l2);
    let h = (3.6f64.powi(2) / l2 - along * along).sqrt();
    let (cx, cy) = (bx + ex * along - ey * h, by + ey * along + ex * h);
    let (ux, uy) = ((cx - bx) / 3.6, (cy - by) / 3.6);
    (bx + ux * 1.5 - uy * 1.1, by + uy * 1.5 + ux * 1.1)
}

/// The sweep's P column as points, m (JSON: SI to the last digit).
fn swept_p(scene: &std::path::Path, steps: usize) -> Vec<(f64, f64)> {
    let (ok, json, err) = linkage(&[
        "sweep",
        scene.to_str().expect("path"),
        "--steps",
        &steps.to_string(),
        "--format",
        "json",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).expect("json");
    let header: Vec<String> = serde_json::from_value(v["columns"].clone()).expect("columns");
    let col = |name: &str| header.iter().position(|h| h == name).expect("column");
    let (x, y) = (col("P_x"), col("P_y"));
    let rows: Vec<Vec<f64>> = serde_json::from_value(v["rows"].clone()).expect("rows");
    rows.iter().map(|r| (r[x], r[y])).collect()
}

fn write_targets(
    dir: &std::path::Path,
    name: &str,
    degrees: &[f64],
    timed: bool,
) -> std::path::PathBuf {
    let rows: String = degrees
        .iter()
        .map(|&d| {
            let (x, y) = known_coupler_point(d);
            if timed {
                format!("{x:e},{y:e},{d}\n")
            } else {
                format!("{x:e},{y:e}\n")
            }
        })
        .collect();
    let path = dir.join(name);
    std::fs::write(&path, rows).expect("csv");
    path
}

/// `synth path` with timing: ten targets every 36° of a crank-rocker's coupler
/// curve; the scene it writes, swept by `linkage sweep --steps 10` from its start,
/// puts P on every target (1e-6 of their size), and the run is the same for the
/// same seed.
#[test]
fn synth_path_timed_designs_a_four_bar_that_sweeps_through_the_targets() {
    let dir = scratch("linkage-cli-path");
    let degrees: Vec<f64> = (0..10).map(|k| 10.0 + 36.0 * f64::from(k)).collect();
    let csv = write_targets(&dir, "timed.csv", &degrees, true);
    let scene = dir.join("path.ron");
    let args = [
        "synth",
        "path",
        "--points",
        csv.to_str().expect("path"),
        "--timed",
        "--solutions",
        "1",
        "--tolerance",
        "1e-8",
        "--seed",
        "4",
    ];
    let (ok, out, err) = linkage(&[&args[..], &["--out", scene.to_str().expect("path")]].concat());
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    assert!(
        v["designs"][0]["relative_error"].as_f64().expect("error") <= 1e-8,
        "{out}"
    );
    let swept = swept_p(&scene, 10);
    let size = 2.9949;
    for (&d, &(x, y)) in degrees.iter().zip(&swept) {
        let (tx, ty) = known_coupler_point(d);
        let miss = (x - tx).hypot(y - ty);
        assert!(miss <= 1e-6 * size, "{d}°: misses by {miss}");
    }
    let (_, again, _) = linkage(&args);
    let strip = |s: &str| -> serde_json::Value {
        let mut v: serde_json::Value = serde_json::from_str(s).expect("json");
        v["seconds"] = serde_json::Value::Null;
        v
    };
    assert_eq!(strip(&out), strip(&again), "deterministic for a seed");
    let _ = std::fs::remove_dir_all(dir);
}

/// The largest distance of a target from the coupler curve of `scene` swept by
/// `linkage sweep` (a polyline of 36,000 positions).
fn curve_miss(scene: &std::path::Path, degrees: &[f64]) -> f64 {
    let swept = swept_p(scene, 36_000);
    degrees
        .iter()
        .map(|&d| {
            let (tx, ty) = known_coupler_point(d);
            swept
                .iter()
                .zip(swept.iter().cycle().skip(1))
                .map(|(&(x0, y0), &(x1, y1))| {
                    let (sx, sy) = (x1 - x0, y1 - y0);
                    let len2 = (sx * sx + sy * sy).max(1e-300);
                    let t = (((tx - x0) * sx + (ty - y0) * sy) / len2).clamp(0.0, 1.0);
                    (x0 + t * sx - tx).hypot(y0 + t * sy - ty)
                })
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max)
}

/// `synth path` without timing: ten targets in order, a turning crank asked for; the
/// scene's swept coupler curve passes within 1e-6 of their size of every one, and so
/// do the scenes of the design's two cognates (`--cognate-out`) where the cognate
/// stays on its branch; the JSON lists both with their own class and crank.
#[test]
fn synth_path_untimed_curve_and_its_cognates_pass_through_the_targets() {
    let dir = scratch("linkage-cli-path-u");
    let degrees: Vec<f64> = (0..10).map(|k| 10.0 + 33.0 * f64::from(k)).collect();
    let csv = write_targets(&dir, "untimed.csv", &degrees, false);
    let scene = dir.join("path.ron");
    let cognates = [dir.join("cognate1.ron"), dir.join("cognate2.ron")];
    let (ok, out, err) = linkage(&[
        "synth",
        "path",
        "--points",
        csv.to_str().expect("path"),
        "--crank-turns",
        "--tolerance",
        "1e-8",
        "--out",
        scene.to_str().expect("path"),
        "--cognate-out",
        cognates[0].to_str().expect("path"),
        cognates[1].to_str().expect("path"),
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    let best = &v["designs"][0];
    assert!(best["crank_turns"].as_bool().expect("turns"), "{out}");
    let size = 2.9949;
    let miss = curve_miss(&scene, &degrees);
    assert!(miss <= 1e-6 * size, "the curve misses by {miss}");
    let listed = best["cognates"].as_array().expect("cognates");
    assert_eq!(listed.len(), 2, "{out}");
    assert_eq!(listed[0]["turns_with"], "crank", "{out}");
    let mut checked = 0;
    for (c, file) in listed.iter().zip(&cognates) {
        assert!(
            c["grashof"].is_string() && c["crank_turns"].is_boolean(),
            "{c}"
        );
        if c["min_transmission_deg"].is_number() {
            let miss = curve_miss(file, &degrees);
            assert!(miss <= 1e-6 * size, "{}: misses by {miss}", file.display());
            checked += 1;
        }
    }
    assert!(checked >= 1, "no cognate stays on its branch: {out}");
    let _ = std::fs::remove_dir_all(dir);
}

/// Bad input to `synth path` is refused with its cause and the valid range.
#[test]
fn synth_path_refuses_bad_targets() {
    let dir = scratch("linkage-cli-path-bad");
    let two = dir.join("two.csv");
    std::fs::write(&two, "0,0\n1,1\n").expect("csv");
    let (ok, _, err) = linkage(&["synth", "path", "--points", two.to_str().expect("path")]);
    assert!(!ok && err.contains("3 to 20"), "{err}");
    let untimed = dir.join("untimed.csv");
    std::fs::write(&untimed, "0,0\n1,1\n2,0\n").expect("csv");
    let (ok, _, err) = linkage(&[
        "synth",
        "path",
        "--points",
        untimed.to_str().expect("path"),
        "--timed",
    ]);
    assert!(
        !ok && err.contains("line 1") && err.contains("3 comma-separated"),
        "{err}"
    );
    let (ok, _, err) = linkage(&[
        "synth",
        "path",
        "--points",
        untimed.to_str().expect("path"),
        "--min-transmission-deg",
        "120",
    ]);
    assert!(!ok && err.contains("0 to 90"), "{err}");
    let _ = std::fs::remove_dir_all(dir);
}

/// The coupler of the crank-rocker of [`known_coupler_point`] at crank angle `deg`
/// as a body position: B, and the angle of B→C, deg.
fn known_coupler_pose(deg: f64) -> (f64, f64, f64) {
    let t = deg.to_radians();
    let (bx, by) = (1.2 * t.cos(), 1.2 * t.sin());
    let (px, py) = known_coupler_point(deg);
    // P is (1.5, 1.1) from B in the coupler's frame: the frame's angle from B→P.
    let angle = (py - by).atan2(px - bx) - 1.1f64.atan2(1.5);
    (bx, by, angle.to_degrees())
}

/// `synth motion` through four positions (fixed pivots on the centre-point curve
/// near the known ones) and five (the Burmester points at the known pivots): the
/// general solver moves each design through every position (1e-9).
#[test]
fn synth_motion_through_four_and_five_positions() {
    let dir = scratch("linkage-cli-burmester");
    let write = |name: &str, degrees: &[f64]| {
        let rows: String = degrees
            .iter()
            .map(|&d| {
                let (x, y, a) = known_coupler_pose(d);
                format!("{x:e},{y:e},{a:e}\n")
            })
            .collect();
        let path = dir.join(name);
        std::fs::write(&path, rows).expect("csv");
        path
    };
    let four = write("four.csv", &[20.0, 70.0, 120.0, 170.0]);
    let (ok, out, err) = linkage(&[
        "synth",
        "motion",
        "--poses",
        four.to_str().expect("path"),
        "--fixed-near",
        "0.05",
        "0.03",
        "3.9",
        "0.45",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    assert!(v["check_miss_m"].as_f64().expect("miss") < 1e-9, "{out}");
    let (ok, _, err) = linkage(&["synth", "motion", "--poses", four.to_str().expect("path")]);
    assert!(!ok && err.contains("--fixed-near takes 4 numbers"), "{err}");

    let five = write("five.csv", &[20.0, 70.0, 120.0, 170.0, 230.0]);
    let (ok, _, err) = linkage(&[
        "synth",
        "motion",
        "--poses",
        five.to_str().expect("path"),
        "--pair",
        "9",
        "1",
    ]);
    assert!(!ok && err.contains("Burmester points (1 to"), "{err}");
    // The listing holds the known pivots A (0, 0) and D (4, 0.5).
    let (ok, out, err) = linkage(&[
        "synth",
        "motion",
        "--poses",
        five.to_str().expect("path"),
        "--pair",
        "1",
        "2",
    ]);
    assert!(ok, "{err}");
    let listed: serde_json::Value = serde_json::from_str(&out).expect("json");
    let points = &listed["burmester_points"];
    let index = |x: f64, y: f64| -> Option<usize> {
        points.as_array()?.iter().position(|p| {
            let c = &p["centre"];
            (c[0].as_f64().unwrap_or(f64::NAN) - x).hypot(c[1].as_f64().unwrap_or(f64::NAN) - y)
                < 1e-9
        })
    };
    let (a, d) = (index(0.0, 0.0), index(4.0, 0.5));
    assert!(a.is_some() && d.is_some(), "{out}");
    let pair = [a.map(|i| i + 1), d.map(|i| i + 1)].map(|i| i.unwrap_or(0).to_string());
    let (ok, out, err) = linkage(&[
        "synth",
        "motion",
        "--poses",
        five.to_str().expect("path"),
        "--pair",
        &pair[0],
        &pair[1],
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    assert!(v["check_miss_m"].as_f64().expect("miss") < 1e-9, "{out}");
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn flywheel_gives_its_figures_as_text_csv_and_json_and_refuses_a_bad_delta() {
    let die = scene("die_cutter.ron");
    let (ok, text, err) = linkage(&["flywheel", &die, "--delta", "0.05"]);
    assert!(ok, "{err}");
    for line in [
        "mean torque",
        "mean power",
        "work surplus range",
        "flywheel on crank",
    ] {
        assert!(text.contains(line), "{line}: {text}");
    }
    let (ok, csv, err) = linkage(&["flywheel", &die, "--format", "csv"]);
    assert!(ok, "{err}");
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("angle_rad,torque_n_m,surplus_j,reduced_inertia_kg_m2")
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().expect("number")).collect())
        .collect();
    assert!(rows.len() > 360 && rows.iter().flatten().all(|v| v.is_finite()));
    let (ok, json, err) = linkage(&["flywheel", &die, "--format", "json", "--delta", "0.02"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).expect("json");
    let f = &v["flywheel"];
    let (range, w) = (
        f["work_range_j"].as_f64().expect("range"),
        f["speed_rad_s"].as_f64().expect("w"),
    );
    let jf = f["flywheel_kg_m2"].as_f64().expect("J_F");
    assert!((jf - range / (w * w * 0.02)).abs() <= 1e-12 * jf, "{jf}");
    let (ok, _, err) = linkage(&["flywheel", &die, "--delta", "1.5"]);
    assert!(
        !ok && err.contains("delta = 1.5 is invalid") && err.contains("(0, 1)"),
        "{err}"
    );
}

#[test]
fn simulate_steady_gives_one_periodic_turn_and_refuses_a_scene_without_a_drive() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/examples/");
    let scene = format!("{root}die_cutter_linear_motor.ron");
    let (ok, csv, err) = linkage(&["simulate", &scene, "--steady"]);
    assert!(ok, "{err}");
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("t_s,angle_rad,speed_rad_s"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().expect("number")).collect())
        .collect();
    let (first, last) = (&rows[0], rows.last().expect("rows"));
    assert!(
        (last[1] - first[1] - std::f64::consts::TAU).abs() < 1e-9,
        "one turn"
    );
    assert!((last[2] - first[2]).abs() <= 1e-9 * first[2], "periodic");
    let (ok, json, err) = linkage(&["simulate", &scene, "--steady", "--format", "json"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).expect("json");
    for key in ["max_rad_s", "min_rad_s", "mean_rad_s", "delta", "period_s"] {
        assert!(v["steady_state"][key].is_f64(), "{key}: {json:.200}");
    }
    let (ok, _, err) = linkage(&["simulate", &common::scene("die_cutter.ron"), "--steady"]);
    assert!(!ok && err.contains("drive"), "{err}");
}

#[test]
fn shaking_gives_the_counterweight_and_both_cycles() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/examples/");
    let scene = format!("{root}slider_crank_engine.ron");
    let (ok, text, err) = linkage(&["shaking", &scene]);
    assert!(ok, "{err}");
    assert!(
        text.contains("crank counterweight") && text.contains("rms shaking force"),
        "{text}"
    );
    let (ok, json, err) = linkage(&[
        "shaking", &scene, "--format", "json", "--about", "0.1", "-0.2",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).expect("json");
    assert_eq!(
        v["before"]["shaking"]["about_m"],
        serde_json::json!([0.1, -0.2])
    );
    let (before, after) = (
        v["before"]["shaking"]["rms_force_n"].as_f64().expect("rms"),
        v["after"]["shaking"]["rms_force_n"].as_f64().expect("rms"),
    );
    assert!(after < before, "{after} vs {before}");
    let (ok, csv, err) = linkage(&["shaking", &scene, "--format", "csv"]);
    assert!(ok, "{err}");
    assert!(csv.starts_with("angle_rad,force_x_n,force_y_n,moment_n_m,balanced_force_x_n"));
    assert_eq!(csv.lines().count(), 361);
}

#[test]
fn shaking_balances_a_four_bar_fully_on_its_crank_and_rocker_and_names_a_bad_link() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/examples/");
    let scene = format!("{root}four_bar_masses.ron");
    for aim in ["rms", "peak"] {
        let (ok, json, err) = linkage(&[
            "shaking", &scene, "--on", "crank", "rocker", "--aim", aim, "--format", "json",
        ]);
        assert!(ok, "{err}");
        let v: serde_json::Value = serde_json::from_str(&json).expect("json");
        assert_eq!(v["aim"], aim);
        assert_eq!(v["counterweights"][1]["link_name"], "rocker");
        let before = v["before"]["shaking"]["peak_force_n"]
            .as_f64()
            .expect("peak");
        let after = v["after"]["shaking"]["peak_force_n"]
            .as_f64()
            .expect("peak");
        assert!(after <= 1e-9 * before, "{aim}: {after} of {before}");
    }
    let (ok, _, err) = linkage(&["shaking", &scene, "--on", "coupler"]);
    assert!(
        !ok && err.contains("`coupler` turns about no ground pivot"),
        "{err}"
    );
    let (ok, _, err) = linkage(&["shaking", &scene, "--on", "nope"]);
    assert!(!ok && err.contains("--on nope: no such link"), "{err}");
}
