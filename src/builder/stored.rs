//! A drawing as text, so that an unfinished one survives a reload (the browser keeps
//! it in local storage). RON over a plain mirror of [`Sketch`]; reading checks every
//! index, since stored text is user input like any other.

use linkage::Vec2;
use linkage::scene::{LengthUnit, Models, Speed};
use linkage::sketch::{Sketch, SketchLink, SketchPoint, SketchSlider};
use serde::{Deserialize, Serialize};

/// The stored form: points as `(name, x m, y m, ground)`, links as `(name, points,
/// mass kg)`, sliders as `(point, guide link, angle rad, mass kg)`.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct StoredSketch {
    name: String,
    length_unit: LengthUnit,
    points: Vec<(String, f64, f64, bool)>,
    links: Vec<(String, Vec<usize>, Option<f64>)>,
    sliders: Vec<(usize, Option<usize>, f64, Option<f64>)>,
    driver: Option<usize>,
    output: Option<usize>,
    speed: Speed,
    models: Models,
    gravity: bool,
}

/// The drawing as RON text.
pub fn to_text(sketch: &Sketch) -> String {
    let stored = StoredSketch {
        name: sketch.name.clone(),
        length_unit: sketch.length_unit,
        points: sketch
            .points
            .iter()
            .map(|p| (p.name.clone(), p.at.x, p.at.y, p.ground))
            .collect(),
        links: sketch
            .links
            .iter()
            .map(|l| (l.name.clone(), l.points.clone(), l.mass_kg))
            .collect(),
        sliders: sketch
            .sliders
            .iter()
            .map(|s| (s.point, s.guide, s.angle_rad, s.mass_kg))
            .collect(),
        driver: sketch.driver,
        output: sketch.output,
        speed: sketch.speed,
        models: sketch.models,
        gravity: sketch.gravity,
    };
    // Plain strings, numbers and options: writing cannot fail.
    ron::to_string(&stored).unwrap_or_default()
}

/// The drawing from [`to_text`]'s text, or why it is not one.
pub fn from_text(text: &str) -> Result<Sketch, String> {
    let s: StoredSketch = ron::from_str(text).map_err(|e| format!("a stored drawing: {e}"))?;
    let n = s.points.len();
    let links = s.links.len();
    let bad_point = s
        .links
        .iter()
        .flat_map(|l| &l.1)
        .chain(s.sliders.iter().map(|sl| &sl.0))
        .any(|&p| p >= n);
    let bad_link = [s.driver, s.output]
        .into_iter()
        .chain(s.sliders.iter().map(|sl| sl.1))
        .flatten()
        .any(|l| l >= links);
    let not_finite = s
        .points
        .iter()
        .any(|p| !(p.1.is_finite() && p.2.is_finite()))
        || s.sliders.iter().any(|sl| !sl.2.is_finite())
        || s.links
            .iter()
            .filter_map(|l| l.2)
            .chain(s.sliders.iter().filter_map(|sl| sl.3))
            .any(|kg| !(kg.is_finite() && kg > 0.0));
    if bad_point || bad_link || not_finite {
        return Err("a stored drawing names a point or link it does not have".into());
    }
    Ok(Sketch {
        name: s.name,
        length_unit: s.length_unit,
        points: s
            .points
            .into_iter()
            .map(|(name, x, y, ground)| SketchPoint {
                name,
                at: Vec2::new(x, y),
                ground,
            })
            .collect(),
        links: s
            .links
            .into_iter()
            .map(|(name, points, mass_kg)| SketchLink {
                name,
                points,
                mass_kg,
            })
            .collect(),
        sliders: s
            .sliders
            .into_iter()
            .map(|(point, guide, angle_rad, mass_kg)| SketchSlider {
                point,
                guide,
                angle_rad,
                mass_kg,
            })
            .collect(),
        driver: s.driver,
        output: s.output,
        speed: s.speed,
        models: s.models,
        gravity: s.gravity,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::builder::edit::{Body, End, SketchEdit, apply};

    #[test]
    fn a_drawing_reads_back_as_written_and_damage_is_refused() {
        let mut s = Sketch::new("stored");
        for edit in [
            SketchEdit::AddPivot(Vec2::new(0.0, 0.0)),
            SketchEdit::AddLink(End::Point(0), End::New(Vec2::new(0.0, 0.1))),
            SketchEdit::AddLink(End::Point(1), End::New(Vec2::new(0.2, -0.03))),
            SketchEdit::AddSlider {
                point: 2,
                angle_rad: 0.0,
            },
            SketchEdit::SetDriver(0),
            SketchEdit::SetModels(Models::Kinetostatics),
            SketchEdit::SetMass(Body::Block(0), Some(120.0)),
            SketchEdit::SetGravity(true),
        ] {
            s = apply(&s, edit).expect("applies");
        }
        let text = to_text(&s);
        assert_eq!(from_text(&text), Ok(s));
        let damaged = text.replace("Some(0)", "Some(7)");
        assert_ne!(damaged, text);
        assert!(from_text(&damaged).is_err());
        assert!(from_text("not a drawing").is_err());
    }
}
