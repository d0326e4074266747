//! The edits a drawing takes, as values: the canvas turns clicks and drags into
//! these, and [`apply`] makes the next drawing from them, or says why not.

use linkage::Vec2;
use linkage::drawing::{Drawing, DrawingLink, DrawingPoint, DrawingSlider};

use super::drawing_edit::finite;
pub use super::drawing_edit::{Body, DrawingEdit, Element, End, Named, Refusal};

/// The drawing after `edit`, or why it is refused (`drawing` is left as it was).
pub fn apply(drawing: &Drawing, edit: DrawingEdit) -> Result<Drawing, Refusal> {
    let mut next = drawing.clone();
    match edit {
        DrawingEdit::AddPivot(at) => {
            finite(at)?;
            add_point(&mut next, at, true);
        }
        DrawingEdit::SetGround { point, ground } => next.points[point].ground = ground,
        DrawingEdit::AddLink(a, b) => add_link(&mut next, a, b)?,
        DrawingEdit::AddPointToLink { link, end } => add_point_to_link(&mut next, link, end)?,
        DrawingEdit::AddSlider { point, angle_rad } => add_slider(&mut next, point, angle_rad)?,
        DrawingEdit::SetGuide {
            slider,
            guide,
            angle_rad,
        } => set_guide(&mut next, slider, guide, angle_rad)?,
        DrawingEdit::SetDriver(link) => set_driver(&mut next, link)?,
        DrawingEdit::MovePoint { point, to } => {
            finite(to)?;
            next.points[point].at = to;
        }
        DrawingEdit::DeletePoint(point) => delete_point(&mut next, point),
        DrawingEdit::DeleteLink(link) => delete_link(&mut next, link),
        DrawingEdit::Rename(what, name) => rename(&mut next, what, name)?,
        DrawingEdit::SetSpeedRpm(rpm) => {
            if !(rpm.is_finite() && rpm != 0.0) {
                return Err(Refusal::Speed(rpm));
            }
            next.speed = linkage::scene::Speed::Rpm(rpm);
        }
        DrawingEdit::SetOutput(link) => next.output = link,
        DrawingEdit::SetModels(models) => next.models = models,
        DrawingEdit::SetGravity(on) => next.gravity = on,
        DrawingEdit::SetDrive(drive) => {
            if let Some(spec) = &drive {
                linkage::model::Drive::from_spec(spec).map_err(Refusal::Drive)?;
            }
            next.drive = drive;
        }
        DrawingEdit::AddSpring(..)
        | DrawingEdit::AddDamper(..)
        | DrawingEdit::AddForce(_)
        | DrawingEdit::SetSpring { .. }
        | DrawingEdit::SetDamper { .. }
        | DrawingEdit::SetForce { .. }
        | DrawingEdit::DeleteElement(_)
        | DrawingEdit::SetBody { .. } => super::loads::apply(&mut next, edit)?,
        DrawingEdit::SetMass(body, kg) => set_mass(&mut next, body, kg)?,
    }
    Ok(next)
}

/// Joins point `end` (drawn or new) to `link`.
fn add_point_to_link(next: &mut Drawing, link: usize, end: End) -> Result<(), Refusal> {
    let p = resolve(next, end)?;
    if next.links[link].points.contains(&p) {
        return Err(Refusal::AlreadyJoined(next.links[link].name.clone()));
    }
    next.links[link].points.push(p);
    Ok(())
}

/// A slider block at `point`, its guide not yet chosen.
fn add_slider(next: &mut Drawing, point: usize, angle_rad: f64) -> Result<(), Refusal> {
    if next.sliders.iter().any(|s| s.point == point) {
        return Err(Refusal::AlreadySlider(next.points[point].name.clone()));
    }
    next.sliders.push(DrawingSlider {
        point,
        guide: None,
        angle_rad,
        mass_kg: None,
    });
    Ok(())
}

