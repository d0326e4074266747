//! Turns the session's current pose into the frame's shapes: ground and guides,
//! fading coupler traces, links as bars and plates, slider blocks, coil springs, pins
//! and the velocity and acceleration vectors. The list is cleared and refilled each
//! frame, so after the first frames it no longer allocates.

use glam::Vec2;

use super::cam_shapes::{cam_discs, rollers};
use super::drawn::{Drawn, colour};
use super::shape::{Kind, Shape};
use super::view::Camera;
use crate::session::Session;
use linkage::PointId;

/// What to draw besides the links.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layers {
    /// Velocity vectors at the joints.
    pub velocities: bool,
    /// Acceleration vectors at the joints.
    pub accelerations: bool,
    /// Coupler traces.
    pub traces: bool,
    /// Instant centres and their circle diagram.
    pub centres: bool,
}

impl Default for Layers {
    fn default() -> Self {
        Self {
            velocities: true,
            accelerations: false,
            traces: true,
            centres: false,
        }
    }
}

/// Scales of the drawn vectors, for the legend: metres of drawing per m/s and per m/s².
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct VectorScales {
    /// Drawing metres per m/s (0 when nothing moves).
    pub velocity: f64,
    /// Drawing metres per m/s² (0 when nothing accelerates).
    pub acceleration: f64,
}

/// A spring from `a` to `b` (view-local m), or none where not finite: a coil with a fixed number of turns, so
/// that it visibly stretches.
pub(super) fn coil(a: Vec2, b: Vec2, bar: f32, pin: f32) -> Option<Shape> {
    Shape::new(
        Kind::Spring,
        [a, b, a],
        0.25 * bar,
        colour::SPRING,
        [9.0, 1.1 * pin],
    )
}

/// A ground pivot at `c` (view-local m): a support triangle on a hatched base.
pub(super) fn ground_pivot(push: &mut impl FnMut(Option<Shape>), c: Vec2, pin: f32, bar: f32) {
    let (half, height) = (PIVOT_HALF_BASE as f32 * pin, PIVOT_HEIGHT as f32 * pin);
    let base_y = c.y - height;
    let (l, rgt) = (Vec2::new(c.x - half, base_y), Vec2::new(c.x + half, base_y));
    push(Shape::new(
        Kind::Ground,
        [c, l, rgt],
        0.25 * bar,
        colour::GROUND,
        [2.0 * PIVOT_HATCH as f32 * pin, 0.0],
    ));
    for side in [l, rgt] {
        push(Shape::new(
            Kind::Bar,
            [c, side, c],
            0.35 * bar,
            colour::GROUND,
            [0.0; 2],
        ));
    }
}

/// A pin's radius, as a share of the mechanism's size.
pub const PIN_SHARE: f64 = 0.024;
/// A ground pivot's support triangle, in pin radii: half its base, and the base's
/// depth below the pin's centre (the apex).
pub const PIVOT_HALF_BASE: f64 = 2.0;
/// See [`PIVOT_HALF_BASE`].
pub const PIVOT_HEIGHT: f64 = 2.6;
/// Half the depth of the hatching under a ground pivot's base, pin radii: joint names
/// keep clear of its upper half and may cover its lower, fainter half.
pub const PIVOT_HATCH: f64 = 0.7;
/// A slider block's half length and half width, in pin radii.
const BLOCK_HALF: [f32; 2] = [2.4, 1.5];

/// How far a slider block reaches from its pin, m (its half diagonal), for a
/// mechanism `size_m` across: names placed beside a slider go outside it.
pub fn block_reach_m(size_m: f64) -> f64 {
    PIN_SHARE * size_m.max(1e-12) * f64::from(BLOCK_HALF[0].hypot(BLOCK_HALF[1]))
}

