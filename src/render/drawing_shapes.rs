//! The shapes of a drawing being built: ground pivots, links as bars and plates (the
//! input link in its own colour), slider blocks on their guide lines, and pins. Sizes
//! are in screen points, since a drawing starts with no size of its own.

use glam::Vec2;
use linkage::drawing::Drawing;

use super::build::{coil, ground_pivot};
use super::drawn::colour;
use super::shape::{Kind, Shape};
use super::view::Camera;

/// Half width of a bar, points.
const BAR_PT: f32 = 3.5;
/// Pin radius, points.
const PIN_PT: f32 = 5.0;

/// Fills `out` with the drawing's shapes; `marked`: a point drawn larger (the first
/// end of a link being drawn, or the point being dragged).
pub fn build_drawing(out: &mut Vec<Shape>, drawing: &Drawing, cam: &Camera, marked: Option<usize>) {
    out.clear();
    let m_per_pt = (1.0 / cam.points_per_m) as f32;
    let (bar, pin) = (BAR_PT * m_per_pt, PIN_PT * m_per_pt);
    let pos = |p: usize| {
        let q = drawing.points[p].at;
        cam.local([q.x, q.y])
    };
    let mut push = |shape: Option<Shape>| out.extend(shape);
    for (p, point) in drawing.points.iter().enumerate() {
        if point.ground {
            ground_pivot(&mut push, pos(p), pin, bar);
        }
    }
    slider_blocks(&mut push, drawing, &pos, bar, pin);
    links(&mut push, drawing, &pos, bar);
    force_elements(&mut push, drawing, &pos, bar, pin);
    for p in 0..drawing.points.len() {
        let c = pos(p);
        push(Shape::new(Kind::Pin, [c, c, c], pin, colour::PIN, [0.0; 2]));
    }
    if let Some(p) = marked.filter(|&p| p < drawing.points.len()) {
        let c = pos(p);
        push(Shape::new(
            Kind::Pin,
            [c, c, c],
            1.6 * pin,
            colour::MARK,
            [0.0; 2],
        ));
    }
}

/// Each slider's block on a short rail along its guide's angle.
fn slider_blocks(
    push: &mut impl FnMut(Option<Shape>),
    drawing: &Drawing,
    pos: &impl Fn(usize) -> Vec2,
    bar: f32,
    pin: f32,
) {
    for s in &drawing.sliders {
        let c = pos(s.point);
        let d = Vec2::new(s.angle_rad.cos() as f32, s.angle_rad.sin() as f32);
        let reach = d * 12.0 * pin;
        push(Shape::new(
            Kind::Line,
            [c - reach, c + reach, c],
            0.3 * bar,
            colour::GROUND,
            [0.0; 2],
        ));
        push(Shape::new(
            Kind::Block,
            [c, c + d, c],
            0.2 * bar,
            colour::BLOCK,
            [2.4 * pin, 1.5 * pin],
        ));
    }
}

/// Links: bars, and plates for three or more points (with bars to the rest).
fn links(
    push: &mut impl FnMut(Option<Shape>),
    drawing: &Drawing,
    pos: &impl Fn(usize) -> Vec2,
    bar: f32,
) {
    for (l, link) in drawing.links.iter().enumerate() {
        let colour = if drawing.driver == Some(l) {
            colour::DRIVER
        } else {
            colour::LINK
        };
        match *link.points.as_slice() {
            [a, b] => push(Shape::new(
                Kind::Bar,
                [pos(a), pos(b), pos(a)],
                bar,
                colour,
                [0.0; 2],
            )),
            [a, b, c, ..] => {
                push(Shape::new(
                    Kind::Plate,
                    [pos(a), pos(b), pos(c)],
                    bar,
                    colour::PLATE,
                    [0.0; 2],
                ));
                for &d in &link.points[3..] {
                    push(Shape::new(
                        Kind::Bar,
                        [pos(a), pos(d), pos(a)],
                        bar,
                        colour::PLATE,
                        [0.0; 2],
                    ));
                }
            }
            _ => {}
        }
    }
}

/// Springs as coils, dampers as a rod through a cylinder, and point forces as arrows
/// of one length (in points) pointing at their point.
fn force_elements(
    push: &mut impl FnMut(Option<Shape>),
    drawing: &Drawing,
    pos: &impl Fn(usize) -> Vec2,
    bar: f32,
    pin: f32,
) {
    for s in &drawing.springs {
        push(coil(pos(s.a), pos(s.b), bar, pin));
    }
    for d in &drawing.dampers {
        let (a, b) = (pos(d.a), pos(d.b));
        let mid = 0.5 * (a + b);
        push(Shape::new(
            Kind::Line,
            [a, b, a],
            0.3 * bar,
            colour::SPRING,
            [0.0; 2],
        ));
        push(Shape::new(
            Kind::Block,
            [mid, mid + (b - a).normalize_or_zero(), mid],
            0.2 * bar,
            colour::SPRING,
            [2.0 * pin, 0.8 * pin],
        ));
    }
    for f in &drawing.forces {
        let tip = pos(f.point);
        let d = Vec2::new(f.force_n.x as f32, f.force_n.y as f32).normalize_or_zero();
        // 8 pins long, ending at the pin's edge.
        let (from, to) = (tip - d * 9.0 * pin, tip - d * pin);
        push(Shape::new(
            Kind::Arrow,
            [from, to, from],
            0.3 * bar,
            colour::FORCE,
            [2.2 * pin, 0.0],
        ));
    }
}
