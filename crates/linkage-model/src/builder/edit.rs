//! The edits a drawing takes, as values: the canvas turns clicks and drags into
//! these, and [`apply`] makes the next drawing from them, or says why not.

use linkage::Vec2;
use linkage::sketch::{Sketch, SketchLink, SketchPoint, SketchSlider};

use super::sketch_edit::finite;
pub use super::sketch_edit::{Body, Element, End, Named, Refusal, SketchEdit};

/// The drawing after `edit`, or why it is refused (`sketch` is left as it was).
pub fn apply(sketch: &Sketch, edit: SketchEdit) -> Result<Sketch, Refusal> {
    let mut next = sketch.clone();
    match edit {
        SketchEdit::AddPivot(at) => {
            finite(at)?;
            add_point(&mut next, at, true);
        }
        SketchEdit::SetGround { point, ground } => next.points[point].ground = ground,
        SketchEdit::AddLink(a, b) => add_link(&mut next, a, b)?,
        SketchEdit::AddPointToLink { link, end } => add_point_to_link(&mut next, link, end)?,
        SketchEdit::AddSlider { point, angle_rad } => add_slider(&mut next, point, angle_rad)?,
        SketchEdit::SetGuide {
            slider,
            guide,
            angle_rad,
        } => set_guide(&mut next, slider, guide, angle_rad)?,
        SketchEdit::SetDriver(link) => set_driver(&mut next, link)?,
        SketchEdit::MovePoint { point, to } => {
            finite(to)?;
            next.points[point].at = to;
        }
        SketchEdit::DeletePoint(point) => delete_point(&mut next, point),
        SketchEdit::DeleteLink(link) => delete_link(&mut next, link),
        SketchEdit::Rename(what, name) => rename(&mut next, what, name)?,
        SketchEdit::SetSpeedRpm(rpm) => {
            if !(rpm.is_finite() && rpm != 0.0) {
                return Err(Refusal::Speed(rpm));
            }
            next.speed = linkage::scene::Speed::Rpm(rpm);
        }
        SketchEdit::SetOutput(link) => next.output = link,
        SketchEdit::SetModels(models) => next.models = models,
        SketchEdit::SetGravity(on) => next.gravity = on,
        SketchEdit::AddSpring(..)
        | SketchEdit::AddDamper(..)
        | SketchEdit::AddForce(_)
        | SketchEdit::SetSpring { .. }
        | SketchEdit::SetDamper { .. }
        | SketchEdit::SetForce { .. }
        | SketchEdit::DeleteElement(_)
        | SketchEdit::SetBody { .. } => super::loads::apply(&mut next, edit)?,
        SketchEdit::SetMass(body, kg) => set_mass(&mut next, body, kg)?,
    }
    Ok(next)
}

/// Joins point `end` (drawn or new) to `link`.
fn add_point_to_link(next: &mut Sketch, link: usize, end: End) -> Result<(), Refusal> {
    let p = resolve(next, end)?;
    if next.links[link].points.contains(&p) {
        return Err(Refusal::AlreadyJoined(next.links[link].name.clone()));
    }
    next.links[link].points.push(p);
    Ok(())
}

/// A slider block at `point`, its guide not yet chosen.
fn add_slider(next: &mut Sketch, point: usize, angle_rad: f64) -> Result<(), Refusal> {
    if next.sliders.iter().any(|s| s.point == point) {
        return Err(Refusal::AlreadySlider(next.points[point].name.clone()));
    }
    next.sliders.push(SketchSlider {
        point,
        guide: None,
        angle_rad,
        mass_kg: None,
    });
    Ok(())
}

