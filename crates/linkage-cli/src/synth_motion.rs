//! `linkage synth motion`: a four-bar that carries a body through three positions
//! read from a CSV file (x m, y m, angle deg per row), with moving pivots given in
//! the body's frame; prints the fixed pivots, the poles and the check by the
//! general solver.

use std::path::Path;

use linkage::synthesis::motion::{BodyPose, three_positions};
use serde_json::json;

use crate::commands::json_text;

/// Designs the four-bar through the three positions in `csv` with moving pivots
/// `moving` ([x1, y1, x2, y2], body frame, m); writes its scene to `scene_out` if
/// given; returns the design as JSON text.
///
/// # Errors
/// An unreadable file or row (named by line), not three positions, or why no
/// four-bar meets them with these pivots.
pub fn run(csv: &Path, moving: &[f64], scene_out: Option<&Path>) -> Result<String, String> {
    let text =
        std::fs::read_to_string(csv).map_err(|e| format!("cannot read {}: {e}", csv.display()))?;
    let rows =
        crate::synth_function::rows(&text, 3).map_err(|e| format!("{}: {e}", csv.display()))?;
    let poses: [BodyPose; 3] = rows
        .iter()
        .map(|r| BodyPose {
            at: [r[0], r[1]],
            angle_rad: r[2].to_radians(),
        })
        .collect::<Vec<_>>()
        .try_into()
        .map_err(|v: Vec<BodyPose>| format!("{}: {} positions, not 3", csv.display(), v.len()))?;
    let [x1, y1, x2, y2] = moving else {
        return Err(format!(
            "--moving takes 4 numbers (x1 y1 x2 y2), not {}",
            moving.len()
        ));
    };
    let design = three_positions(poses, [[*x1, *y1], [*x2, *y2]]).map_err(|e| e.to_string())?;
    let checked = design.check().map_err(|e| e.to_string())?;
    if let Some(path) = scene_out {
        let text = checked.scene.to_ron().map_err(|e| e.to_string())?;
        std::fs::write(path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    let inputs: Vec<f64> = (0..3).map(|i| design.input_at(i).to_degrees()).collect();
    json_text(&json!({
        "fixed_pivots_m": design.fixed,
        "moving_pivots_body_m": design.moving,
        "poles_m": design.poles,
        "crank_input_deg": inputs,
        "check_miss_m": checked.miss_m,
        "check_miss_rad": checked.miss_rad,
    }))
}
