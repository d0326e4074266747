//! `linkage synth path`: a four-bar whose coupler point passes through target
//! points read from a CSV file, by the solver's path search; prints the designs
//! ranked by their largest miss, the evaluations and the time taken.

use linkage::synthesis::path::{
    PathConstraints, PathDesign, PathSearch, PathTargets, SearchOptions,
};
use serde_json::json;

use crate::PathSearchArgs;
use crate::commands::json_text;

/// Runs the search `args` describes; writes the best design's scene to `args.out`
/// if given; returns the result as JSON text.
///
/// # Errors
/// An unreadable file or row (named by line), targets or options the search
/// refuses (with the valid range), or no design that meets the constraints.
pub fn run(args: &PathSearchArgs) -> Result<String, String> {
    let csv = &args.points;
    let text =
        std::fs::read_to_string(csv).map_err(|e| format!("cannot read {}: {e}", csv.display()))?;
    let width = if args.timed { 3 } else { 2 };
    let rows =
        crate::synth_function::rows(&text, width).map_err(|e| format!("{}: {e}", csv.display()))?;
    let targets = PathTargets {
        points_m: rows.iter().map(|r| [r[0], r[1]]).collect(),
        crank_deg: args.timed.then(|| rows.iter().map(|r| r[2]).collect()),
    };
    let mut search =
        PathSearch::new(&targets, &constraints(args)?, options(args)).map_err(|e| e.to_string())?;
    let progress = search.run();
    let designs = search.designs();
    let Some(best) = designs.first() else {
        return Err(format!(
            "no four-bar meets the constraints after {} evaluations: raise --max-evaluations, \
             or loosen them (--rocking-crank, --any-branch, --min-transmission-deg, --ground-region)",
            progress.evaluations
        ));
    };
    if let Some(path) = &args.out {
        let scene = best.scene().to_ron().map_err(|e| e.to_string())?;
        std::fs::write(path, scene).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    json_text(&json!({
        "targets": targets.points_m.len(),
        "timed": args.timed,
        "seed": args.seed,
        "evaluations": progress.evaluations,
        "seconds": progress.seconds,
        "within_tolerance": progress.solutions,
        "designs": designs.iter().map(design_json).collect::<Vec<_>>(),
    }))
}

fn constraints(args: &PathSearchArgs) -> Result<PathConstraints, String> {
    let ground_region_m = match args.ground_region.as_deref() {
        None => None,
        Some(&[x0, y0, x1, y1]) => Some([[x0, y0], [x1, y1]]),
        Some(other) => {
            return Err(format!(
                "--ground-region takes 4 numbers (x0 y0 x1 y1), not {}",
                other.len()
            ));
        }
    };
    Ok(PathConstraints {
        crank_turns: !args.rocking_crank,
        min_transmission_deg: args.min_transmission_deg,
        ground_region_m,
        one_branch: !args.any_branch,
    })
}

fn options(args: &PathSearchArgs) -> SearchOptions {
    SearchOptions {
        seed: args.seed,
        solutions: args.solutions,
        tolerance: args.tolerance,
        max_evaluations: args.max_evaluations,
        ..SearchOptions::default()
    }
}

fn design_json(d: &PathDesign) -> serde_json::Value {
    json!({
        "pivot_a_m": d.pivot_a,
        "pivot_d_m": d.pivot_d,
        "crank_m": d.crank_m,
        "coupler_m": d.coupler_m,
        "rocker_m": d.rocker_m,
        "coupler_point_m": d.coupler_point_m,
        "c_left_of_bd": d.c_left_of_bd,
        "crank_deg": d.crank_deg,
        "max_error_m": d.max_error_m,
        "rms_error_m": d.rms_error_m,
        "relative_error": d.relative_error,
        "crank_turns": d.crank_turns,
        "min_transmission_deg": d.min_transmission_deg,
    })
}
