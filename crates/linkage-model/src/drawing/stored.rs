//! A drawing as text, so that an unfinished one survives a reload (the browser keeps
//! it in local storage). RON over a plain mirror of [`Drawing`]; reading checks every
//! index, since stored text is user input like any other.

use linkage::Vec2;
use linkage::drawing::{
    Drawing, DrawingDamper, DrawingForce, DrawingLink, DrawingPoint, DrawingSlider, DrawingSpring,
};
use linkage::scene::{DriveSpec, ForceWhen, LengthUnit, Models, Speed};
use serde::{Deserialize, Serialize};

/// The stored form: points as `(name, x m, y m, ground)`, links as `(name, points,
/// mass kg)` with their `(centroid m, inertia kg m²)` apart, sliders as `(point,
/// guide link, angle rad, mass kg)`, springs as `(a, b, k N/m, free length m)`,
/// dampers as `(a, b, c N s/m)`, forces as `(point, x N, y N, when)`. The fields
/// after `gravity` came later: a drawing stored without them still reads.
/// A link's own centroid (x, y m) and inertia (kg m²), each `None` for a uniform body.
type StoredBody = (Option<(f64, f64)>, Option<f64>);

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct StoredDrawing {
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
    #[serde(default)]
    bodies: Vec<StoredBody>,
    #[serde(default)]
    springs: Vec<(usize, usize, f64, Option<f64>)>,
    #[serde(default)]
    dampers: Vec<(usize, usize, f64)>,
    #[serde(default)]
    forces: Vec<(usize, f64, f64, ForceWhen)>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    drive: Option<DriveSpec>,
}

/// The drawing as RON text.
pub fn to_text(drawing: &Drawing) -> String {
    let stored = StoredDrawing {
        name: drawing.name.clone(),
        length_unit: drawing.length_unit,
        points: drawing
            .points
            .iter()
            .map(|p| (p.name.clone(), p.at.x, p.at.y, p.ground))
            .collect(),
        links: drawing
            .links
            .iter()
            .map(|l| (l.name.clone(), l.points.clone(), l.mass_kg))
            .collect(),
        sliders: drawing
            .sliders
            .iter()
            .map(|s| (s.point, s.guide, s.angle_rad, s.mass_kg))
            .collect(),
        driver: drawing.driver,
        output: drawing.output,
        speed: drawing.speed,
        models: drawing.models,
        gravity: drawing.gravity,
        bodies: drawing
            .links
            .iter()
            .map(|l| (l.centroid.map(|c| (c.x, c.y)), l.inertia_kg_m2))
            .collect(),
        springs: drawing
            .springs
            .iter()
            .map(|s| (s.a, s.b, s.k_n_per_m, s.free_length_m))
            .collect(),
        dampers: drawing
            .dampers
            .iter()
            .map(|d| (d.a, d.b, d.c_n_s_per_m))
            .collect(),
        forces: drawing
            .forces
            .iter()
            .map(|f| (f.point, f.force_n.x, f.force_n.y, f.when))
            .collect(),
        drive: drawing.drive.clone(),
    };
    // Plain strings, numbers and options: writing cannot fail.
    ron::to_string(&stored).unwrap_or_default()
}

