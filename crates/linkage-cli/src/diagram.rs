//! `linkage diagram`: the sheet of one position (pose, polygons, tables, instant
//! centres) as SVG, written by `linkage-diagram` exactly as the app exports it, and
//! as PNG rendered from that SVG by resvg (`linkage_diagram::png`) with the app's own
//! font.

use linkage::Kinematics;
use linkage::force_polygon::{ForcePolygons, force_polygons};
use linkage::instant_centres::instant_centres;
use linkage::kinetostatics::Kinetostatics;
use linkage::polygon::polygons;
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
    let svg = sheet(&position, parts);
    write_sheet(svg, &args.out)
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

/// Writes `svg` (and its PNG) where `out` says; returns what goes to standard output
/// (the SVG when no file was named).
pub fn write_sheet(svg: String, out: &SheetOut) -> Result<String> {
    let write = |path: &std::path::Path, bytes: &[u8]| {
        std::fs::write(path, bytes).map_err(|source| CliError::Write {
            path: path.to_path_buf(),
            source,
        })
    };
    if let Some(path) = &out.svg {
        write(path, svg.as_bytes())?;
    }
    if let Some(path) = &out.png {
        write(path, &render_png(&svg, out.dpi)?)?;
    }
    Ok(if out.svg.is_none() && out.png.is_none() {
        svg
    } else {
        String::new()
    })
}

/// The SVG rendered at `dpi`, as PNG bytes, with the app's own font.
pub fn render_png(svg: &str, dpi: f32) -> Result<Vec<u8>> {
    linkage_diagram::png::render(svg, dpi, epaint_default_fonts::UBUNTU_LIGHT, "Ubuntu")
        .map_err(CliError::Plot)
}
