//! `linkage cam FILE`: a disc cam from its file (RON): the program's s, v, a and
//! jerk at the cam's speed, the pitch and profile points, the pressure angle and the
//! radii of curvature over the turn, as CSV, or as JSON with the joins' continuity,
//! each law's peak coefficients and the cam's extremes; and the profile as DXF for
//! manufacture (`--dxf`).

use std::path::Path;

use linkage::cam::{CamDesign, CamPoint, CamSpec, Law, SegmentKind, peak_coefficients};
use serde_json::json;

use crate::args::CamFormat;
use crate::error::{CliError, Result};
use crate::io::{json_text, to_csv};

/// Reads the cam file at `path`.
fn design(path: &Path) -> Result<CamDesign> {
    let text = std::fs::read_to_string(path).map_err(|source| CliError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    CamSpec::from_ron(&text)
        .and_then(|spec| spec.design())
        .map_err(|e| CliError::in_file(path, e))
}

/// The turn sampled at `samples` cam angles.
fn sampled(d: &CamDesign, samples: usize) -> Vec<CamPoint> {
    (0..samples)
        .map(|i| d.cam.at(std::f64::consts::TAU * i as f64 / samples as f64))
        .collect()
}

/// Runs the command.
pub fn run(path: &Path, samples: usize, format: CamFormat, dxf: Option<&Path>) -> Result<String> {
    if !(4..=1_000_000).contains(&samples) {
        return Err(CliError::refused(format!(
            "--samples {samples} is out of range: 4 to 1000000"
        )));
    }
    let d = design(path)?;
    let points = sampled(&d, samples);
    if let Some(out) = dxf {
        write_dxf(out, &d, &points)?;
    }
    match format {
        CamFormat::Csv => rows_csv(&d, &points),
        CamFormat::Json => figures_json(&d, &points),
    }
}

#[cfg(not(target_arch = "wasm32"))]
fn write_dxf(out: &Path, d: &CamDesign, points: &[CamPoint]) -> Result<()> {
    crate::cam_dxf::write(out, d, points)
}

/// The CLI is only type-checked for wasm32, where the DXF crate does not build.
#[cfg(target_arch = "wasm32")]
fn write_dxf(_: &Path, _: &CamDesign, _: &[CamPoint]) -> Result<()> {
    Err(CliError::refused(
        "--dxf is not available in a wasm32 build".to_string(),
    ))
}

const HEADER: [&str; 12] = [
    "angle_deg",
    "s",
    "v",
    "a",
    "jerk",
    "pitch_x_m",
    "pitch_y_m",
    "profile_x_m",
    "profile_y_m",
    "pressure_angle_deg",
    "pitch_radius_m",
    "profile_radius_m",
];

/// A row: the follower's motion at the cam's speed (SI; rad for an oscillating
/// follower), the points and the figures.
fn row(d: &CamDesign, p: &CamPoint) -> Vec<f64> {
    let w = d.speed_rad_s;
    let m = &p.motion;
    vec![
        p.angle_rad.to_degrees(),
        m.s,
        m.v * w,
        m.a * w * w,
        m.j * w * w * w,
        p.pitch_m[0],
        p.pitch_m[1],
        p.profile_m[0],
        p.profile_m[1],
        p.pressure_angle_rad.to_degrees(),
        p.pitch_radius_m,
        p.profile_radius_m,
    ]
}

fn rows_csv(d: &CamDesign, points: &[CamPoint]) -> Result<String> {
    let header: Vec<String> = HEADER.iter().map(|h| h.to_string()).collect();
    let rows: Vec<Vec<f64>> = points.iter().map(|p| row(d, p)).collect();
    to_csv(&header, &rows)
}

fn figures_json(d: &CamDesign, points: &[CamPoint]) -> Result<String> {
    let laws: Vec<Law> = d
        .cam
        .program
        .segments()
        .iter()
        .filter_map(|s| match s.kind {
            SegmentKind::Rise { law, .. } | SegmentKind::Return { law, .. } => Some(law),
            SegmentKind::Dwell => None,
        })
        .collect();
    let peaks: Vec<serde_json::Value> = laws
        .iter()
        .map(|&law| json!({"law": law, "coefficients": peak_coefficients(law)}))
        .collect();
    let rows: Vec<serde_json::Value> = points
        .iter()
        .map(|p| {
            let r = row(d, p);
            serde_json::Value::Object(
                HEADER
                    .iter()
                    .zip(r)
                    .map(|(h, v)| (h.to_string(), json!(v)))
                    .collect(),
            )
        })
        .collect();
    json_text(&json!({
        "name": d.name,
        "speed_rad_s": d.speed_rad_s,
        "joins": d.cam.program.joins(),
        "peak_coefficients": peaks,
        "extremes": d.cam.extremes(),
        "rows": rows,
    }))
}
