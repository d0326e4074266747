//! The shapes of a drawing being built: ground pivots, links as bars and plates (the
//! input link in its own colour), slider blocks on their guide lines, and pins. Sizes
//! are in screen points, since a drawing starts with no size of its own.

use glam::Vec2;
use linkage::sketch::Sketch;

use super::build::{colour, ground_pivot};
use super::shape::{Kind, Shape};
use super::view::Camera;

/// Half width of a bar, points.
const BAR_PT: f32 = 3.5;
/// Pin radius, points.
const PIN_PT: f32 = 5.0;

/// Fills `out` with the drawing's shapes; `marked`: a point drawn larger (the first
/// end of a link being drawn, or the point being dragged).
pub fn build_sketch(out: &mut Vec<Shape>, sketch: &Sketch, cam: &Camera, marked: Option<usize>) {
    out.clear();
    let m_per_pt = (1.0 / cam.points_per_m) as f32;
    let (bar, pin) = (BAR_PT * m_per_pt, PIN_PT * m_per_pt);
    let pos = |p: usize| {
        let q = sketch.points[p].at;
        cam.local([q.x, q.y])
    };
    let mut push = |shape: Option<Shape>| out.extend(shape);
    for (p, point) in sketch.points.iter().enumerate() {
        if point.ground {
            ground_pivot(&mut push, pos(p), pin, bar);
        }
    }
    for s in &sketch.sliders {
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
    for (l, link) in sketch.links.iter().enumerate() {
        let colour = if sketch.driver == Some(l) {
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
    for p in 0..sketch.points.len() {
        let c = pos(p);
        push(Shape::new(Kind::Pin, [c, c, c], pin, colour::PIN, [0.0; 2]));
    }
    if let Some(p) = marked.filter(|&p| p < sketch.points.len()) {
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