/// The drawing from [`to_text`]'s text, or why it is not one.
pub fn from_text(text: &str) -> Result<Drawing, String> {
    let s: StoredDrawing = ron::from_str(text).map_err(|e| format!("a stored drawing: {e}"))?;
    if !indices_valid(&s) {
        return Err("a stored drawing names a point or link it does not have".into());
    }
    if !values_valid(&s) {
        return Err(
            "a stored drawing holds a place, mass or force element that is not a valid number"
                .into(),
        );
    }
    let bodies = s.bodies.into_iter().chain(std::iter::repeat((None, None)));
    Ok(Drawing {
        name: s.name,
        length_unit: s.length_unit,
        points: s
            .points
            .into_iter()
            .map(|(name, x, y, ground)| DrawingPoint {
                name,
                at: Vec2::new(x, y),
                ground,
            })
            .collect(),
        links: s
            .links
            .into_iter()
            .zip(bodies)
            .map(
                |((name, points, mass_kg), (centroid, inertia))| DrawingLink {
                    name,
                    points,
                    mass_kg,
                    centroid: centroid.map(|(x, y)| Vec2::new(x, y)),
                    inertia_kg_m2: inertia,
                },
            )
            .collect(),
        sliders: s
            .sliders
            .into_iter()
            .map(|(point, guide, angle_rad, mass_kg)| DrawingSlider {
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
        springs: s
            .springs
            .into_iter()
            .map(|(a, b, k_n_per_m, free_length_m)| DrawingSpring {
                a,
                b,
                k_n_per_m,
                free_length_m,
            })
            .collect(),
        dampers: s
            .dampers
            .into_iter()
            .map(|(a, b, c_n_s_per_m)| DrawingDamper { a, b, c_n_s_per_m })
            .collect(),
        forces: s
            .forces
            .into_iter()
            .map(|(point, x, y, when)| DrawingForce {
                point,
                force_n: Vec2::new(x, y),
                when,
            })
            .collect(),
        drive: s.drive,
    })
}

/// Whether every point and link index names one the drawing has.
fn indices_valid(s: &StoredDrawing) -> bool {
    let n = s.points.len();
    let links = s.links.len();
    let points = s
        .links
        .iter()
        .flat_map(|l| l.1.iter().copied())
        .chain(s.sliders.iter().map(|sl| sl.0))
        .chain(s.springs.iter().flat_map(|e| [e.0, e.1]))
        .chain(s.dampers.iter().flat_map(|e| [e.0, e.1]))
        .chain(s.forces.iter().map(|f| f.0));
    let link_refs = [s.driver, s.output]
        .into_iter()
        .chain(s.sliders.iter().map(|sl| sl.1))
        .flatten();
    points.into_iter().all(|p| p < n)
        && link_refs.into_iter().all(|l| l < links)
        && s.bodies.len() <= links
}

/// Whether every place, mass and force element is a valid number.
fn values_valid(s: &StoredDrawing) -> bool {
    let positive = |v: f64| v.is_finite() && v > 0.0;
    let at_least_zero = |v: f64| v.is_finite() && v >= 0.0;
    s.points.iter().all(|p| p.1.is_finite() && p.2.is_finite())
        && s.sliders.iter().all(|sl| sl.2.is_finite())
        && s.links
            .iter()
            .filter_map(|l| l.2)
            .chain(s.sliders.iter().filter_map(|sl| sl.3))
            .all(positive)
        && s.bodies.iter().all(|(c, i)| {
            c.is_none_or(|(x, y)| x.is_finite() && y.is_finite()) && i.is_none_or(at_least_zero)
        })
        && s.springs
            .iter()
            .all(|e| at_least_zero(e.2) && e.3.is_none_or(at_least_zero))
        && s.dampers.iter().all(|e| at_least_zero(e.2))
        && s.forces.iter().all(|f| f.1.is_finite() && f.2.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::edit::{Body, DrawingEdit, End, apply};

    /// A drawing kept in the browser's storage by an earlier version reads in this
    /// one: the text names fields, never a type, so renaming the types (a sketch
    /// became a drawing) changes nothing stored.
    #[test]
    fn the_stored_text_names_no_type() {
        let text = to_text(&Drawing::new("d"));
        assert!(
            !text.contains("Drawing") && !text.contains("Sketch"),
            "{text}"
        );
        assert!(from_text(&text).is_ok());
    }

    #[test]
    fn a_drawing_reads_back_as_written_and_damage_is_refused() {
        let mut s = Drawing::new("stored");
        for edit in [
            DrawingEdit::AddPivot(Vec2::new(0.0, 0.0)),
            DrawingEdit::AddLink(End::Point(0), End::New(Vec2::new(0.0, 0.1))),
            DrawingEdit::AddLink(End::Point(1), End::New(Vec2::new(0.2, -0.03))),
            DrawingEdit::AddSlider {
                point: 2,
                angle_rad: 0.0,
            },
            DrawingEdit::SetDriver(0),
            DrawingEdit::SetModels(Models::Kinetostatics),
            DrawingEdit::SetMass(Body::Block(0), Some(120.0)),
            DrawingEdit::SetGravity(true),
            DrawingEdit::AddSpring(0, 2),
            DrawingEdit::SetSpring {
                spring: 0,
                k_n_per_m: 250.0,
                free_length_m: Some(0.15),
            },
            DrawingEdit::AddDamper(1, 2),
            DrawingEdit::AddForce(2),
        ] {
            s = apply(&s, edit).expect("applies");
        }
        let text = to_text(&s);
        assert_eq!(from_text(&text), Ok(s));
        let damaged = text.replace("Some(0)", "Some(7)");
        assert_ne!(damaged, text);
        assert!(from_text(&damaged).is_err());
        assert!(from_text("not a drawing").is_err());
        let bad_spring = text.replace("springs:[(0,2,", "springs:[(0,9,");
        assert_ne!(bad_spring, text, "{text}");
        assert!(from_text(&bad_spring).is_err());
    }

    #[test]
    fn a_drawing_stored_before_force_elements_still_reads() {
        let old = r#"(name:"old",length_unit:Millimetre,points:[("A",0.0,0.0,true),("B",0.0,0.1,false)],links:[("link 1",[0,1],None)],sliders:[],driver:Some(0),output:None,speed:Rpm(60.0),models:Kinematics,gravity:false)"#;
        let s = from_text(old).expect("reads");
        assert_eq!(s.links.len(), 1);
        assert!(s.links[0].centroid.is_none() && s.springs.is_empty() && s.forces.is_empty());
    }
}