/// Fills `out` with the shapes of the session's current pose, seen by `cam` over
/// `visible_m` ([min x, min y, max x, max y], m: the view's rectangle in the world).
pub fn build(
    out: &mut Vec<Shape>,
    s: &Session,
    cam: &Camera,
    layers: Layers,
    m_per_px: f64,
    visible_m: [f64; 4],
) -> VectorScales {
    out.clear();
    let m = s.mechanism();
    let size = m.size_m.max(1e-12);
    let d = Drawn {
        s,
        cam,
        bar: (0.016 * size) as f32,
        pin: (PIN_SHARE * size) as f32,
    };
    let mut push = |shape: Option<Shape>| out.extend(shape);
    // Ground pivots: a support triangle on a hatched base.
    for r in m
        .revolutes
        .iter()
        .filter(|r| r.a == m.ground || r.b == m.ground)
    {
        ground_pivot(&mut push, d.pos(r.point), d.pin, d.bar);
    }
    ground_guides(&mut push, &d);
    if layers.traces {
        push_traces(&mut push, s, cam, 0.22 * d.bar);
    }
    cam_discs(&mut push, &d);
    links(&mut push, &d);
    rollers(&mut push, &d);
    sliders_springs_and_pins(&mut push, &d);
    arrows(&mut push, &d, layers, m_per_px, visible_m)
}

/// The box `b` ([min x, min y, max x, max y]) shrunk by `margin` on every side.
fn visible_m_shrunk(b: [f64; 4], margin: f64) -> [f64; 4] {
    [b[0] + margin, b[1] + margin, b[2] - margin, b[3] - margin]
}

/// The largest scale up to `full` at which the arrow `v` from `at` ends inside
/// `inside`; `full` for a pin outside it (off screen, its arrow is no concern) or a
/// vector that is not finite.
fn scale_keeping_inside(at: linkage::Vec2, v: linkage::Vec2, full: f64, inside: [f64; 4]) -> f64 {
    let within = |x: f64, lo: f64, hi: f64| (lo..=hi).contains(&x);
    if !(within(at.x, inside[0], inside[2]) && within(at.y, inside[1], inside[3])) {
        return full;
    }
    let room = |x: f64, dx: f64, lo: f64, hi: f64| match dx {
        d if d > 0.0 => (hi - x) / d,
        d if d < 0.0 => (lo - x) / d,
        _ => f64::INFINITY,
    };
    let s = room(at.x, v.x, inside[0], inside[2]).min(room(at.y, v.y, inside[1], inside[3]));
    if s.is_nan() { full } else { full.min(s) }
}

/// Where a guide fixed to ground is drawn, m: its centre line from `a` to `b` over
/// the slider's travel and a margin, its two rails `off` to either side of it.
pub struct GuideRails {
    /// The centre line's start.
    pub a: linkage::Vec2,
    /// The centre line's end.
    pub b: linkage::Vec2,
    /// From the centre line to one rail (the other is the opposite).
    pub off: linkage::Vec2,
}

/// Every ground guide's rails, as the view draws them and as the joints' names keep
/// off them.
pub fn ground_guide_rails(s: &Session) -> Vec<GuideRails> {
    let (m, pose) = (s.mechanism(), s.pose());
    let pin = PIN_SHARE * m.size_m.max(1e-12);
    m.sliders
        .iter()
        .enumerate()
        .filter(|(_, sl)| sl.guide == m.ground)
        .map(|(i, sl)| {
            let dir = sl.direction(&pose.links);
            let through = pose.links[sl.guide].world(&sl.through_local);
            let travel = s
                .curves()
                .slide_travel_m
                .get(i)
                .copied()
                .flatten()
                .unwrap_or([pose.slides[i].displacement_m; 2]);
            GuideRails {
                a: through + dir * (travel[0] - 4.0 * pin),
                b: through + dir * (travel[1] + 4.0 * pin),
                off: linkage::Vec2::new(-dir.y, dir.x) * 1.7 * pin,
            }
        })
        .collect()
}

/// Guides fixed to ground: two rails over the slider's travel, hatched outside.
fn ground_guides(push: &mut impl FnMut(Option<Shape>), d: &Drawn<'_>) {
    for rails in ground_guide_rails(d.s) {
        let (a, b) = (
            d.cam.local([rails.a.x, rails.a.y]),
            d.cam.local([rails.b.x, rails.b.y]),
        );
        let off = Vec2::new(rails.off.x as f32, rails.off.y as f32);
        for rail in [off, -off] {
            push(Shape::new(
                Kind::Line,
                [a + rail, b + rail, a],
                0.3 * d.bar,
                colour::GROUND,
                [0.0; 2],
            ));
        }
        push(Shape::new(
            Kind::Ground,
            [a, b - off, a - off],
            0.0,
            colour::GROUND,
            [1.2 * d.pin, 0.0],
        ));
    }
}

