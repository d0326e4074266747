//! `linkage synth motion`: a four-bar that carries a body through three, four or
//! five positions read from a CSV file (x m, y m, angle deg per row). Three: moving
//! pivots given in the body's frame; four: fixed pivots taken on the centre-point
//! curve near given points; five: two of the Burmester points. Prints the pivots,
//! the poles, the Burmester points (five) and the check by the general solver.

use std::path::Path;

use linkage::synthesis::motion::BodyPose;
use linkage::synthesis::positions::{
    PositionsChoice, PositionsDesign, PositionsError, through_positions,
};
use linkage::synthesis::rows::read_rows;
use serde_json::json;

use crate::error::{CliError, Result};
use crate::io::json_text;

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
pub fn run(csv: &Path, choice: &Choice, scene_out: Option<&Path>) -> Result<String> {
    let text = std::fs::read_to_string(csv).map_err(|source| CliError::Read {
        path: csv.to_path_buf(),
        source,
    })?;
    let rows = read_rows(&text, 3).map_err(|e| CliError::in_file(csv, e))?;
    let poses: Vec<BodyPose> = rows
        .iter()
        .map(|r| BodyPose {
            at: [r[0], r[1]],
            angle_rad: r[2].to_radians(),
        })
        .collect();
    // A choice is read only where the number of positions uses it.
    let pivots = |v: &[f64], flag: &str, used: bool| -> Result<Option<[[f64; 2]; 2]>> {
        used.then(|| four_numbers(v, flag).map(|[x1, y1, x2, y2]| [[x1, y1], [x2, y2]]))
            .transpose()
    };
    let pair = |k: usize| choice.pair.get(k).copied().unwrap_or(k + 1);
    let positions = PositionsChoice {
        moving: pivots(&choice.moving, "--moving", poses.len() == 3)?,
        fixed_near: pivots(&choice.fixed_near, "--fixed-near", poses.len() == 4)?,
        burmester_pair: [pair(0), pair(1)],
    };
    let PositionsDesign {
        four_bar: design,
        burmester,
    } = through_positions(&poses, &positions).map_err(|e| match e {
        PositionsError::Count(n) => CliError::refused(format!(
            "{}: {n} positions; 3, 4 or 5 are needed",
            csv.display()
        )),
        PositionsError::NoSuchBurmesterPoint { asked, count } => CliError::refused(format!(
            "--pair {asked}: there are {count} Burmester points (1 to {count})"
        )),
        PositionsError::Method(e) => CliError::Solver(e),
        other => CliError::refused(other.to_string()),
    })?;
    let checked = design.check()?;
    if let Some(path) = scene_out {
        let text = checked.scene.to_ron()?;
        std::fs::write(path, text).map_err(|source| CliError::Write {
            path: path.to_path_buf(),
            source,
        })?;
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

fn four_numbers(v: &[f64], flag: &str) -> Result<[f64; 4]> {
    v.try_into().map_err(|_| {
        CliError::refused(format!(
            "{flag} takes 4 numbers (x1 y1 x2 y2), not {}",
            v.len()
        ))
    })
}
