//! `linkage sweep`: one input cycle (or the assemblable range) as CSV, written row by
//! row as it is solved, or as JSON; the rows next to the input's dead points are
//! named. A failed write is kept apart so that a closed pipe ends quietly.

use std::io::Write;

use linkage::Kinematics;
use linkage::sweep::{Grid, csv_header, csv_row, sweep_each_on, sweep_range};
use linkage_diagram::cycle_table::{self, CycleTable, DEFAULT_STEP_DEG};
use serde_json::json;

use crate::args::{Format, SceneArgs};
use crate::error::{CliError, Result};
use crate::io::{check_finite, describe, json_text, length_unit, load};

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
/// JSON's rows unless asked otherwise: a degree apart on a full turn.
const JSON_STEPS: usize = 360;

/// Where the sweep's rows lie.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Rows {
    /// So many positions, evenly spaced over the input's range (`--steps`).
    Steps(usize),
    /// The whole multiples of a step in degrees (`--step-deg`).
    EveryDeg(f64),
}

impl Rows {
    /// The rows asked for: CSV on whole degrees unless told, JSON on 360 steps.
    pub(crate) fn new(steps: Option<usize>, step_deg: Option<f64>, format: Format) -> Self {
        match (steps, step_deg, format) {
            (Some(n), _, _) => Self::Steps(n),
            (None, Some(d), _) => Self::EveryDeg(d),
            (None, None, Format::Csv) => Self::EveryDeg(DEFAULT_STEP_DEG),
            (None, None, Format::Json) => Self::Steps(JSON_STEPS),
        }
    }

    /// The inputs these rows lie at for `k`.
    fn grid(self, k: &Kinematics) -> std::result::Result<Grid, linkage::LinkageError> {
        match self {
            Self::Steps(n) => {
                let (range, full) = sweep_range(k)?;
                Ok(Grid::even(range, full, n))
            }
            Self::EveryDeg(d) => cycle_table::grid(k, d),
        }
    }
}

/// `sweep SCENE`: the rows written to `out`.
pub(crate) fn sweep(
    args: &SceneArgs,
    rows: Rows,
    format: Format,
    out: &mut dyn Write,
) -> Result<()> {
    let most = match format {
        Format::Csv => MAX_CSV_STEPS,
        Format::Json => MAX_JSON_STEPS,
    };
    if let Rows::Steps(steps) = rows
        && steps > most
    {
        return Err(CliError::refused(format!(
            "--steps {steps} is too many for {} output: at most {most}",
            if format == Format::Csv { "CSV" } else { "JSON" }
        )));
    }
    let mut k = load(args)?;
    let grid = rows.grid(&k).map_err(|e| describe(args, e))?;
    let dead_points = dead_points(&k);
    if format == Format::Csv {
        let table = CycleTable::new(length_unit(args)?);
        sweep_csv(&mut k, grid, table, out).map_err(|f| match f {
            CliError::Solver(e) => describe(args, e),
            other => other,
        })?;
        note_dead_points(dead_points, rows);
        return Ok(());
    }
    let m = k.mechanism().clone();
    let mut table: Vec<Vec<f64>> = Vec::with_capacity(grid.count());
    let info = sweep_each_on(&mut k, grid, |m, s, a| -> Result<()> {
        let row = csv_row(m, s, a);
        check_finite(&row, "sweep")?;
        table.push(row);
        Ok(())
    })
    .map_err(|f| match f {
        CliError::Solver(e) => describe(args, e),
        other => other,
    })?;
    note_dead_points(dead_points, rows);
    warn_near_singular(&info.near_singular);
    let next_to_dead_points = match (dead_points, rows) {
        (Some(_), Rows::Steps(n)) => vec![0, n - 1],
        _ => Vec::new(),
    };
    let text = json_text(&json!({
            "scene": m.name,
            "solver_path": k.path().label(),
            "input_speed_rad_s": m.driver.speed_rad_s,
            "range_rad": info.range,
            "near_singular_inputs_rad": info.near_singular,
            "dead_points_rad": dead_points,
            "rows_next_to_dead_points": next_to_dead_points,
            "columns": csv_header(&m),
            "rows": table,
    }))?;
    out.write_all(text.as_bytes())?;
    Ok(())
}

/// The sweep as CSV in the table a report takes ([`CycleTable`]), each row written
/// as soon as it is solved.
fn sweep_csv(k: &mut Kinematics, grid: Grid, table: CycleTable, out: &mut dyn Write) -> Result<()> {
    let mut w = csv::Writer::from_writer(out);
    w.write_record(table.header(k.mechanism()))
        .map_err(csv_failure)?;
    let info = sweep_each_on(k, grid, |m, s, angles| -> Result<()> {
        check_finite(&csv_row(m, s, angles), "sweep")?;
        w.write_record(table.row(m, s, angles))
            .map_err(csv_failure)?;
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

/// Says where the input's dead points are and which rows sit next to them: with
/// `--steps`, the sweep's first and last, a millionth of the range inside them,
/// where the outputs' rates grow without bound (a slider's speed of hundreds of m/s
/// there is the dead point's, not the mechanism's working speed); on whole
/// multiples of a step, the rows lie between them.
fn note_dead_points(dead_points: Option<[f64; 2]>, rows: Rows) {
    let Some([a, b]) = dead_points else {
        return;
    };
    let (a, b) = (a.to_degrees(), b.to_degrees());
    match rows {
        Rows::Steps(steps) => eprintln!(
            "note: the input's range ends at dead points, {a:.4} deg and {b:.4} deg; rows 1 and \
             {steps} are a millionth of the range inside them, where the outputs' speeds and \
             accelerations grow without bound"
        ),
        Rows::EveryDeg(step) => eprintln!(
            "note: the input's range ends at dead points, {a:.4} deg and {b:.4} deg; the rows are \
             the multiples of {step} deg between them (the outputs' speeds and accelerations \
             grow without bound towards the dead points)"
        ),
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
