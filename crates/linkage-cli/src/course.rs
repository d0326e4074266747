//! `linkage course-sheet`: the course sheet of a scene (`linkage_diagram::course`)
//! as SVG, PNG or PDF; `linkage course-report`: the course-design report
//! (`linkage_diagram::course_report`), as PDF above all.

use linkage_diagram::course::CourseSheet;
use linkage_diagram::course_report::CourseReport;
use linkage_diagram::svg_course::course_sheet;
use linkage_diagram::svg_report::course_report;

use crate::args::{CourseArgs, SceneArgs};
use crate::diagram::{check_dpi, write_sheet};
use crate::error::Result;
use crate::io::{describe, load};

/// The SVG text, written where asked; returns what goes to standard output.
pub fn run(scene: &SceneArgs, args: &CourseArgs) -> Result<String> {
    check_dpi(&args.out)?;
    let mut k = load(scene)?;
    let sheet = CourseSheet::compute_from(&mut k, args.positions, args.first_deg, &chosen(args))
        .map_err(|e| describe(scene, e))?;
    write_sheet(course_sheet(&sheet, args.out.lang), &args.out)
}

/// The course-design report, written where asked (its PDF with --pdf).
pub fn report(scene: &SceneArgs, args: &CourseArgs) -> Result<String> {
    check_dpi(&args.out)?;
    let mut k = load(scene)?;
    let data = CourseReport::compute_from(&mut k, args.positions, args.first_deg, &chosen(args))
        .map_err(|e| describe(scene, e))?;
    write_sheet(course_report(&data, args.out.lang), &args.out)
}

/// The positions drawn with their polygons: as asked, or the second and the one
/// half a range on.
fn chosen(args: &CourseArgs) -> Vec<usize> {
    if !args.chosen.is_empty() {
        return args.chosen.clone();
    }
    [
        1.min(args.positions.saturating_sub(1)),
        args.positions / 2 + 1,
    ]
    .into_iter()
    .filter(|&c| c < args.positions)
    .collect()
}