/// Links: bars, plates for three or more joints (or an offset tool point).
fn links(push: &mut impl FnMut(Option<Shape>), d: &Drawn<'_>) {
    let (m, topo, bar) = (d.s.mechanism(), d.s.topology(), d.bar);
    for l in m.moving_links() {
        let colour = if l == m.driver.link {
            colour::DRIVER
        } else {
            colour::LINK
        };
        let others = topo.link_others[l].iter().map(|&p| d.pos(p));
        match topo.link_joints[l].as_slice() {
            &[a, b, c, ..] => push(Shape::new(
                Kind::Plate,
                [d.pos(a), d.pos(b), d.pos(c)],
                bar,
                colour::PLATE,
                [0.0; 2],
            )),
            &[a, b] => {
                let (a, b) = (d.pos(a), d.pos(b));
                let off_line = others
                    .map(|p| (p, distance_to_line(p, a, b)))
                    .filter(|(_, dist)| *dist > 2.0 * bar)
                    .max_by(|x, y| x.1.total_cmp(&y.1));
                match off_line {
                    Some((p, _)) => push(Shape::new(
                        Kind::Plate,
                        [a, b, p],
                        bar,
                        colour::PLATE,
                        [0.0; 2],
                    )),
                    None => push(Shape::new(Kind::Bar, [a, b, a], bar, colour, [0.0; 2])),
                }
            }
            &[a] => {
                let a = d.pos(a);
                if let Some(far) = others.max_by(|x, y| x.distance(a).total_cmp(&y.distance(a))) {
                    push(Shape::new(Kind::Bar, [a, far, a], bar, colour, [0.0; 2]));
                }
            }
            [] => {}
        }
    }
}

/// Slider blocks along their guides, springs, pins at the joints and marks at the
/// other named points (centroids, tool points).
fn sliders_springs_and_pins(push: &mut impl FnMut(Option<Shape>), d: &Drawn<'_>) {
    let (m, pose, pin) = (d.s.mechanism(), d.s.pose(), d.pin);
    for sl in &m.sliders {
        let c = d.pos(sl.point);
        let dir = sl.direction(&pose.links);
        let axis = c + Vec2::new(dir.x as f32, dir.y as f32);
        push(Shape::new(
            Kind::Block,
            [c, axis, c],
            0.2 * d.bar,
            colour::BLOCK,
            BLOCK_HALF.map(|k| k * pin),
        ));
    }
    // Springs: a coil with a fixed number of turns, so it visibly stretches.
    for sp in &d.s.scene().forces.springs {
        if let (Some(a), Some(b)) = (m.point_index(&sp.a), m.point_index(&sp.b)) {
            push(coil(d.pos(a), d.pos(b), d.bar, pin));
        }
    }
    for r in &m.revolutes {
        let c = d.pos(r.point);
        push(Shape::new(Kind::Pin, [c, c, c], pin, colour::PIN, [0.0; 2]));
    }
    for &i in &d.s.topology().marks {
        let c = d.pos(i);
        push(Shape::new(
            Kind::Pin,
            [c, c, c],
            0.45 * pin,
            colour::MARK,
            [0.0; 2],
        ));
    }
}

/// The cycle's typical largest arrow, a share of the mechanism's size.
const FULL_SHARE: f64 = 0.33;
/// The longest arrow in any frame, a share of the mechanism's size.
const MOST_SHARE: f64 = 0.5;

/// The least share of an arrow's full scale that keeping its tip in the view may
/// leave (a pin at the view's edge moving outwards is drawn clipped, not as a dot).
const LEAST_ARROW_SHARE: f64 = 0.1;