/// The slider's guide (a link not through its own pin; `None`: ground) and angle.
fn set_guide(
    next: &mut Sketch,
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
fn set_driver(next: &mut Sketch, link: usize) -> Result<(), Refusal> {
    let l = &next.links[link];
    if !l.points.iter().any(|&p| next.points[p].ground) {
        return Err(Refusal::DriverNotGrounded(l.name.clone()));
    }
    next.driver = Some(link);
    Ok(())
}

/// A link's or a block's mass (`None`: none), kg, finite and positive.
fn set_mass(next: &mut Sketch, body: Body, kg: Option<f64>) -> Result<(), Refusal> {
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
fn next_point_name(sketch: &Sketch) -> String {
    (0..)
        .map(|i: usize| {
            let letter = char::from(b'A' + (i % 26) as u8);
            match i / 26 {
                0 => letter.to_string(),
                round => format!("{letter}{round}"),
            }
        })
        .find(|name| sketch.points.iter().all(|p| &p.name != name))
        .unwrap_or_default()
}

/// The first unused `link N`.
fn next_link_name(sketch: &Sketch) -> String {
    (1..)
        .map(|i: usize| format!("link {i}"))
        .find(|name| sketch.links.iter().all(|l| &l.name != name))
        .unwrap_or_default()
}

fn add_point(sketch: &mut Sketch, at: Vec2, ground: bool) -> usize {
    let name = next_point_name(sketch);
    sketch.points.push(SketchPoint { name, at, ground });
    sketch.points.len() - 1
}

fn resolve(sketch: &mut Sketch, end: End) -> Result<usize, Refusal> {
    match end {
        End::Point(p) => Ok(p),
        End::New(at) => {
            finite(at)?;
            Ok(add_point(sketch, at, false))
        }
    }
}

fn add_link(sketch: &mut Sketch, a: End, b: End) -> Result<(), Refusal> {
    if a == b {
        return Err(Refusal::SameEnds);
    }
    if let (End::Point(p), End::Point(q)) = (a, b)
        && let Some(l) = sketch
            .links
            .iter()
            .find(|l| l.points.contains(&p) && l.points.contains(&q))
    {
        return Err(Refusal::AlreadyJoined(l.name.clone()));
    }
    let p = resolve(sketch, a)?;
    let q = resolve(sketch, b)?;
    let name = next_link_name(sketch);
    sketch.links.push(SketchLink::new(&name, vec![p, q]));
    Ok(())
}

/// Renames a point or a link; names are unique among points and among links (a
/// slider's block and guide point take theirs from its pin: "slider C", "C guide").
fn rename(sketch: &mut Sketch, what: Named, name: String) -> Result<(), Refusal> {
    let name = name.trim().to_owned();
    let taken = match what {
        Named::Point(p) => sketch
            .points
            .iter()
            .enumerate()
            .any(|(i, q)| i != p && q.name == name),
        Named::Link(l) => {
            name == "ground"
                || sketch
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
        Named::Point(p) => sketch.points[p].name = name,
        Named::Link(l) => sketch.links[l].name = name,
    }
    Ok(())
}

/// Removes a point; links left with one point go, and so do its sliders and the
/// force elements at it.
fn delete_point(sketch: &mut Sketch, point: usize) {
    sketch.sliders.retain(|s| s.point != point);
    sketch.springs.retain(|s| s.a != point && s.b != point);
    sketch.dampers.retain(|d| d.a != point && d.b != point);
    sketch.forces.retain(|f| f.point != point);
    for link in &mut sketch.links {
        link.points.retain(|&p| p != point);
    }
    let short: Vec<usize> = (0..sketch.links.len())
        .filter(|&l| sketch.links[l].points.len() < 2)
        .collect();
    for l in short.into_iter().rev() {
        remove_link(sketch, l);
    }
    remove_point(sketch, point);
}

/// Removes a link, then the moving points no link or slider holds any more.
fn delete_link(sketch: &mut Sketch, link: usize) {
    remove_link(sketch, link);
    let held = |s: &Sketch, p: usize| {
        s.points[p].ground
            || s.links.iter().any(|l| l.points.contains(&p))
            || s.sliders.iter().any(|sl| sl.point == p)
    };
    for p in (0..sketch.points.len()).rev() {
        if !held(sketch, p) {
            delete_point(sketch, p);
        }
    }
}

/// Removes link `link`, renumbering the driver, the output and the guides.
fn remove_link(sketch: &mut Sketch, link: usize) {
    sketch.links.remove(link);
    let shift = |l: Option<usize>| match l {
        Some(l) if l == link => None,
        Some(l) if l > link => Some(l - 1),
        other => other,
    };
    sketch.driver = shift(sketch.driver);
    sketch.output = shift(sketch.output);
    sketch.sliders.retain(|s| s.guide != Some(link));
    for s in &mut sketch.sliders {
        s.guide = shift(s.guide);
    }
}

/// Removes point `point` (no link or slider may hold it), renumbering the rest.
fn remove_point(sketch: &mut Sketch, point: usize) {
    sketch.points.remove(point);
    let shift = |p: &mut usize| {
        if *p > point {
            *p -= 1;
        }
    };
    for link in &mut sketch.links {
        link.points.iter_mut().for_each(shift);
    }
    for s in &mut sketch.sliders {
        shift(&mut s.point);
    }
    for s in &mut sketch.springs {
        shift(&mut s.a);
        shift(&mut s.b);
    }
    for d in &mut sketch.dampers {
        shift(&mut d.a);
        shift(&mut d.b);
    }
    for f in &mut sketch.forces {
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
        let mut s = Sketch::new("drawn");
        for edit in [
            SketchEdit::AddPivot(at(0.0, 0.0)),
            SketchEdit::AddPivot(at(0.3, 0.0)),
            SketchEdit::AddLink(End::Point(0), End::New(at(0.0, 0.1))),
            SketchEdit::AddLink(End::Point(2), End::New(at(0.2, 0.3))),
            SketchEdit::AddLink(End::Point(3), End::Point(1)),
            SketchEdit::SetDriver(0),
        ] {
            s = apply(&s, edit).expect("applies");
        }
        let names: Vec<&str> = s.points.iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, ["A", "B", "C", "D"]);
        assert_eq!(s.mobility().dof(), 1);
        assert!(s.to_scene().is_ok());
        assert_eq!(
            apply(&s, SketchEdit::AddLink(End::Point(2), End::Point(0))),
            Err(Refusal::AlreadyJoined("link 1".into()))
        );
        assert_eq!(
            apply(&s, SketchEdit::SetDriver(1)),
            Err(Refusal::DriverNotGrounded("link 2".into()))
        );
    }

    #[test]
    fn an_inverted_slider_crank_drawn_with_a_guide_on_a_link() {
        // Crank A-B, rocker D-E with the block at B sliding along it.
        let mut s = Sketch::new("drawn");
        for edit in [
            SketchEdit::AddPivot(at(0.0, 0.0)),
            SketchEdit::AddPivot(at(0.2, 0.0)),
            SketchEdit::AddLink(End::Point(0), End::New(at(0.0, 0.1))),
            SketchEdit::AddLink(End::Point(1), End::New(at(-0.2, 0.2))),
            SketchEdit::AddSlider {
                point: 2,
                angle_rad: 0.0,
            },
            SketchEdit::SetDriver(0),
        ] {
            s = apply(&s, edit).expect("applies");
        }
        assert_eq!(
            apply(
                &s,
                SketchEdit::SetGuide {
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
        let guided = SketchEdit::SetGuide {
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
        let mut s = Sketch::new("drawn");
        for edit in [
            SketchEdit::AddPivot(at(0.0, 0.0)),
            SketchEdit::AddLink(End::Point(0), End::New(at(0.1, 0.0))),
            SketchEdit::AddLink(End::Point(1), End::New(at(0.2, 0.0))),
            SketchEdit::AddSlider {
                point: 2,
                angle_rad: 0.0,
            },
            SketchEdit::SetDriver(0),
        ] {
            s = apply(&s, edit).expect("applies");
        }
        // B goes: both links lose an end, and C is held only by its slider.
        let after = apply(&s, SketchEdit::DeletePoint(1)).expect("applies");
        assert!(after.links.is_empty());
        assert_eq!(after.driver, None);
        assert_eq!(after.points.len(), 2);
        assert_eq!(after.sliders[0].point, 1);
        assert_eq!(after.points[1].name, "C");
        // Deleting the crank instead keeps B (the rod holds it).
        let after = apply(&s, SketchEdit::DeleteLink(0)).expect("applies");
        assert_eq!(after.links.len(), 1);
        assert_eq!(after.links[0].points, [1, 2]);
        assert_eq!(after.driver, None);
    }
}
