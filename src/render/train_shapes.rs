//! A gear train's schematic as the GPU draws it (the gear lab's train view): each
//! shaft a line (a hollow one two), each gear and pulley a block in its member's
//! colour, an internal gear's teeth outside its pitch line with its cup, a
//! carrier's arm out to its planets' pins, belt runs solid and chain runs dashed,
//! a member held still hatched to the frame at its free end. Each block carries
//! stripes that slide as its member turns (a turning cylinder seen from the side),
//! so every member is seen to turn at its own speed.

use glam::Vec2;
use linkage::gears::train_file::StageKind;
use linkage_diagram::train_schematic::{Block, MemberLine, Schematic, StageRun};

use super::shape::{Kind, Shape};
use super::view::Camera;

/// Stripes round a block's circumference (half of them seen at a time).
const STRIPES: usize = 10;
const EDGE: [f32; 4] = [0.2, 0.2, 0.24, 1.0];
const SHAFT: [f32; 4] = [0.15, 0.15, 0.18, 1.0];
const FRAME: [f32; 4] = [0.45, 0.45, 0.45, 1.0];

/// The members' colours, in the file's order (repeating): the names on the canvas
/// and in the panel's table are written in them.
pub const MEMBER_COLOURS: [[f32; 4]; 6] = [
    [0.85, 0.55, 0.25, 1.0],
    [0.35, 0.58, 0.82, 1.0],
    [0.45, 0.70, 0.40, 1.0],
    [0.78, 0.45, 0.70, 1.0],
    [0.80, 0.72, 0.30, 1.0],
    [0.45, 0.72, 0.72, 1.0],
];

/// A member's colour.
pub fn member_colour(member: usize) -> [f32; 4] {
    MEMBER_COLOURS[member % MEMBER_COLOURS.len()]
}

/// Thin lines' half width, m of the schematic, for the camera's scale.
fn line_width(camera: &Camera) -> f32 {
    (0.6 / camera.points_per_m.max(1e-12)) as f32
}

/// The schematic's shapes in `list`; `angles` every member's turn (rad), `held`
/// whether each member stands still (a brake: hatched to the frame).
pub fn build_train(
    list: &mut Vec<Shape>,
    s: &Schematic,
    angles: &[f64],
    held: &[bool],
    camera: &Camera,
) {
    list.clear();
    let line = line_width(camera);
    let mut push = |shape: Option<Shape>| list.extend(shape);
    let at = |p: [f64; 2]| camera.local(p);
    for run in &s.runs {
        stage_run(&mut push, run, s.unit, line, &at);
    }
    for l in &s.members {
        shaft(&mut push, l, s, line, &at);
    }
    for arm in &s.arms {
        let hub = arm.hub;
        for pin in &arm.pins {
            let corner = [hub[0], pin[1]];
            for (a, b) in [(hub, corner), (corner, *pin)] {
                segment(&mut push, at(a), at(b), 2.0 * line, SHAFT);
            }
        }
    }
    for b in &s.blocks {
        let angle = angles.get(b.member).copied().unwrap_or(0.0);
        block(&mut push, b, angle, s.unit, line, &at);
        if held.get(b.member).copied().unwrap_or(false) {
            frame_hatch(&mut push, b, s.unit, line, &at);
        }
    }
    for arm in &s.arms {
        for pin in &arm.pins {
            let p = at(*pin);
            push(Shape::new(
                Kind::Pin,
                [p; 3],
                3.0 * line,
                super::drawn::colour::PIN,
                [0.0; 2],
            ));
        }
    }
}

fn segment(push: &mut impl FnMut(Option<Shape>), a: Vec2, b: Vec2, width: f32, colour: [f32; 4]) {
    push(Shape::new(Kind::Line, [a, b, a], width, colour, [0.0; 2]));
}

/// A rectangle filled and edged, corners `lo` and `hi`.
fn rect(push: &mut impl FnMut(Option<Shape>), lo: Vec2, hi: Vec2, fill: [f32; 4], line: f32) {
    let (a, b, c, d) = (lo, Vec2::new(hi.x, lo.y), hi, Vec2::new(lo.x, hi.y));
    // Grown by half a line, so that the two halves meet without a seam.
    push(Shape::new(
        Kind::Fill,
        [a, b, c],
        0.5 * line,
        fill,
        [0.0; 2],
    ));
    push(Shape::new(
        Kind::Fill,
        [a, c, d],
        0.5 * line,
        fill,
        [0.0; 2],
    ));
    for (p, q) in [(a, b), (b, c), (c, d), (d, a)] {
        segment(push, p, q, line, EDGE);
    }
}

/// A shaft: one thick line, or two for a hollow one; a planet's pin at each of its
/// copies.
fn shaft(
    push: &mut impl FnMut(Option<Shape>),
    l: &MemberLine,
    s: &Schematic,
    line: f32,
    at: &impl Fn([f64; 2]) -> Vec2,
) {
    let heights: Vec<f64> = if l.on_carrier {
        s.blocks
            .iter()
            .find(|b| b.member == l.member)
            .map_or_else(|| vec![l.y], |b| b.centres_y.clone())
    } else {
        vec![l.y]
    };
    for y in heights {
        if l.hollow {
            for dy in [-0.45 * s.unit, 0.45 * s.unit] {
                segment(
                    push,
                    at([l.x[0], y + dy]),
                    at([l.x[1], y + dy]),
                    line,
                    SHAFT,
                );
            }
        } else {
            segment(push, at([l.x[0], y]), at([l.x[1], y]), 2.0 * line, SHAFT);
        }
    }
}