/// The slider's guide (a link not through its own pin; `None`: ground) and angle.
fn set_guide(
    next: &mut Drawing,
    slider: usize,
    guide: Option<usize>,
    angle_rad: f64,
) -> Result<(), Refusal> {
    if !angle_rad.is_finite() {
        return Err(Refusal::NotFinite);
    }
    let pin = next.sliders[slider].point;
    if let Some(l) = guide.filter(|&l| next.links[l].points.contains(&pin)) {
        return Err(Refusal::GuideThroughPin(next.links[l].name.clone()));
    }
    next.sliders[slider].guide = guide;
    next.sliders[slider].angle_rad = angle_rad;
    Ok(())
}

/// The driver: a link with a point on ground.
fn set_driver(next: &mut Drawing, link: usize) -> Result<(), Refusal> {
    let l = &next.links[link];
    if !l.points.iter().any(|&p| next.points[p].ground) {
        return Err(Refusal::DriverNotGrounded(l.name.clone()));
    }
    next.driver = Some(link);
    Ok(())
}

/// A link's or a block's mass (`None`: none), kg, finite and positive.
fn set_mass(next: &mut Drawing, body: Body, kg: Option<f64>) -> Result<(), Refusal> {
    if let Some(kg) = kg.filter(|kg| !(kg.is_finite() && *kg > 0.0)) {
        return Err(Refusal::Mass(kg));
    }
    match body {
        Body::Link(l) => next.links[l].mass_kg = kg,
        Body::Block(b) => next.sliders[b].mass_kg = kg,
    }
    Ok(())
}

/// The first unused name of `A`..`Z`, then `A1`..`Z1`, ...
fn next_point_name(drawing: &Drawing) -> String {
    (0..)
        .map(|i: usize| {
            let letter = char::from(b'A' + (i % 26) as u8);
            match i / 26 {
                0 => letter.to_string(),
                round => format!("{letter}{round}"),
            }
        })
        .find(|name| drawing.points.iter().all(|p| &p.name != name))
        .unwrap_or_default()
}

/// The first unused `link N`.
fn next_link_name(drawing: &Drawing) -> String {
    (1..)
        .map(|i: usize| format!("link {i}"))
        .find(|name| drawing.links.iter().all(|l| &l.name != name))
        .unwrap_or_default()
}

fn add_point(drawing: &mut Drawing, at: Vec2, ground: bool) -> usize {
    let name = next_point_name(drawing);
    drawing.points.push(DrawingPoint { name, at, ground });
    drawing.points.len() - 1
}

fn resolve(drawing: &mut Drawing, end: End) -> Result<usize, Refusal> {
    match end {
        End::Point(p) => Ok(p),
        End::New(at) => {
            finite(at)?;
            Ok(add_point(drawing, at, false))
        }
    }
}

fn add_link(drawing: &mut Drawing, a: End, b: End) -> Result<(), Refusal> {
    if a == b {
        return Err(Refusal::SameEnds);
    }
    if let (End::Point(p), End::Point(q)) = (a, b)
        && let Some(l) = drawing
            .links
            .iter()
            .find(|l| l.points.contains(&p) && l.points.contains(&q))
    {
        return Err(Refusal::AlreadyJoined(l.name.clone()));
    }
    let p = resolve(drawing, a)?;
    let q = resolve(drawing, b)?;
    let name = next_link_name(drawing);
    drawing.links.push(DrawingLink::new(&name, vec![p, q]));
    Ok(())
}

/// Renames a point or a link; names are unique among points and among links (a
/// slider's block and guide point take theirs from its pin: "slider C", "C guide").
fn rename(drawing: &mut Drawing, what: Named, name: String) -> Result<(), Refusal> {
    let name = name.trim().to_owned();
    let taken = match what {
        Named::Point(p) => drawing
            .points
            .iter()
            .enumerate()
            .any(|(i, q)| i != p && q.name == name),
        Named::Link(l) => {
            name == "ground"
                || drawing
                    .links
                    .iter()
                    .enumerate()
                    .any(|(i, k)| i != l && k.name == name)
        }
    };
    if name.is_empty() || taken || name.contains('\n') {
        return Err(Refusal::Name(name));
    }
    match what {
        Named::Point(p) => drawing.points[p].name = name,
        Named::Link(l) => drawing.links[l].name = name,
    }
    Ok(())
}

