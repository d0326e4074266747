//! `linkage course-sheet`: the course sheet of a scene (`linkage_diagram::course`)
//! as SVG, and as PNG rendered from it.

use linkage_diagram::course::CourseSheet;
use linkage_diagram::svg_course::course_sheet;

use crate::args::{CourseArgs, SceneArgs};
use crate::diagram::render_png;
use crate::error::{CliError, Result};
use crate::io::{describe, load};

/// The SVG text, written where asked; returns what goes to standard output.
pub fn run(scene: &SceneArgs, args: &CourseArgs) -> Result<String> {
    if !(args.dpi.is_finite() && (10.0..=1200.0).contains(&args.dpi)) {
        return Err(CliError::refused(format!(
            "--dpi {} is out of range: 10 to 1200",
            args.dpi
        )));
    }
    let mut k = load(scene)?;
    let chosen = if args.chosen.is_empty() {
        vec![
            1.min(args.positions.saturating_sub(1)),
            args.positions / 2 + 1,
        ]
        .into_iter()
        .filter(|&c| c < args.positions)
        .collect()
    } else {
        args.chosen.clone()
    };
    let sheet =
        CourseSheet::compute(&mut k, args.positions, &chosen).map_err(|e| describe(scene, e))?;
    let svg = course_sheet(&sheet);
    for (path, bytes) in [
        (&args.svg, Some(svg.clone().into_bytes())),
        (&args.png, None),
    ] {
        let Some(path) = path else { continue };
        let bytes = match bytes {
            Some(b) => b,
            None => render_png(&svg, args.dpi)?,
        };
        std::fs::write(path, bytes).map_err(|source| CliError::Write {
            path: path.to_path_buf(),
            source,
        })?;
    }
    Ok(if args.svg.is_none() && args.png.is_none() {
        svg
    } else {
        String::new()
    })
}
