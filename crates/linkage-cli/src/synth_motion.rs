//! `linkage synth motion`: a four-bar that carries a body through three, four or
//! five positions read from a CSV file (x m, y m, angle deg per row). Three: moving
//! pivots given in the body's frame; four: fixed pivots taken on the centre-point
//! curve near given points; five: two of the Burmester points. Prints the pivots,
//! the poles, the Burmester points (five) and the check by the general solver.

use std::path::Path;

use linkage::synthesis::burmester::{burmester_points, four_bar_of, four_positions};
use linkage::synthesis::motion::{BodyPose, MotionFourBar, three_positions};
use serde_json::json;

use crate::commands::json_text;

/// The choice that fixes the four-bar, per number of positions.
pub struct Choice {
    /// Three positions: moving pivots x1 y1 x2 y2 (body frame, m).
    pub moving: Vec<f64>,
    /// Four positions: points x1 y1 x2 y2 near the fixed pivots (m).
    pub fixed_near: Vec<f64>,
    /// Five positions: two Burmester points, from 1.
    pub pair: Vec<usize>,
}

/// Designs the four-bar through the positions in `csv` as `choice` says; writes
/// its scene to `scene_out` if given; returns the design as JSON text.
///
/// # Errors
/// An unreadable file or row (named by line), not three to five positions, a
/// choice missing or out of range, or why no four-bar meets the positions so.
pub fn run(csv: &Path, choice: &Choice, scene_out: Option<&Path>) -> Result<String, String> {
    let text =
        std::fs::read_to_string(csv).map_err(|e| format!("cannot read {}: {e}", csv.display()))?;
    let rows =
        crate::synth_function::rows(&text, 3).map_err(|e| format!("{}: {e}", csv.display()))?;
    let poses: Vec<BodyPose> = rows
        .iter()
        .map(|r| BodyPose {
            at: [r[0], r[1]],
            angle_rad: r[2].to_radians(),
        })
        .collect();
    let mut burmester = None;
    let design = match poses.len() {
        3 => three(&poses, &choice.moving)?,
        4 => {
            let [x1, y1, x2, y2] = four_numbers(&choice.fixed_near, "--fixed-near")?;
            four_positions(&poses, [[x1, y1], [x2, y2]]).map_err(|e| e.to_string())?
        }
        5 => {
            let points = burmester_points(&poses).map_err(|e| e.to_string())?;
            let pick = |k: usize| {
                let i = choice.pair.get(k).copied().unwrap_or(k + 1);
                points.get(i.wrapping_sub(1)).copied().ok_or_else(|| {
                    format!(
                        "--pair {i}: there are {} Burmester points (1 to {})",
                        points.len(),
                        points.len()
                    )
                })
            };
            let cranks = [pick(0)?, pick(1)?];
            burmester = Some(points);
            four_bar_of(&poses, cranks).map_err(|e| e.to_string())?
        }
        n => {
            return Err(format!(
                "{}: {n} positions; 3, 4 or 5 are needed",
                csv.display()
            ));
        }
    };
    let checked = design.check().map_err(|e| e.to_string())?;
    if let Some(path) = scene_out {
        let text = checked.scene.to_ron().map_err(|e| e.to_string())?;
        std::fs::write(path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    let inputs: Vec<f64> = (0..poses.len())
        .map(|i| design.input_at(i).to_degrees())
        .collect();
    json_text(&json!({
        "positions": poses.len(),
        "fixed_pivots_m": design.fixed,
        "moving_pivots_body_m": design.moving,
        "poles_m": design.poles,
        "burmester_points": burmester,
        "crank_input_deg": inputs,
        "check_miss_m": checked.miss_m,
        "check_miss_rad": checked.miss_rad,
    }))
}

fn four_numbers(v: &[f64], flag: &str) -> Result<[f64; 4], String> {
    v.try_into()
        .map_err(|_| format!("{flag} takes 4 numbers (x1 y1 x2 y2), not {}", v.len()))
}

fn three(poses: &[BodyPose], moving: &[f64]) -> Result<MotionFourBar, String> {
    let [x1, y1, x2, y2] = four_numbers(moving, "--moving")?;
    let three: [BodyPose; 3] = [poses[0], poses[1], poses[2]];
    three_positions(three, [[x1, y1], [x2, y2]]).map_err(|e| e.to_string())
}
