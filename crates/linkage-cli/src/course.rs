//! `linkage course-sheet`: the course sheet of a scene (`linkage_diagram::course`)
//! as SVG, and as PNG rendered from it.

use linkage_diagram::course::CourseSheet;
use linkage_diagram::svg_course::course_sheet;

use crate::args::{CourseArgs, SceneArgs};
use crate::diagram::{check_dpi, write_sheet};
use crate::error::Result;
use crate::io::{describe, load};

/// The SVG text, written where asked; returns what goes to standard output.
pub fn run(scene: &SceneArgs, args: &CourseArgs) -> Result<String> {
    check_dpi(&args.out)?;
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
    write_sheet(course_sheet(&sheet, args.out.lang), &args.out)
}
