//! The edits of a drawing's loads and bodies: springs, dampers and point forces
//! placed, set and removed, and a link's own centroid and inertia. Split from
//! [`super::edit`], which dispatches them here.

use linkage::Vec2;
use linkage::drawing::{Drawing, DrawingDamper, DrawingForce, DrawingSpring};
use linkage::scene::ForceWhen;

use super::drawing_edit::{DrawingEdit, Element, Refusal, finite};

/// Stiffness of a new spring, N/m.
pub const NEW_SPRING_N_PER_M: f64 = 1000.0;
/// Coefficient of a new damper, N·s/m.
pub const NEW_DAMPER_N_S_PER_M: f64 = 10.0;
/// A new point force, N: 100 N down the drawing.
pub const NEW_FORCE_N: [f64; 2] = [0.0, -100.0];

/// Applies a load or body edit to `next`; other edits change nothing.
///
/// # Errors
/// Two ends at one point, or a number that is not finite or is negative.
pub(super) fn apply(next: &mut Drawing, edit: DrawingEdit) -> Result<(), Refusal> {
    match edit {
        DrawingEdit::AddSpring(a, b) => {
            two_points(a, b)?;
            next.springs.push(DrawingSpring {
                a,
                b,
                k_n_per_m: NEW_SPRING_N_PER_M,
                free_length_m: None,
            });
        }
        DrawingEdit::AddDamper(a, b) => {
            two_points(a, b)?;
            next.dampers.push(DrawingDamper {
                a,
                b,
                c_n_s_per_m: NEW_DAMPER_N_S_PER_M,
            });
        }
        DrawingEdit::AddForce(point) => next.forces.push(DrawingForce {
            point,
            force_n: Vec2::new(NEW_FORCE_N[0], NEW_FORCE_N[1]),
            when: ForceWhen::Always,
        }),
        DrawingEdit::SetSpring {
            spring,
            k_n_per_m,
            free_length_m,
        } => {
            coefficient(k_n_per_m)?;
            free_length_m.map(coefficient).transpose()?;
            let s = &mut next.springs[spring];
            (s.k_n_per_m, s.free_length_m) = (k_n_per_m, free_length_m);
        }
        DrawingEdit::SetDamper {
            damper,
            c_n_s_per_m,
        } => next.dampers[damper].c_n_s_per_m = coefficient(c_n_s_per_m)?,
        DrawingEdit::SetForce {
            force,
            force_n,
            when,
        } => {
            finite(force_n)?;
            (next.forces[force].force_n, next.forces[force].when) = (force_n, when);
        }
        DrawingEdit::SetBody {
            link,
            centroid,
            inertia_kg_m2,
        } => {
            centroid.map(finite).transpose()?;
            inertia_kg_m2.map(coefficient).transpose()?;
            let l = &mut next.links[link];
            (l.centroid, l.inertia_kg_m2) = (centroid, inertia_kg_m2);
        }
        DrawingEdit::DeleteElement(element) => match element {
            Element::Spring(i) => drop(next.springs.remove(i)),
            Element::Damper(i) => drop(next.dampers.remove(i)),
            Element::Force(i) => drop(next.forces.remove(i)),
        },
        _ => {}
    }
    Ok(())
}

fn two_points(a: usize, b: usize) -> Result<(), Refusal> {
    if a == b {
        Err(Refusal::SameEnds)
    } else {
        Ok(())
    }
}

/// `v` if it is a finite number >= 0.
fn coefficient(v: f64) -> Result<f64, Refusal> {
    if v.is_finite() && v >= 0.0 {
        Ok(v)
    } else {
        Err(Refusal::Coefficient(v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drawing::edit::{End, apply as apply_edit};

    fn at(x: f64, y: f64) -> Vec2 {
        Vec2::new(x, y)
    }

    fn apply(s: &Drawing, edit: DrawingEdit) -> Result<Drawing, Refusal> {
        apply_edit(s, edit)
    }

    #[test]
    fn force_elements_follow_their_points_and_refuse_bad_numbers() {
        let mut s = Drawing::new("loads");
        for edit in [
            DrawingEdit::AddPivot(at(0.0, 0.0)),
            DrawingEdit::AddPivot(at(0.3, 0.0)),
            DrawingEdit::AddLink(End::Point(0), End::New(at(0.0, 0.1))),
            DrawingEdit::AddSpring(2, 1),
            DrawingEdit::AddDamper(0, 2),
            DrawingEdit::AddForce(2),
            DrawingEdit::AddForce(1),
        ] {
            s = apply(&s, edit).expect("applies");
        }
        assert_eq!(
            apply(&s, DrawingEdit::AddSpring(1, 1)),
            Err(Refusal::SameEnds)
        );
        for bad in [-1.0, f64::NAN, f64::INFINITY] {
            let spring = DrawingEdit::SetSpring {
                spring: 0,
                k_n_per_m: bad,
                free_length_m: None,
            };
            assert!(
                matches!(apply(&s, spring), Err(Refusal::Coefficient(_))),
                "{bad}"
            );
        }
        let body = |centroid, inertia_kg_m2| DrawingEdit::SetBody {
            link: 0,
            centroid,
            inertia_kg_m2,
        };
        assert!(apply(&s, body(Some(at(f64::NAN, 0.0)), None)).is_err());
        assert!(apply(&s, body(None, Some(-1.0))).is_err());
        let own = apply(&s, body(Some(at(0.0, 0.05)), Some(0.2))).expect("applies");
        assert_eq!(own.links[0].centroid, Some(at(0.0, 0.05)));
        // Deleting the first pivot takes the damper at it; the rest are renumbered.
        let after = apply(&s, DrawingEdit::DeletePoint(0)).expect("applies");
        assert!(after.dampers.is_empty());
        assert_eq!((after.springs[0].a, after.springs[0].b), (1, 0));
        let at_points: Vec<usize> = after.forces.iter().map(|f| f.point).collect();
        assert_eq!(at_points, [1, 0]);
        let after = apply(&after, DrawingEdit::DeleteElement(Element::Force(0))).expect("applies");
        assert_eq!(after.forces.len(), 1);
    }
}
