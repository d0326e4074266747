//! `linkage diagram`: the sheet of one position (pose, polygons, tables, instant
//! centres) as SVG, written by `linkage-diagram` exactly as the app exports it, and
//! as PNG rendered from that SVG by resvg (`linkage_diagram::png`) with the app's own
//! font.

use linkage::Kinematics;
use linkage::force_polygon::{ForcePolygons, force_polygons};
use linkage::instant_centres::instant_centres;
use linkage::kinetostatics::Kinetostatics;
use linkage::polygon::polygons;
use linkage_diagram::pages::{Sheet, page_path};
use linkage_diagram::svg::{Parts, Position, sheet};

use crate::args::{DEFAULT_PARTS, DiagramArgs, Part, SceneArgs, SheetOut};
use crate::error::{CliError, Result};
use crate::io::load;

/// The SVG text of the sheet, and the PNG written if asked; returns what goes to
/// standard output (the SVG when no file was named).
pub fn run(scene: &SceneArgs, args: &DiagramArgs) -> Result<String> {
    if !(args.input_deg.is_finite()) {
        return Err(CliError::refused(format!(
            "--input-deg {} is invalid: must be a finite number",
            args.input_deg
        )));
    }
    check_dpi(&args.out)?;
    let mut k = load(scene)?;
    let has = |p: Part| args.what.contains(&p);
    let input_rad = args.input_deg.to_radians();
    let forces = if has(Part::Forces) {
        match forces_at(&mut k, input_rad) {
            Ok(fp) => Some(fp),
            // The default sheet has force polygons where the scene has force data
            // and the position has them; one asked for by name must.
            Err(_) if args.what == DEFAULT_PARTS => None,
            Err(e) => return Err(e.into()),
        }
    } else {
        None
    };
    let s = k.solve(input_rad)?;
    let eqs = polygons(&k, &s);
    let m = k.mechanism();
    let centres = instant_centres(m, &s);
    let parts = Parts {
        pose: has(Part::Pose) || has(Part::Centres),
        velocity: has(Part::Velocity),
        acceleration: has(Part::Acceleration),
        centres: has(Part::Centres),
        table: has(Part::Table),
        forces: has(Part::Forces),
    };
    let position = Position {
        mechanism: m,
        solution: &s,
        equations: &eqs,
        centres: Some(&centres),
        forces: forces.as_ref(),
    };
    write_sheet(sheet(&position, parts, args.out.lang), &args.out)
}

/// The force polygons at `input_rad`.
fn forces_at(k: &mut Kinematics, input_rad: f64) -> linkage::Result<ForcePolygons> {
    let mut ks = Kinetostatics::new(k)?;
    force_polygons(k, &mut ks, input_rad)
}

/// Refuses a resolution outside 10 to 1200 dpi.
pub fn check_dpi(out: &SheetOut) -> Result<()> {
    if out.dpi.is_finite() && (10.0..=1200.0).contains(&out.dpi) {
        Ok(())
    } else {
        Err(CliError::refused(format!(
            "--dpi {} is out of range: 10 to 1200",
            out.dpi
        )))
    }
}

/// Writes `sheet`'s pages (SVG, PNG, PDF) where `out` says; returns what goes to
/// standard output: a one-page sheet's SVG when no file was named.
///
/// # Errors
/// A file that cannot be written, or a sheet of several pages with no file named.
pub fn write_sheet(sheet: Sheet, out: &SheetOut) -> Result<String> {
    let write = |path: &std::path::Path, bytes: &[u8]| {
        std::fs::write(path, bytes).map_err(|source| CliError::Write {
            path: path.to_path_buf(),
            source,
        })
    };
    for (i, page) in sheet.pages.iter().enumerate() {
        if let Some(path) = &out.svg {
            write(&page_path(path, i), page.as_bytes())?;
        }
        if let Some(path) = &out.png {
            write(&page_path(path, i), &render_png(page, out.dpi)?)?;
        }
    }
    if let Some(path) = &out.pdf {
        let lang = out.lang.code();
        let pdf = linkage_diagram::pdf::document(&sheet, SHEET_FONT, SHEET_FAMILY, lang)
            .map_err(CliError::Plot)?;
        write(path, &pdf)?;
    }
    if out.svg.is_some() || out.png.is_some() || out.pdf.is_some() {
        return Ok(String::new());
    }
    match &sheet.pages[..] {
        [one] => Ok(one.clone()),
        pages => Err(CliError::refused(format!(
            "the sheet has {} A4 pages: write them with --pdf FILE, or --svg FILE \
             (FILE, FILE-2, …)",
            pages.len()
        ))),
    }
}

/// The face the sheets' Latin text is set in: the app's own.
const SHEET_FONT: &[u8] = epaint_default_fonts::UBUNTU_LIGHT;
/// Its family name.
const SHEET_FAMILY: &str = "Ubuntu";

/// The SVG rendered at `dpi`, as PNG bytes, with the app's own font.
pub fn render_png(svg: &str, dpi: f32) -> Result<Vec<u8>> {
    linkage_diagram::png::render(svg, dpi, SHEET_FONT, SHEET_FAMILY).map_err(CliError::Plot)
}
