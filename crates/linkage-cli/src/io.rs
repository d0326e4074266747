//! What every command shares: the scene it names, loaded with the command line's
//! solver path and branches, the solver's errors worded with the scene's file, and
//! the output written as CSV or JSON text.

use linkage::scene::{Branch, SolverPath};
use linkage::{Kinematics, Mechanism};
use serde_json::Value;

use crate::args::{PathArg, SceneArgs};

pub(crate) fn load(args: &SceneArgs) -> Result<Kinematics, String> {
    let text = std::fs::read_to_string(&args.scene)
        .map_err(|e| format!("cannot read scene {}: {e}", args.scene.display()))?;
    let mut mech =
        Mechanism::from_ron(&text).map_err(|e| format!("{}: {e}", args.scene.display()))?;
    if let Some(spec) = &args.branch {
        apply_branches(&mut mech, spec)?;
    }
    if let Some(w) = args.speed_rad_s {
        if !w.is_finite() {
            return Err(format!(
                "--speed-rad-s {w} is invalid: must be a finite number"
            ));
        }
        mech.driver.speed_rad_s = w;
    }
    let path = match args.path {
        PathArg::Auto => mech.solver.path,
        PathArg::ClosedForm => SolverPath::ClosedForm,
        PathArg::Newton => SolverPath::Newton,
    };
    Kinematics::with_path(mech, path).map_err(|e| e.to_string())
}

/// `C=left,E=flip`: sides keep the end joints the scene names.
fn apply_branches(mech: &mut Mechanism, spec: &str) -> Result<(), String> {
    for item in spec.split(',').filter(|s| !s.is_empty()) {
        let (point, side) = item.split_once('=').ok_or_else(|| {
            format!("--branch `{item}`: expected POINT=left|right|along|against|flip")
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
                format!("--branch {point}=flip: the scene gives no branch at `{point}`")
            })?,
            ("along", _) => Branch::Along,
            ("against", _) => Branch::Against,
            ("left", Some((f, t))) => Branch::Left(f, t),
            ("right", Some((f, t))) => Branch::Right(f, t),
            ("left" | "right", None) => {
                return Err(format!(
                    "--branch {point}={side}: the scene has no Left/Right branch at `{point}` to reuse its end joints"
                ));
            }
            _ => {
                return Err(format!(
                    "--branch `{item}`: side must be left, right, along, against or flip"
                ));
            }
        };
        mech.set_branch(point, branch).map_err(|e| e.to_string())?;
    }
    Ok(())
}

/// The solver's error in the words of this command line: an input speed that
/// overflows is named by where it came from (`--speed-rad-s`, or the scene's driver).
pub(crate) fn describe(args: &SceneArgs, e: linkage::LinkageError) -> String {
    let linkage::LinkageError::SpeedOverflow {
        speed_rad_s,
        most_rad_s,
    } = e
    else {
        return e.to_string();
    };
    let rpm = |w: f64| w * 60.0 / std::f64::consts::TAU;
    match args.speed_rad_s {
        Some(_) => format!(
            "--speed-rad-s {speed_rad_s:e} makes velocities or accelerations overflow: give at most {most_rad_s:.1e} rad/s"
        ),
        None => format!(
            "the scene's driver speed ({speed_rad_s:e} rad/s, {:e} rpm) makes velocities or accelerations overflow: at most {most_rad_s:.1e} rad/s ({:.1e} rpm), or give --speed-rad-s",
            rpm(speed_rad_s),
            rpm(most_rad_s)
        ),
    }
}

pub(crate) fn check_finite(values: &[f64], what: &str) -> Result<(), String> {
    match values.iter().position(|v| !v.is_finite()) {
        Some(i) => Err(format!(
            "non-finite value in {what} (column {i}); refusing to print it"
        )),
        None => Ok(()),
    }
}

pub(crate) fn to_csv(header: &[String], rows: &[Vec<f64>]) -> Result<String, String> {
    let text: Vec<Vec<String>> = rows
        .iter()
        .map(|r| r.iter().map(|v| format!("{v:e}")).collect())
        .collect();
    records_to_csv(header, &text)
}

/// CSV of text records (for tables that mix names and numbers).
pub(crate) fn records_to_csv(header: &[String], rows: &[Vec<String>]) -> Result<String, String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(header).map_err(|e| e.to_string())?;
    for r in rows {
        w.write_record(r).map_err(|e| e.to_string())?;
    }
    String::from_utf8(w.into_inner().map_err(|e| e.to_string())?).map_err(|e| e.to_string())
}

pub(crate) fn json_text(v: &Value) -> Result<String, String> {
    serde_json::to_string_pretty(v)
        .map(|s| s + "\n")
        .map_err(|e| e.to_string())
}