/// Removes a point; links left with one point go, and so do its sliders and the
/// force elements at it.
fn delete_point(drawing: &mut Drawing, point: usize) {
    drawing.sliders.retain(|s| s.point != point);
    drawing.springs.retain(|s| s.a != point && s.b != point);
    drawing.dampers.retain(|d| d.a != point && d.b != point);
    drawing.forces.retain(|f| f.point != point);
    for link in &mut drawing.links {
        link.points.retain(|&p| p != point);
    }
    let short: Vec<usize> = (0..drawing.links.len())
        .filter(|&l| drawing.links[l].points.len() < 2)
        .collect();
    for l in short.into_iter().rev() {
        remove_link(drawing, l);
    }
    remove_point(drawing, point);
}

/// Removes a link, then the moving points no link or slider holds any more.
fn delete_link(drawing: &mut Drawing, link: usize) {
    remove_link(drawing, link);
    let held = |s: &Drawing, p: usize| {
        s.points[p].ground
            || s.links.iter().any(|l| l.points.contains(&p))
            || s.sliders.iter().any(|sl| sl.point == p)
    };
    for p in (0..drawing.points.len()).rev() {
        if !held(drawing, p) {
            delete_point(drawing, p);
        }
    }
}

/// Removes link `link`, renumbering the driver, the output and the guides.
fn remove_link(drawing: &mut Drawing, link: usize) {
    drawing.links.remove(link);
    let shift = |l: Option<usize>| match l {
        Some(l) if l == link => None,
        Some(l) if l > link => Some(l - 1),
        other => other,
    };
    drawing.driver = shift(drawing.driver);
    drawing.output = shift(drawing.output);
    drawing.sliders.retain(|s| s.guide != Some(link));
    for s in &mut drawing.sliders {
        s.guide = shift(s.guide);
    }
}

