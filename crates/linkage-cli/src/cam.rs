//! `linkage cam FILE`: a disc cam from its file (RON): the program's s, v, a and
//! jerk at the cam's speed, the pitch and profile points, the pressure angle and the
//! radii of curvature over the turn, as CSV, or as JSON with the joins' continuity,
//! each law's peak coefficients and the cam's extremes; and the profile as DXF for
//! manufacture (`--dxf`).

use std::path::Path;

use linkage::cam::{
    CAM_TABLE_HEADER, CamDesign, CamPoint, CamSpec, Law, SegmentKind, cam_table_row,
    peak_coefficients,
};
use serde_json::json;

use crate::args::CamFormat;
use crate::error::{CliError, Result};
use crate::io::{json_text, to_csv};

/// The pressure-angle limit the sheet marks: 30 deg for a translating follower, 45
/// for an arm, as for a cam joint.
fn pressure_limit(d: &CamDesign) -> f64 {
    match d.cam.follower {
        linkage::cam::Follower::Translating { .. } => 30f64.to_radians(),
        linkage::cam::Follower::Oscillating { .. } => 45f64.to_radians(),
    }
}

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

/// Runs the command; `[dxf, svg]` are where the profile's files go, if asked.
pub fn run(
    path: &Path,
    samples: usize,
    format: CamFormat,
    [dxf, svg]: [Option<&Path>; 2],
    lang: linkage_diagram::words::Lang,
) -> Result<String> {
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
    if let Some(out) = svg {
        let sheet = linkage_diagram::svg_cam::cam_sheet(
            &linkage_diagram::svg_cam::CamSheet {
                title: &d.name,
                points: &points,
                base_radius_m: d.cam.base_radius_m,
                pressure_limit_rad: pressure_limit(&d),
            },
            lang,
        );
        // The cam sheet is one page.
        std::fs::write(out, sheet.first_page()).map_err(|source| CliError::Write {
            path: out.to_path_buf(),
            source,
        })?;
    }
    match format {
        CamFormat::Csv => rows_csv(&d, &points),
        CamFormat::Json => figures_json(&d, &points),
    }
}

#[cfg(not(target_arch = "wasm32"))]
fn write_dxf(out: &Path, d: &CamDesign, points: &[CamPoint]) -> Result<()> {
    let profile: Vec<[f64; 2]> = points.iter().map(|p| p.profile_m).collect();
    let pitch: Vec<[f64; 2]> = points.iter().map(|p| p.pitch_m).collect();
    let write_error = |e: String| CliError::Write {
        path: out.to_path_buf(),
        source: std::io::Error::other(e),
    };
    let bytes = linkage_diagram::cam_dxf::cam_dxf(&profile, &pitch, d.cam.base_radius_m)
        .map_err(|e| write_error(e.to_string()))?;
    std::fs::write(out, bytes).map_err(|e| write_error(e.to_string()))
}

/// The CLI is only type-checked for wasm32, where the DXF crate does not build.
#[cfg(target_arch = "wasm32")]
fn write_dxf(_: &Path, _: &CamDesign, _: &[CamPoint]) -> Result<()> {
    Err(CliError::refused(
        "--dxf is not available in a wasm32 build".to_string(),
    ))
}

/// A row: the follower's motion at the cam's speed and the cam's points and figures.
fn row(d: &CamDesign, p: &CamPoint) -> Vec<f64> {
    cam_table_row(p, d.speed_rad_s).to_vec()
}

fn rows_csv(d: &CamDesign, points: &[CamPoint]) -> Result<String> {
    let header: Vec<String> = CAM_TABLE_HEADER.iter().map(|h| h.to_string()).collect();
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
                CAM_TABLE_HEADER
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
