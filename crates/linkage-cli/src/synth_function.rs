//! `linkage synth function`: a four-bar function generator through precision points
//! read from a CSV file (input and output angle per row, degrees), by Freudenstein's
//! equation: exact for three points, least squares for more.

use std::path::Path;

use linkage::synthesis::function::{PrecisionPoint, freudenstein, structural_error};
use linkage::synthesis::rows::read_rows;
use serde_json::json;

use crate::error::{CliError, Result};
use crate::io::json_text;

/// Designs the generator through the points in `csv` with ground `ground_m`; writes
/// it as a scene to `scene_out` if given; returns the design as JSON text.
///
/// # Errors
/// An unreadable file or row (named by line), or why no four-bar meets the points.
pub fn run(csv: &Path, ground_m: f64, scene_out: Option<&Path>) -> Result<String> {
    let text = std::fs::read_to_string(csv).map_err(|source| CliError::Read {
        path: csv.to_path_buf(),
        source,
    })?;
    let points = parse(&text).map_err(|e| CliError::in_file(csv, e))?;
    let design = freudenstein(&points, ground_m)?;
    if let Some(path) = scene_out {
        let scene = design.scene(points[0]).to_ron()?;
        std::fs::write(path, scene).map_err(|source| CliError::Write {
            path: path.to_path_buf(),
            source,
        })?;
    }
    let error = structural_error(&design, &points);
    let [a, b, c, d] = design.lengths;
    json_text(&json!({
        "method": if points.len() == 3 { "exact (three precision points)" } else { "least squares" },
        "precision_points": points.len(),
        "k": design.k,
        "crank_m": a.abs(),
        "coupler_m": b,
        "rocker_m": c.abs(),
        "ground_m": d,
        "crank_reversed": a < 0.0,
        "rocker_reversed": c < 0.0,
        "error_at_points_deg": error.map(f64::to_degrees),
    }))
}

/// The rows `input_deg, output_deg` as precision points.
fn parse(text: &str) -> Result<Vec<PrecisionPoint>> {
    Ok(read_rows(text, 2)?
        .into_iter()
        .map(|v| PrecisionPoint {
            input_rad: v[0].to_radians(),
            output_rad: v[1].to_radians(),
        })
        .collect())
}