/// A member held still (a brake): its block fixed to the frame, a base line along
/// its outer edge hatched outwards, as the textbooks draw a gear fixed to the
/// housing.
fn frame_hatch(
    push: &mut impl FnMut(Option<Shape>),
    b: &Block,
    unit: f64,
    line: f32,
    at: &impl Fn([f64; 2]) -> Vec2,
) {
    let yc = b.centres_y[0];
    // A ring's teeth are drawn above and below its axis: both fixed, hatched
    // outwards; a gear's block along its top.
    let edges: &[(f64, f64)] = if b.internal {
        &[(yc + b.radius + unit, 1.0), (yc - b.radius - unit, -1.0)]
    } else {
        &[(yc + b.radius, 1.0)]
    };
    let (x0, x1) = (
        b.x - b.half_width - 0.5 * unit,
        b.x + b.half_width + 0.5 * unit,
    );
    for &(edge, out) in edges {
        segment(push, at([x0, edge]), at([x1, edge]), 1.5 * line, FRAME);
        let steps = 5;
        for k in 0..steps {
            let x = x0 + (x1 - x0) * f64::from(k) / f64::from(steps - 1);
            let tip = [x + 0.6 * unit, edge + out * 0.8 * unit];
            segment(push, at([x, edge]), at(tip), line, FRAME);
        }
    }
}

/// A gear or pulley: its block (an internal gear's teeth outside its pitch line,
/// with the cup to its hub), and the stripes of its turn.
fn block(
    push: &mut impl FnMut(Option<Shape>),
    b: &Block,
    angle: f64,
    unit: f64,
    line: f32,
    at: &impl Fn([f64; 2]) -> Vec2,
) {
    let fill = member_colour(b.member);
    let hw = b.half_width;
    for &yc in &b.centres_y {
        if b.internal {
            let (r, t) = (b.radius, unit);
            for (lo, hi) in [(yc + r, yc + r + t), (yc - r - t, yc - r)] {
                rect(push, at([b.x - hw, lo]), at([b.x + hw, hi]), fill, line);
            }
            let mid = r + 0.5 * t;
            for side in [-1.0, 1.0] {
                let y = yc + side * mid;
                segment(push, at([b.x + hw, y]), at([b.hub_x, y]), 2.0 * line, SHAFT);
            }
            segment(
                push,
                at([b.hub_x, yc - mid]),
                at([b.hub_x, yc + mid]),
                2.0 * line,
                SHAFT,
            );
            stripes(push, [b.hub_x, yc], mid, 0.6 * hw, angle, line, &at);
        } else {
            let (lo, hi) = (at([b.x - hw, yc - b.radius]), at([b.x + hw, yc + b.radius]));
            rect(push, lo, hi, fill, line);
            stripes(push, [b.x, yc], b.radius, hw, angle, line, &at);
        }
    }
}

/// The stripes of a cylinder of `radius` about `centre` turned by `angle`, seen
/// from the side: each at height r·sin(θ) while its side faces the viewer
/// (cos θ > 0), so they slide one way as it turns.
fn stripes(
    push: &mut impl FnMut(Option<Shape>),
    [x, y]: [f64; 2],
    radius: f64,
    half_width: f64,
    angle: f64,
    line: f32,
    at: &impl Fn([f64; 2]) -> Vec2,
) {
    for k in 0..STRIPES {
        let theta = angle + std::f64::consts::TAU * k as f64 / STRIPES as f64;
        let (sin, cos) = theta.sin_cos();
        if cos <= 0.15 {
            continue;
        }
        let h = y + radius * sin;
        segment(
            push,
            at([x - half_width, h]),
            at([x + half_width, h]),
            line,
            EDGE,
        );
    }
}

/// A belt's run as its two strands (crossed: an X), a chain's dashed.
fn stage_run(
    push: &mut impl FnMut(Option<Shape>),
    run: &StageRun,
    unit: f64,
    line: f32,
    at: &impl Fn([f64; 2]) -> Vec2,
) {
    let d = 0.5 * unit;
    let [y0, y1] = run.y;
    let strands = if run.crossed {
        [
            ([run.x - d, y0], [run.x + d, y1]),
            ([run.x + d, y0], [run.x - d, y1]),
        ]
    } else {
        [
            ([run.x - d, y0], [run.x - d, y1]),
            ([run.x + d, y0], [run.x + d, y1]),
        ]
    };
    for (a, b) in strands {
        let (a, b) = (at(a), at(b));
        match run.kind {
            StageKind::Belt => segment(push, a, b, 1.5 * line, SHAFT),
            StageKind::Chain => push(Shape::new(
                Kind::Dash,
                [a, b, a],
                1.5 * line,
                SHAFT,
                [(0.6 * unit) as f32, 0.0],
            )),
        }
    }
}
