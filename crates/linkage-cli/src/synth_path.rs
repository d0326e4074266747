//! `linkage synth path`: a four-bar whose coupler point passes through target
//! points read from a CSV file, by the solver's path search; prints the designs
//! ranked by their largest miss, the evaluations and the time taken.

use linkage::synthesis::path::{
    PathConstraints, PathDesign, PathSearch, PathTargets, SearchOptions, TargetOrder,
};
use serde_json::json;

use crate::args::PathSearchArgs;
use crate::error::{CliError, Result};
use crate::io::json_text;

/// Runs the search `args` describes; writes the best design's scene to `args.out`
/// if given; returns the result as JSON text.
///
/// # Errors
/// An unreadable file or row (named by line), targets or options the search
/// refuses (with the valid range), or no design that meets the constraints.
pub fn run(args: &PathSearchArgs) -> Result<String> {
    let csv = &args.points;
    let text = std::fs::read_to_string(csv).map_err(|source| CliError::Read {
        path: csv.to_path_buf(),
        source,
    })?;
    let width = if args.timed { 3 } else { 2 };
    let rows =
        linkage::synthesis::rows::read_rows(&text, width).map_err(|e| CliError::in_file(csv, e))?;
    let targets = PathTargets {
        points_m: rows.iter().map(|r| [r[0], r[1]]).collect(),
        crank_deg: args.timed.then(|| rows.iter().map(|r| r[2]).collect()),
    };
    let mut search = PathSearch::new(&targets, &constraints(args)?, options(args))?;
    let progress = search.run();
    let designs = search.designs();
    let Some(best) = designs.first() else {
        return Err(CliError::refused(format!(
            "no four-bar meets the constraints after {} evaluations: raise --max-evaluations, \
             or loosen them (--any-branch, --min-transmission-deg, --ground-region, without --crank-turns)",
            progress.evaluations
        )));
    };
    if let Some(path) = &args.out {
        write_scene(&best.scene(), path)?;
    }
    for (k, path) in args.cognate_out.iter().flatten().enumerate() {
        let scene = best.cognate_scene(k).ok_or_else(|| {
            CliError::refused(format!(
                "the best design has no cognate {} to write to {} (its coupler point lies on B or C)",
                k + 1,
                path.display()
            ))
        })?;
        write_scene(&scene, path)?;
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

fn write_scene(scene: &linkage::scene::SceneFile, path: &std::path::Path) -> Result<()> {
    let text = scene.to_ron()?;
    std::fs::write(path, text).map_err(|source| CliError::Write {
        path: path.to_path_buf(),
        source,
    })
}

fn constraints(args: &PathSearchArgs) -> Result<PathConstraints> {
    let ground_region_m = match args.ground_region.as_deref() {
        None => None,
        Some(&[x0, y0, x1, y1]) => Some([[x0, y0], [x1, y1]]),
        Some(other) => {
            return Err(CliError::refused(format!(
                "--ground-region takes 4 numbers (x0 y0 x1 y1), not {}",
                other.len()
            )));
        }
    };
    Ok(PathConstraints {
        crank_turns: args.crank_turns,
        min_transmission_deg: args.min_transmission_deg,
        ground_region_m,
        one_branch: !args.any_branch,
        order: if args.any_order {
            TargetOrder::Any
        } else {
            TargetOrder::AsGiven
        },
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

/// A design as JSON: its linkage, misses and cognates (each with its own class,
/// crank and transmission angle, and the link of the design its crank turns with).
fn design_json(d: &PathDesign) -> serde_json::Value {
    serde_json::to_value(d).unwrap_or_else(|e| json!({ "error": e.to_string() }))
}