/// The velocity and acceleration arrows at the joints, where `layers` shows them:
/// the cycle's typical largest a third of the mechanism long (one scale through the
/// cycle, as a drawing's μv: before, the scale followed each frame's largest arrow,
/// and an arrow's length said nothing from one crank angle to the next), none longer
/// than half of it, and shorter where that would carry a tip past the view's edge
/// (the fit frames the links, not the arrows: a slider at the end of its travel
/// moving outwards ran off the view). Returns the scales they are drawn at.
fn arrows(
    push: &mut impl FnMut(Option<Shape>),
    d: &Drawn<'_>,
    layers: Layers,
    m_per_px: f64,
    visible_m: [f64; 4],
) -> VectorScales {
    let (pose, size) = (d.s.pose(), d.s.mechanism().size_m.max(1e-12));
    let mut scales = VectorScales::default();
    let arrow_r = (1.4 * m_per_px) as f32;
    let head = (9.0 * m_per_px) as f32;
    let joint_points = &d.s.topology().joint_points;
    for (on, colour, field, scale) in [
        (layers.velocities, colour::VELOCITY, 0, &mut scales.velocity),
        (
            layers.accelerations,
            colour::ACCELERATION,
            1,
            &mut scales.acceleration,
        ),
    ] {
        let vec_of = |p: PointId| {
            let pm = &pose.points[p];
            if field == 0 {
                pm.velocity
            } else {
                pm.acceleration
            }
        };
        let largest = joint_points
            .iter()
            .map(|&p| vec_of(p).norm())
            .filter(|v| v.is_finite())
            .fold(0.0, f64::max);
        if !on || largest <= 0.0 {
            continue;
        }
        // To the cycle's typical largest vector, so that lengths compare between
        // crank angles; never longer than half the mechanism (a dynamic run's speeds,
        // or a position past the cycle's 90th percentile).
        let typical = d.s.curves().typical_largest[field];
        let full = FULL_SHARE * size / typical.max(largest * FULL_SHARE / MOST_SHARE);
        let inside = visible_m_shrunk(visible_m, 12.0 * m_per_px);
        *scale = joint_points
            .iter()
            .map(|&p| scale_keeping_inside(pose.points[p].position, vec_of(p), full, inside))
            .fold(full, f64::min)
            .max(LEAST_ARROW_SHARE * full);
        for &p in joint_points {
            let v = vec_of(p) * *scale;
            if v.norm() < 2.0 * m_per_px {
                continue;
            }
            let a = d.at(p);
            let tip = [a[0] + v.x, a[1] + v.y];
            push(Shape::new(
                Kind::Arrow,
                [d.cam.local(a), d.cam.local(tip), d.cam.local(a)],
                arrow_r,
                colour,
                [head, 0.0],
            ));
        }
    }
    scales
}

fn push_traces(push: &mut impl FnMut(Option<Shape>), s: &Session, cam: &Camera, radius: f32) {
    let curves = s.curves();
    let n = curves.input_deg.len();
    if n < 2 {
        return;
    }
    let now = s.input_rad().to_degrees();
    let first = curves.input_deg[0];
    let span = curves.input_deg[n - 1] - first;
    // Position of the current input along the sweep, in samples.
    let here = if curves.full_rotation {
        (now - first).rem_euclid(360.0) / 360.0 * n as f64
    } else {
        ((now - first) / span.max(1e-12)).clamp(0.0, 1.0) * (n - 1) as f64
    };
    for trace in &curves.traces {
        for (i, w) in trace.path.windows(2).enumerate() {
            let behind = if curves.full_rotation {
                (here - i as f64).rem_euclid(n as f64) / n as f64
            } else {
                (here - i as f64).abs() / n as f64
            };
            // Recent path strong, older path fading to a faint line.
            let alpha = (0.12 + 0.78 * (1.0 - behind)) as f32;
            let mut c = colour::TRACE;
            c[3] = alpha;
            push(Shape::new(
                Kind::Line,
                [cam.local(w[0]), cam.local(w[1]), cam.local(w[0])],
                radius,
                c,
                [0.0; 2],
            ));
        }
    }
}

fn distance_to_line(p: Vec2, a: Vec2, b: Vec2) -> f32 {
    let ab = b - a;
    let len = ab.length();
    if len <= 0.0 {
        return p.distance(a);
    }
    (ab.perp_dot(p - a) / len).abs()
}
