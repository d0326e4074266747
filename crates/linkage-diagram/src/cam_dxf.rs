//! A cam's profile (and its pitch curve and base circle, each on its own layer) as a
//! DXF drawing in millimetres, written by the `dxf` crate: closed lightweight
//! polylines through the sampled points, which a CAM program offsets or fits.

use dxf::entities::{Circle, Entity, EntityType, LwPolyline};
use dxf::enums::{AcadVersion, Units};
use dxf::{Drawing, DxfError, LwPolylineVertex, Point};

/// The profile's layer.
pub const PROFILE_LAYER: &str = "PROFILE";
/// The pitch curve's layer.
pub const PITCH_LAYER: &str = "PITCH";
/// The base circle's layer.
pub const BASE_CIRCLE_LAYER: &str = "BASE_CIRCLE";

fn polyline(points: &[[f64; 2]], layer: &str) -> Entity {
    let mut line = LwPolyline::default();
    line.set_is_closed(true);
    line.vertices = points
        .iter()
        .map(|&[x, y]| LwPolylineVertex {
            x: x * 1e3,
            y: y * 1e3,
            ..Default::default()
        })
        .collect();
    let mut e = Entity::new(EntityType::LwPolyline(line));
    e.common.layer = layer.to_string();
    e
}

/// The DXF of a cam: its `profile` and `pitch` curve (m, in the cam's frame about its
/// centre) and its base circle of `base_radius_m`.
///
/// # Errors
/// The `dxf` crate's, writing to memory.
pub fn cam_dxf(
    profile: &[[f64; 2]],
    pitch: &[[f64; 2]],
    base_radius_m: f64,
) -> Result<Vec<u8>, DxfError> {
    let mut drawing = millimetre_drawing();
    drawing.add_entity(polyline(profile, PROFILE_LAYER));
    drawing.add_entity(polyline(pitch, PITCH_LAYER));
    drawing.add_entity(circle(base_radius_m, BASE_CIRCLE_LAYER));
    saved(&drawing)
}

/// An empty drawing in millimetres, in a version that has lightweight polylines
/// (they came with R14; the crate writes R12 unless told).
fn millimetre_drawing() -> Drawing {
    let mut drawing = Drawing::new();
    drawing.header.version = AcadVersion::R2000;
    drawing.header.default_drawing_units = Units::Millimeters;
    drawing
}

/// A circle about the origin of `radius_m`, in millimetres, on `layer`.
fn circle(radius_m: f64, layer: &str) -> Entity {
    let mut e = Entity::new(EntityType::Circle(Circle::new(
        Point::new(0.0, 0.0, 0.0),
        radius_m * 1e3,
    )));
    e.common.layer = layer.to_string();
    e
}

/// The drawing's bytes.
fn saved(drawing: &Drawing) -> Result<Vec<u8>, DxfError> {
    let mut bytes = Vec::new();
    drawing.save(&mut bytes)?;
    Ok(bytes)
}

/// A cut gear's outline (`gear_profile::gear_outline`, metres) as a DXF drawing in
/// millimetres: the closed outline on the `PROFILE` layer, the pitch circle on the
/// `PITCH` layer.
///
/// # Errors
/// The `dxf` crate's, writing to memory.
pub fn gear_dxf(outline: &[[f64; 2]], pitch_radius_m: f64) -> Result<Vec<u8>, DxfError> {
    let mut drawing = millimetre_drawing();
    drawing.add_entity(polyline(outline, PROFILE_LAYER));
    drawing.add_entity(circle(pitch_radius_m, PITCH_LAYER));
    saved(&drawing)
}