/// Removes point `point` (no link or slider may hold it), renumbering the rest.
fn remove_point(drawing: &mut Drawing, point: usize) {
    drawing.points.remove(point);
    let shift = |p: &mut usize| {
        if *p > point {
            *p -= 1;
        }
    };
    for link in &mut drawing.links {
        link.points.iter_mut().for_each(shift);
    }
    for s in &mut drawing.sliders {
        shift(&mut s.point);
    }
    for s in &mut drawing.springs {
        shift(&mut s.a);
        shift(&mut s.b);
    }
    for d in &mut drawing.dampers {
        shift(&mut d.a);
        shift(&mut d.b);
    }
    for f in &mut drawing.forces {
        shift(&mut f.point);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(x: f64, y: f64) -> Vec2 {
        Vec2::new(x, y)
    }

    #[test]
    fn a_four_bar_drawn_edit_by_edit_has_one_degree_of_freedom() {
        let mut s = Drawing::new("drawn");
        for edit in [
            DrawingEdit::AddPivot(at(0.0, 0.0)),
            DrawingEdit::AddPivot(at(0.3, 0.0)),
            DrawingEdit::AddLink(End::Point(0), End::New(at(0.0, 0.1))),
            DrawingEdit::AddLink(End::Point(2), End::New(at(0.2, 0.3))),
            DrawingEdit::AddLink(End::Point(3), End::Point(1)),
            DrawingEdit::SetDriver(0),
        ] {
            s = apply(&s, edit).expect("applies");
        }
        let names: Vec<&str> = s.points.iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, ["A", "B", "C", "D"]);
        assert_eq!(s.mobility().dof(), 1);
        assert!(s.to_scene().is_ok());
        assert_eq!(
            apply(&s, DrawingEdit::AddLink(End::Point(2), End::Point(0))),
            Err(Refusal::AlreadyJoined("link 1".into()))
        );
        assert_eq!(
            apply(&s, DrawingEdit::SetDriver(1)),
            Err(Refusal::DriverNotGrounded("link 2".into()))
        );
    }

    #[test]
    fn an_inverted_slider_crank_drawn_with_a_guide_on_a_link() {
        // Crank A-B, rocker D-E with the block at B sliding along it.
        let mut s = Drawing::new("drawn");
        for edit in [
            DrawingEdit::AddPivot(at(0.0, 0.0)),
            DrawingEdit::AddPivot(at(0.2, 0.0)),
            DrawingEdit::AddLink(End::Point(0), End::New(at(0.0, 0.1))),
            DrawingEdit::AddLink(End::Point(1), End::New(at(-0.2, 0.2))),
            DrawingEdit::AddSlider {
                point: 2,
                angle_rad: 0.0,
            },
            DrawingEdit::SetDriver(0),
        ] {
            s = apply(&s, edit).expect("applies");
        }
        assert_eq!(
            apply(
                &s,
                DrawingEdit::SetGuide {
                    slider: 0,
                    guide: Some(0),
                    angle_rad: 0.0
                }
            ),
            Err(Refusal::GuideThroughPin("link 1".into()))
        );
        // The guide along the rocker D-E, through B as drawn.
        let (d, e) = (s.points[1].at, s.points[3].at);
        let along = (e.y - d.y).atan2(e.x - d.x);
        let guided = DrawingEdit::SetGuide {
            slider: 0,
            guide: Some(1),
            angle_rad: along,
        };
        s = apply(&s, guided).expect("applies");
        let scene = s.to_scene().expect("an inverted slider-crank");
        assert_eq!(scene.sliders[0].guide, "link 2");
        assert!(scene.links[2].points.contains_key("C guide"));
    }

    #[test]
    fn deleting_a_point_takes_its_links_and_renumbers_the_rest() {
        let mut s = Drawing::new("drawn");
        for edit in [
            DrawingEdit::AddPivot(at(0.0, 0.0)),
            DrawingEdit::AddLink(End::Point(0), End::New(at(0.1, 0.0))),
            DrawingEdit::AddLink(End::Point(1), End::New(at(0.2, 0.0))),
            DrawingEdit::AddSlider {
                point: 2,
                angle_rad: 0.0,
            },
            DrawingEdit::SetDriver(0),
        ] {
            s = apply(&s, edit).expect("applies");
        }
        // B goes: both links lose an end, and C is held only by its slider.
        let after = apply(&s, DrawingEdit::DeletePoint(1)).expect("applies");
        assert!(after.links.is_empty());
        assert_eq!(after.driver, None);
        assert_eq!(after.points.len(), 2);
        assert_eq!(after.sliders[0].point, 1);
        assert_eq!(after.points[1].name, "C");
        // Deleting the crank instead keeps B (the rod holds it).
        let after = apply(&s, DrawingEdit::DeleteLink(0)).expect("applies");
        assert_eq!(after.links.len(), 1);
        assert_eq!(after.links[0].points, [1, 2]);
        assert_eq!(after.driver, None);
    }

    #[test]
    fn a_drive_is_kept_when_valid_and_refused_by_its_field_when_not() {
        use linkage::scene::{DriveSpec, MotorSpec, Shaft};
        let s = Drawing::new("drawn");
        let mut drive = DriveSpec {
            motor: MotorSpec::Linear {
                no_load_rpm: 1500.0,
                rated_torque_n_m: 500.0,
                rated_rpm: 1450.0,
            },
            gear_ratio: 29.0,
            train: None,
            motor_inertia_kg_m2: 0.1,
            flywheel_kg_m2: 40.0,
            flywheel_on: Shaft::Motor,
        };
        let kept = apply(&s, DrawingEdit::SetDrive(Some(drive.clone()))).expect("valid");
        assert_eq!(kept.drive.as_ref(), Some(&drive));
        drive.gear_ratio = 0.0;
        let refused = apply(&kept, DrawingEdit::SetDrive(Some(drive))).expect_err("gear 0");
        assert!(
            refused.to_string().contains("drive.gear_ratio"),
            "{refused}"
        );
        let none = apply(&kept, DrawingEdit::SetDrive(None)).expect("removed");
        assert_eq!(none.drive, None);
    }
}
