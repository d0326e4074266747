//! The cam's profile (and its pitch curve and base circle, each on its own layer) as
//! a DXF drawing in millimetres, written by the `dxf` crate: closed lightweight
//! polylines through the sampled points, which a CAM program offsets or fits.

use std::path::Path;

use dxf::entities::{Circle, Entity, EntityType, LwPolyline};
use dxf::enums::{AcadVersion, Units};
use dxf::{Drawing, LwPolylineVertex, Point};
use linkage::cam::{CamDesign, CamPoint};

use crate::error::{CliError, Result};

/// The profile's layer.
pub const PROFILE_LAYER: &str = "PROFILE";
/// The pitch curve's layer.
pub const PITCH_LAYER: &str = "PITCH";

fn polyline(points: impl Iterator<Item = [f64; 2]>, layer: &str) -> Entity {
    let mut line = LwPolyline::default();
    line.set_is_closed(true);
    line.vertices = points
        .map(|[x, y]| LwPolylineVertex {
            x: x * 1e3,
            y: y * 1e3,
            ..Default::default()
        })
        .collect();
    let mut e = Entity::new(EntityType::LwPolyline(line));
    e.common.layer = layer.to_string();
    e
}

/// Writes the DXF of `d` sampled at `points` to `path`.
pub fn write(path: &Path, d: &CamDesign, points: &[CamPoint]) -> Result<()> {
    let mut drawing = Drawing::new();
    // Lightweight polylines came with R14; the crate writes R12 unless told.
    drawing.header.version = AcadVersion::R2000;
    drawing.header.default_drawing_units = Units::Millimeters;
    drawing.add_entity(polyline(points.iter().map(|p| p.profile_m), PROFILE_LAYER));
    drawing.add_entity(polyline(points.iter().map(|p| p.pitch_m), PITCH_LAYER));
    let base = Circle::new(Point::new(0.0, 0.0, 0.0), d.cam.base_radius_m * 1e3);
    let mut circle = Entity::new(EntityType::Circle(base));
    circle.common.layer = "BASE_CIRCLE".to_string();
    drawing.add_entity(circle);
    drawing.save_file(path).map_err(|e| CliError::Write {
        path: path.to_path_buf(),
        source: std::io::Error::other(e.to_string()),
    })
}
