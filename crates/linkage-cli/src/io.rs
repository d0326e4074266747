//! What every command shares: the scene it names, loaded with the command line's
//! solver path and branches, the solver's errors worded with the scene's file, and
//! the output written as CSV or JSON text.

use linkage::scene::{Branch, SolverPath};
use linkage::{Kinematics, Mechanism};
use serde_json::Value;

use crate::args::{PathArg, SceneArgs};
use crate::error::{CliError, Result};

/// The scene `args` names, with their branches and speed, ready to solve.
/// The scene file's length unit (what its lengths are written in).
pub(crate) fn length_unit(args: &SceneArgs) -> Result<linkage::scene::LengthUnit> {
    let text = std::fs::read_to_string(&args.scene).map_err(|source| CliError::ReadScene {
        path: args.scene.clone(),
        source,
    })?;
    let scene = linkage::SceneFile::parse(&text).map_err(|e| CliError::in_file(&args.scene, e))?;
    Ok(scene.length_unit)
}

pub(crate) fn load(args: &SceneArgs) -> Result<Kinematics> {
    let text = std::fs::read_to_string(&args.scene).map_err(|source| CliError::ReadScene {
        path: args.scene.clone(),
        source,
    })?;
    let mut mech = Mechanism::from_ron(&text).map_err(|e| CliError::in_file(&args.scene, e))?;
    if let Some(spec) = &args.branch {
        apply_branches(&mut mech, spec)?;
    }
    if let Some(w) = args.speed_rad_s {
        if !w.is_finite() {
            return Err(CliError::refused(format!(
                "--speed-rad-s {w} is invalid: must be a finite number"
            )));
        }
        mech.driver.speed_rad_s = w;
    }
    let path = match args.path {
        PathArg::Auto => mech.solver.path,
        PathArg::ClosedForm => SolverPath::ClosedForm,
        PathArg::Newton => SolverPath::Newton,
    };
    Ok(Kinematics::with_path(mech, path)?)
}

/// `C=left,E=flip`: sides keep the end joints the scene names.
fn apply_branches(mech: &mut Mechanism, spec: &str) -> Result<()> {
    for item in spec.split(',').filter(|s| !s.is_empty()) {
        let (point, side) = item.split_once('=').ok_or_else(|| {
            CliError::refused(format!(
                "--branch `{item}`: expected POINT=left|right|along|against|flip"
            ))
        })?;
        let current = mech
            .point_index(point)
            .and_then(|p| mech.branch_for(p).cloned());
        let ends = match &current {
            Some(Branch::Left(f, t) | Branch::Right(f, t)) => Some((f.clone(), t.clone())),
            _ => None,
        };
        let branch = match (side.to_ascii_lowercase().as_str(), ends) {
            ("flip", _) => current.map(|b| b.flipped()).ok_or_else(|| {
                CliError::refused(format!(
                    "--branch {point}=flip: the scene gives no branch at `{point}`"
                ))
            })?,
            ("along", _) => Branch::Along,
            ("against", _) => Branch::Against,
            ("left", Some((f, t))) => Branch::Left(f, t),
            ("right", Some((f, t))) => Branch::Right(f, t),
            ("left" | "right", None) => {
                return Err(CliError::refused(format!(
                    "--branch {point}={side}: the scene has no Left/Right branch at `{point}` to reuse its end joints"
                )));
            }
            _ => {
                return Err(CliError::refused(format!(
                    "--branch `{item}`: side must be left, right, along, against or flip"
                )));
            }
        };
        mech.set_branch(point, branch)?;
    }
    Ok(())
}

/// The solver's error in the words of this command line: an input speed that
/// overflows is named by where it came from (`--speed-rad-s`, or the scene's driver).
pub(crate) fn describe(args: &SceneArgs, e: linkage::LinkageError) -> CliError {
    match e {
        linkage::LinkageError::SpeedOverflow {
            speed_rad_s,
            most_rad_s,
        } => CliError::SpeedOverflow {
            from_option: args.speed_rad_s.is_some(),
            speed_rad_s,
            most_rad_s,
        },
        e => CliError::Solver(e),
    }
}

/// `Ok` when every value is finite; else the first that is not, by its column.
pub(crate) fn check_finite(values: &[f64], what: &str) -> Result<()> {
    match values.iter().position(|v| !v.is_finite()) {
        Some(column) => Err(CliError::NonFinite {
            what: what.to_string(),
            column,
        }),
        None => Ok(()),
    }
}

/// CSV of numbers, each written as `{:e}`.
pub(crate) fn to_csv(header: &[String], rows: &[Vec<f64>]) -> Result<String> {
    let text: Vec<Vec<String>> = rows
        .iter()
        .map(|r| r.iter().map(|v| format!("{v:e}")).collect())
        .collect();
    records_to_csv(header, &text)
}

/// CSV of text records (for tables that mix names and numbers).
pub(crate) fn records_to_csv(header: &[String], rows: &[Vec<String>]) -> Result<String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(header)?;
    for r in rows {
        w.write_record(r)?;
    }
    let bytes = w
        .into_inner()
        .map_err(|e| CliError::Output(e.into_error()))?;
    // The records are Rust strings, so their CSV is UTF-8.
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}

/// Pretty JSON with a final newline.
pub(crate) fn json_text(v: &Value) -> Result<String> {
    Ok(serde_json::to_string_pretty(v)? + "\n")
}
