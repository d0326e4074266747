//! `linkage sweep`: one input cycle (or the assemblable range) as CSV, written row by
//! row as it is solved, or as JSON; the rows next to the input's dead points are
//! named. A failed write is kept apart so that a closed pipe ends quietly.

use std::io::Write;

use linkage::Kinematics;
use linkage::sweep::{csv_header, csv_row};
use serde_json::json;

use crate::args::{Format, SceneArgs};
use crate::error::{CliError, Result};
use crate::io::{check_finite, describe, json_text, load};

/// A CSV writer's failure: a failed write (a closed pipe) is the output's.
fn csv_failure(e: csv::Error) -> CliError {
    if !e.is_io_error() {
        return CliError::Csv(e);
    }
    match e.into_kind() {
        csv::ErrorKind::Io(io) => CliError::Output(io),
        other => CliError::refused(format!("cannot write CSV: {other:?}")),
    }
}

/// Most rows `sweep` writes as CSV (streamed: memory stays flat) and as JSON (held
/// whole: about 1 kB a row).
pub const MAX_CSV_STEPS: usize = 100_000_000;
/// See [`MAX_CSV_STEPS`].
pub const MAX_JSON_STEPS: usize = 100_000;

/// `sweep SCENE --steps N`: the rows written to `out`.
pub(crate) fn sweep(
    args: &SceneArgs,
    steps: usize,
    format: Format,
    out: &mut dyn Write,
) -> Result<()> {
    let most = match format {
        Format::Csv => MAX_CSV_STEPS,
        Format::Json => MAX_JSON_STEPS,
    };
    if steps > most {
        return Err(CliError::refused(format!(
            "--steps {steps} is too many for {} output: at most {most}",
            if format == Format::Csv { "CSV" } else { "JSON" }
        )));
    }
    let mut k = load(args)?;
    let dead_points = dead_points(&k);
    if format == Format::Csv {
        sweep_csv(&mut k, steps, out).map_err(|f| match f {
            CliError::Solver(e) => describe(args, e),
            other => other,
        })?;
        note_dead_points(dead_points, steps);
        return Ok(());
    }
    let sw = linkage::sweep::sweep(&mut k, steps).map_err(|e| describe(args, e))?;
    note_dead_points(dead_points, steps);
    let m = k.mechanism();
    let header = csv_header(m);
    let rows: Vec<Vec<f64>> = sw
        .solutions
        .iter()
        .zip(&sw.angles)
        .map(|(s, a)| csv_row(m, s, a))
        .collect();
    for r in &rows {
        check_finite(r, "sweep")?;
    }
    warn_near_singular(&sw.near_singular);
    let text = json_text(&json!({
            "scene": m.name,
            "solver_path": k.path().label(),
            "input_speed_rad_s": m.driver.speed_rad_s,
            "range_rad": sw.range,
            "near_singular_inputs_rad": sw.near_singular,
            "dead_points_rad": dead_points,
            "rows_next_to_dead_points": dead_points.map_or(Vec::new(), |_| vec![0, steps - 1]),
            "columns": header,
            "rows": rows,
    }))?;
    out.write_all(text.as_bytes())?;
    Ok(())
}

/// The sweep as CSV, each row written as soon as it is solved.
fn sweep_csv(k: &mut Kinematics, steps: usize, out: &mut dyn Write) -> Result<()> {
    let header = csv_header(k.mechanism());
    let mut w = csv::Writer::from_writer(out);
    w.write_record(&header).map_err(csv_failure)?;
    let mut cells: Vec<String> = Vec::with_capacity(header.len());
    let info = linkage::sweep::sweep_each(k, steps, |m, s, angles| -> Result<()> {
        let row = csv_row(m, s, angles);
        check_finite(&row, "sweep")?;
        cells.clear();
        cells.extend(row.iter().map(|v| format!("{v:e}")));
        w.write_record(&cells).map_err(csv_failure)?;
        Ok(())
    })?;
    w.flush()?;
    warn_near_singular(&info.near_singular);
    Ok(())
}

/// The input's dead points where its range ends (a rocker for input), located: the
/// ends of the assembly interval the sweep covers; `None` for a full turn.
fn dead_points(k: &Kinematics) -> Option<[f64; 2]> {
    let ranges = linkage::analysis::assembly_ranges_of(k);
    if ranges.full_rotation {
        return None;
    }
    ranges.containing(k.mechanism().driver.start_rad)
}

/// Says which rows sit next to the input's dead points: the sweep's first and last,
/// a millionth of the range inside them, where the outputs' rates grow without
/// bound (a slider's speed of hundreds of m/s there is the dead point's, not the
/// mechanism's working speed).
fn note_dead_points(dead_points: Option<[f64; 2]>, steps: usize) {
    if let Some([a, b]) = dead_points {
        eprintln!(
            "note: the input's range ends at dead points, {:.4} deg and {:.4} deg; rows 1 and \
             {steps} are a millionth of the range inside them, where the outputs' speeds and \
             accelerations grow without bound",
            a.to_degrees(),
            b.to_degrees()
        );
    }
}

fn warn_near_singular(inputs_rad: &[f64]) {
    for x in inputs_rad {
        eprintln!(
            "warning: near a dead point/tangency at input {:.4} deg (velocities lose digits)",
            x.to_degrees()
        );
    }
}
