//! `linkage synth function`: a four-bar function generator through precision points
//! read from a CSV file (input and output angle per row, degrees), by Freudenstein's
//! equation: exact for three points, least squares for more.

use std::path::Path;

use linkage::synthesis::function::{PrecisionPoint, freudenstein, structural_error};
use serde_json::json;

use crate::commands::json_text;

/// Designs the generator through the points in `csv` with ground `ground_m`; writes
/// it as a scene to `scene_out` if given; returns the design as JSON text.
///
/// # Errors
/// An unreadable file or row (named by line), or why no four-bar meets the points.
pub fn run(csv: &Path, ground_m: f64, scene_out: Option<&Path>) -> Result<String, String> {
    let text =
        std::fs::read_to_string(csv).map_err(|e| format!("cannot read {}: {e}", csv.display()))?;
    let points = parse(&text).map_err(|e| format!("{}: {e}", csv.display()))?;
    let design = freudenstein(&points, ground_m).map_err(|e| e.to_string())?;
    if let Some(path) = scene_out {
        let scene = design
            .scene(points[0])
            .to_ron()
            .map_err(|e| e.to_string())?;
        std::fs::write(path, scene).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
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
fn parse(text: &str) -> Result<Vec<PrecisionPoint>, String> {
    Ok(rows(text, 2)?
        .into_iter()
        .map(|v| PrecisionPoint {
            input_rad: v[0].to_radians(),
            output_rad: v[1].to_radians(),
        })
        .collect())
}

/// The rows of `width` numbers; blank lines, `#` comments and a header line (a first
/// row that is not numbers) are skipped.
///
/// # Errors
/// A row that is not `width` numbers, named by its line.
pub fn rows(text: &str, width: usize) -> Result<Vec<Vec<f64>>, String> {
    let mut out = Vec::new();
    let header = first_row(text);
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let numbers: Result<Vec<f64>, _> = line.split(',').map(|c| c.trim().parse()).collect();
        match numbers {
            Ok(v) if v.len() == width && v.iter().all(|x| x.is_finite()) => out.push(v),
            Err(_) if i == header => {} // a header
            _ => {
                return Err(format!(
                    "line {}: {line:?} is not {width} comma-separated numbers",
                    i + 1
                ));
            }
        }
    }
    Ok(out)
}

/// The index of the first line that is neither blank nor a comment.
fn first_row(text: &str) -> usize {
    text.lines()
        .position(|l| !(l.trim().is_empty() || l.trim().starts_with('#')))
        .unwrap_or(0)
}
