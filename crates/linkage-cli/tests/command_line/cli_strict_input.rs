//! What the CLI does with the inputs issue 11's fuzzing run found mishandled: a
//! closed pipe, negative option values, absurd counts, NaN, a full disk. Each test is
//! named after its finding.

use std::io::Read;
use std::process::{Command, Stdio};

use crate::common;

use common::{run_linkage as linkage, scene};

#[test]
fn sweep_into_a_closed_pipe_exits_0_without_a_message() {
    // `linkage sweep SCENE | head -1`: read one line, then close the pipe.
    let mut child = Command::new(env!("CARGO_BIN_EXE_linkage"))
        .args(["sweep", &scene("die_cutter.ron"), "--steps", "200000"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn");
    let mut stdout = child.stdout.take().expect("stdout");
    let mut first = [0u8; 64];
    stdout.read_exact(&mut first).expect("first bytes");
    drop(stdout);
    let out = child.wait_with_output().expect("wait");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "stderr: {stderr}");
    assert!(
        !stderr.contains("panicked") && !stderr.contains("error"),
        "{stderr}"
    );
}

#[test]
fn negative_speed_is_accepted_as_a_separate_value() {
    let (code, out, err) = linkage(&[
        "sweep",
        &scene("slider_crank.ron"),
        "--speed-rad-s",
        "-3.5",
        "--steps",
        "4",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(out.lines().count(), 5);
}

#[test]
fn option_values_minus_inf_minus_0_and_tiny_negatives_are_values_not_flags() {
    for v in ["-0", "-1e-15", "-1"] {
        let (code, _, err) = linkage(&["at", &scene("slider_crank.ron"), "--input-deg", v]);
        assert_eq!(code, Some(0), "--input-deg {v}: {err}");
    }
    let (code, _, err) = linkage(&["at", &scene("slider_crank.ron"), "--input-deg", "-inf"]);
    assert_eq!(code, Some(1));
    assert!(
        err.contains("finite"),
        "named as a value, refused for what it is: {err}"
    );
}

#[test]
fn sweep_steps_18446744073709551615_is_refused_not_a_capacity_overflow() {
    let (code, _, err) = linkage(&[
        "sweep",
        &scene("slider_crank.ron"),
        "--steps",
        "18446744073709551615",
    ]);
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("at most 100000000") && !err.contains("panicked"),
        "{err}"
    );
    let (code, _, err) = linkage(&[
        "sweep",
        &scene("slider_crank.ron"),
        "--steps",
        "10000000",
        "--format",
        "json",
    ]);
    assert_eq!(code, Some(1));
    assert!(err.contains("at most 100000"), "{err}");
}

#[test]
fn simulate_dt_out_1e_minus_9_is_refused_not_grown_in_memory() {
    let (code, _, err) = linkage(&[
        "simulate",
        &scene("gravity_flipper.ron"),
        "--dt-out",
        "1e-9",
    ]);
    assert_eq!(code, Some(1));
    assert!(
        err.contains("output dt") && err.contains("at most"),
        "{err}"
    );
}

#[test]
fn simulate_dt_1e_minus_12_is_refused_at_once() {
    let (code, _, err) = linkage(&[
        "simulate",
        &scene("gravity_flipper.ron"),
        "--method",
        "rk4",
        "--dt",
        "1e-12",
    ]);
    assert_eq!(code, Some(1));
    assert!(err.contains("steps"), "{err}");
}

#[test]
fn synth_die_cutter_rpm_nan_is_refused_instead_of_writing_an_unloadable_scene() {
    let (code, out, err) = linkage(&["synth", "die-cutter", "--rpm", "NaN"]);
    assert_eq!(code, Some(1));
    assert!(out.is_empty() && err.contains("rpm"), "{err}");
}

#[test]
fn writing_to_a_full_disk_is_an_error_not_a_panic() {
    let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") else {
        return; // no /dev/full on this system
    };
    let out = Command::new(env!("CARGO_BIN_EXE_linkage"))
        .args(["sweep", &scene("slider_crank.ron")])
        .stdout(full)
        .output()
        .expect("run");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(
        err.contains("cannot write the output") && !err.contains("panicked"),
        "{err}"
    );
}

/// The CSV (degrees, the scene's millimetres, six significant digits) holds JSON's
/// rows (SI) in those units, row for row.
#[test]
fn sweep_csv_streams_the_same_rows_as_json() {
    let (_, csv, _) = linkage(&["sweep", &scene("quick_return.ron"), "--steps", "37"]);
    let (_, json, _) = linkage(&[
        "sweep",
        &scene("quick_return.ron"),
        "--steps",
        "37",
        "--format",
        "json",
    ]);
    let v: serde_json::Value = serde_json::from_str(&json).expect("json");
    let rows = v["rows"].as_array().expect("rows");
    let columns: Vec<String> = serde_json::from_value(v["columns"].clone()).expect("columns");
    let csv_rows: Vec<Vec<f64>> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|c| c.parse().expect("number")).collect())
        .collect();
    assert_eq!(csv_rows.len(), rows.len());
    for (c, j) in csv_rows.iter().zip(rows) {
        let j: Vec<f64> = serde_json::from_value(j.clone()).expect("row");
        // Each kind of value against the row's largest of that kind: six digits.
        for (i, (a, b)) in c.iter().zip(&j).enumerate() {
            let kind = kind_of(&columns[i]);
            let (si, scale) = match kind {
                "rad" => (b.to_degrees().rem_euclid(360.0), 360.0),
                "theta" => (b.to_degrees(), 360.0),
                "omega" | "alpha" => (*b, largest(&columns, &j, kind)),
                _ => (b * 1e3, largest(&columns, &j, kind) * 1e3),
            };
            assert!(
                (a - si).abs() <= 1e-5 * scale,
                "{}: {a} vs {si}",
                columns[i]
            );
        }
    }
}

/// What a JSON column holds: a point's position, velocity or acceleration (both
/// components), a link's angle, rate or acceleration, or the input.
fn kind_of(column: &str) -> &str {
    match column.rsplit('_').next().unwrap_or_default() {
        "x" | "y" => "position",
        "vx" | "vy" => "velocity",
        "ax" | "ay" => "acceleration",
        other => other,
    }
}

/// The largest magnitude in `row` of the columns of `kind`, a point's two
/// components taken together: a table's round-off is relative to it.
fn largest(columns: &[String], row: &[f64], kind: &str) -> f64 {
    let most = columns
        .iter()
        .zip(row)
        .filter(|(c, _)| kind_of(c) == kind)
        .fold(0.0_f64, |most, (_, v)| most.max(v.abs()));
    most * std::f64::consts::SQRT_2
}
