//! A gear pair in mesh as the GPU draws it (the gear lab's second view): both cut
//! gears filled and outlined, turned as [`MeshPose`] says, their working pitch circles
//! dashed and base circles dotted, the line of action between the base circles'
//! tangent points, the path of contact on it drawn thick, the points where teeth touch
//! now, and the centres.

use linkage::gears::{GearPair, MeshPose};

use super::drawn::colour;
use super::gear_shapes::{BASE, BLANK as PINION, LINE_OF_ACTION, PITCH, circle, fill_circle};
use super::shape::{Kind, Shape};
use super::view::Camera;

/// A marked point: a solid disc of 16 sides, not grown (a pin is drawn white with
/// a ring; a contact point wants to stand out).
const DOT: [f32; 2] = [16.0, 0.0];
const WHEEL: [f32; 4] = [0.66, 0.74, 0.82, 1.0];
const EDGE: [f32; 4] = [0.25, 0.25, 0.28, 1.0];

/// The box the pair's view frames, m: the whole pinion and as much of the wheel
/// again above the pitch point, so that the mesh (the line of action, the contacts)
/// is large, as the textbooks draw it.
pub fn pair_bounds(pair: &GearPair) -> [f64; 4] {
    let m = pair.pinion.spec.module_m;
    let half = pair.pinion.tip_radius_m + 2.0 * m;
    let pitch_point = pair.working_pitch_radii_m[0];
    [
        -half,
        -pair.pinion.tip_radius_m - m,
        half,
        pitch_point + half,
    ]
}

/// The pair's shapes in `list`: `outlines` are the pinion's and the wheel's cut
/// outlines about their own centres (unturned).
pub fn build_gear_pair(
    list: &mut Vec<Shape>,
    pair: &GearPair,
    pose: &MeshPose,
    outlines: [&[[f64; 2]]; 2],
    camera: &Camera,
) {
    list.clear();
    let line = (0.6 / camera.points_per_m.max(1e-9)) as f32;
    let mut push = |s: Option<Shape>| list.extend(s);
    let centres = [[0.0, 0.0], pose.wheel_centre_m];
    let turns = [pose.pinion_turn_rad, pose.wheel_turn_rad];
    for ((outline, centre), (turn, fill)) in outlines
        .iter()
        .zip(centres)
        .zip(turns.into_iter().zip([PINION, WHEEL]))
    {
        gear(&mut push, outline, centre, turn, camera, line, fill);
    }
    let [r1, r2] = pair.working_pitch_radii_m;
    for (centre, radius, colour, every) in [
        (centres[0], r1, PITCH, 2),
        (centres[1], r2, PITCH, 2),
        (centres[0], pair.pinion.base_radius_m, BASE, 1),
        (centres[1], pair.wheel.base_radius_m, BASE, 1),
    ] {
        circle(&mut push, camera.local(centre), radius, line, colour, every);
    }
    let [n1, n2] = pose.line_of_action_m.map(|p| camera.local(p));
    push(Shape::new(
        Kind::Line,
        [n1, n2, n1],
        line,
        LINE_OF_ACTION,
        [0.0; 2],
    ));
    let [b2, b1] = pose.path_of_contact_m.map(|p| camera.local(p));
    push(Shape::new(
        Kind::Line,
        [b2, b1, b2],
        2.5 * line,
        LINE_OF_ACTION,
        [0.0; 2],
    ));
    // The line of centres, and the ends of both lines and the pitch point marked.
    let (o1, o2) = (camera.local(centres[0]), camera.local(centres[1]));
    push(Shape::new(
        Kind::Line,
        [o1, o2, o1],
        0.6 * line,
        EDGE,
        [0.0; 2],
    ));
    for p in [n1, n2, b1, b2] {
        fill_circle(&mut push, p, f64::from(3.0 * line), LINE_OF_ACTION, DOT);
    }
    let pitch_point = camera.local([0.0, pair.working_pitch_radii_m[0]]);
    fill_circle(&mut push, pitch_point, f64::from(3.0 * line), EDGE, DOT);
    for c in &pose.contacts {
        fill_circle(
            &mut push,
            camera.local(*c),
            f64::from(7.0 * line),
            colour::PAST_LIMIT,
            DOT,
        );
    }
    for centre in centres {
        let p = camera.local(centre);
        push(Shape::new(
            Kind::Pin,
            [p; 3],
            4.0 * line,
            colour::PIN,
            [0.0; 2],
        ));
    }
}

/// One gear: its outline turned by `turn` about `centre`, filled as a fan from the
/// centre and edged.
fn gear(
    push: &mut impl FnMut(Option<Shape>),
    outline: &[[f64; 2]],
    centre: [f64; 2],
    turn: f64,
    camera: &Camera,
    line: f32,
    fill: [f32; 4],
) {
    let (s, c) = turn.sin_cos();
    let at =
        |[x, y]: [f64; 2]| camera.local([centre[0] + c * x - s * y, centre[1] + s * x + c * y]);
    let o = camera.local(centre);
    let n = outline.len();
    for i in 0..n {
        let (a, b) = (at(outline[i]), at(outline[(i + 1) % n]));
        push(Shape::new(Kind::Fill, [o, a, b], line, fill, [0.0; 2]));
    }
    for i in 0..n {
        let (a, b) = (at(outline[i]), at(outline[(i + 1) % n]));
        push(Shape::new(Kind::Line, [a, b, a], line, EDGE, [0.0; 2]));
    }
}
