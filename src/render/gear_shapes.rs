//! The gear-cutting lab as the GPU draws it: the blank (its tip circle, filled), each
//! cutter position rolled so far filled in the background's colour (the material it
//! takes away) and outlined thinly (the trace the envelope shows in), the cutter now
//! filled over it, the pitch, base, root and tip circles, and the cut flanks marked
//! red where the cutter's tip has undercut them (cut thinner than the involute).

use glam::Vec2;
use linkage::gears::Gear;
use linkage::gears::generation::{cut_tooth_thickness_at, cutter_outline};

use super::drawn::colour;
use super::shape::{Kind, Shape};
use super::view::Camera;
use crate::gear_lab::{CUTTER_TEETH, GearLab};

/// The canvas's colour: the cut-away material is filled with it.
pub const BACKGROUND: [f32; 4] = [0.965, 0.965, 0.95, 1.0];
/// The blank, and the pinion of the pair (the same gear).
pub(super) const BLANK: [f32; 4] = [0.80, 0.74, 0.58, 1.0];
const CUTTER: [f32; 4] = [0.36, 0.55, 0.78, 0.55];
const CUTTER_EDGE: [f32; 4] = [0.16, 0.3, 0.55, 1.0];
const TRACE: [f32; 4] = [0.36, 0.45, 0.65, 0.22];
pub(super) const PITCH: [f32; 4] = [0.1, 0.5, 0.2, 1.0];
pub(super) const BASE: [f32; 4] = [0.75, 0.35, 0.1, 1.0];
const FINE: [f32; 4] = [0.35, 0.35, 0.35, 0.8];
pub(super) const LINE_OF_ACTION: [f32; 4] = [0.55, 0.1, 0.45, 1.0];
/// Segments of a drawn circle.
const ROUND: usize = 240;
/// Points on each of the cutter's tip fillets.
const FILLET_POINTS: usize = 8;
/// The roll past which the middle space is cut through its undercut (the cutter's
/// tip has crossed the line of centres and left the base circle's region).
const UNDERCUT_SHOWN_FROM: f64 = 0.75;
/// Radii along a flank where undercut is looked for.
const UNDERCUT_SAMPLES: usize = 32;

/// The box the lab's view frames, m: the blank, and the cutter at the roll's ends
/// and middle.
pub fn bounds(g: &Gear) -> [f64; 4] {
    let r = g.tip_radius_m + g.spec.module_m;
    let reach = crate::gear_lab::roll_reach(g);
    [-reach, 0.0, reach]
        .into_iter()
        .filter_map(|phi| cutter_outline(g, phi, CUTTER_TEETH, 2))
        .flatten()
        .flatten()
        .fold([-r, -r, r, r], |b, [x, y]| {
            [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)]
        })
}

/// The lab's shapes for `g` in `list`, its undercut as [`undercut_segments`] gave it.
pub fn build_gear_lab(
    list: &mut Vec<Shape>,
    lab: &GearLab,
    g: &Gear,
    undercut: &[[[f64; 2]; 2]],
    camera: &Camera,
) {
    list.clear();
    let at = |p: [f64; 2]| camera.local(p);
    // Half a line's width, m: 0.6 screen points.
    let line = (0.6 / camera.points_per_m.max(1e-9)) as f32;
    let mut push = |s: Option<Shape>| list.extend(s);
    fill_circle(
        &mut push,
        at([0.0, 0.0]),
        g.tip_radius_m,
        BLANK,
        [ROUND as f32, 0.002],
    );
    // Each position's cutter once: filled away, then traced, the last drawn over.
    let positions = lab.positions(g);
    let cutters: Vec<Vec<Vec<[f64; 2]>>> = positions
        .iter()
        .map(|&phi| cutter_outline(g, phi, CUTTER_TEETH, FILLET_POINTS).unwrap_or_default())
        .collect();
    for part in cutters.iter().flatten() {
        fill_convex(&mut push, part, &at, line, BACKGROUND);
    }
    for parts in &cutters {
        // The teeth's outlines (the body's last): what the envelope shows in.
        for part in parts.iter().take(2 * CUTTER_TEETH + 1) {
            outline(&mut push, part, &at, 0.5 * line, TRACE);
        }
    }
    for part in cutters.last().into_iter().flatten() {
        fill_convex(&mut push, part, &at, 0.0, CUTTER);
        outline(&mut push, part, &at, line, CUTTER_EDGE);
    }
    let centre = at([0.0, 0.0]);
    for (radius, colour, every) in [
        (g.pitch_radius_m, PITCH, 2),
        (g.base_radius_m, BASE, 2),
        (g.root_radius_m, FINE, 0),
        (g.tip_radius_m, FINE, 0),
    ] {
        circle(&mut push, centre, radius, line, colour, every);
    }
    if lab.roll >= UNDERCUT_SHOWN_FROM {
        undercut_marks(&mut push, undercut, &at, 3.0 * line);
    }
    if let Some(&now) = positions.last() {
        cutter_lines(&mut push, g, now, &at, line);
    }
    push(Shape::new(
        Kind::Pin,
        [centre; 3],
        2.0 * line,
        colour::PIN,
        [0.0; 2],
    ));
}

/// A filled circle, as a fan of `sides` triangles from its centre, each grown by
/// `grow` of the radius (an opaque fan shows no seams).
pub(super) fn fill_circle(
    push: &mut impl FnMut(Option<Shape>),
    centre: Vec2,
    radius: f64,
    colour: [f32; 4],
    [sides, grow]: [f32; 2],
) {
    let sides = sides as usize;
    let r = radius as f32;
    let a = |k: usize| {
        let t = std::f32::consts::TAU * k as f32 / sides as f32;
        centre + r * Vec2::new(t.cos(), t.sin())
    };
    for i in 0..sides {
        push(Shape::new(
            Kind::Fill,
            [centre, a(i), a(i + 1)],
            grow * r,
            colour,
            [0.0; 2],
        ));
    }
}

/// A convex polygon filled, as a fan from its first point, each triangle grown by
/// `grow` (m) so that an opaque fan shows no seams.
fn fill_convex(
    push: &mut impl FnMut(Option<Shape>),
    points: &[[f64; 2]],
    at: &impl Fn([f64; 2]) -> Vec2,
    grow: f32,
    colour: [f32; 4],
) {
    let Some(&first) = points.first() else {
        return;
    };
    let o = at(first);
    for pair in points[1..].windows(2) {
        push(Shape::new(
            Kind::Fill,
            [o, at(pair[0]), at(pair[1])],
            grow,
            colour,
            [0.0; 2],
        ));
    }
}

/// A closed polygon's edges.
fn outline(
    push: &mut impl FnMut(Option<Shape>),
    points: &[[f64; 2]],
    at: &impl Fn([f64; 2]) -> Vec2,
    width: f32,
    colour: [f32; 4],
) {
    for (i, &p) in points.iter().enumerate() {
        let (a, b) = (at(p), at(points[(i + 1) % points.len()]));
        push(Shape::new(Kind::Line, [a, b, a], width, colour, [0.0; 2]));
    }
}

/// A circle's outline: solid where `every` is 0, else drawn `every` segments of
/// [`ROUND`] on and `every` off (dashes; 1 makes dots).
pub(super) fn circle(
    push: &mut impl FnMut(Option<Shape>),
    centre: Vec2,
    radius: f64,
    width: f32,
    colour: [f32; 4],
    every: usize,
) {
    let r = radius as f32;
    let point = |k: usize| {
        let t = std::f32::consts::TAU * k as f32 / ROUND as f32;
        centre + r * Vec2::new(t.cos(), t.sin())
    };
    for i in (0..ROUND).filter(|i| every == 0 || (i / every).is_multiple_of(2)) {
        let (a, b) = (point(i), point(i + 1));
        push(Shape::new(Kind::Line, [a, b, a], width, colour, [0.0; 2]));
    }
}

/// The undercut of the middle space's two flanks as line segments (m, the gear's
/// frame): where the cut tooth is thinner than the involute tooth at the same radius,
/// or, below the base circle where there is no involute, thinner than it is at the
/// base circle (the neck the cutter's tip leaves; the root fillet of a gear that is
/// not undercut is thicker there).
/// The dear part of the lab's drawing (a search over the cutter's turn per radius):
/// the canvas keeps it while the gear stays the same. The flanks are mirror images
/// about the space's middle (the y axis), so one is searched.
pub fn undercut_segments(g: &Gear) -> Vec<[[f64; 2]; 2]> {
    if !GearLab::undercut(g) {
        return Vec::new();
    }
    let (lo, hi) = (g.root_radius_m, g.tip_radius_m);
    // The tooth right of the middle space, centred at 90° − 180°/z.
    let middle = std::f64::consts::FRAC_PI_2 - std::f64::consts::PI / f64::from(g.spec.teeth);
    let point = |rho: f64| -> Option<[f64; 2]> {
        let cut = cut_tooth_thickness_at(g, rho)?;
        let involute = g
            .tooth_thickness_at(rho.max(g.base_radius_m))
            .unwrap_or(f64::INFINITY);
        if cut >= involute - 1e-4 * g.spec.module_m {
            return None;
        }
        let angle = middle + 0.5 * cut / rho;
        Some([rho * angle.cos(), rho * angle.sin()])
    };
    let points: Vec<Option<[f64; 2]>> = (0..=UNDERCUT_SAMPLES)
        .map(|k| point(lo + (hi - lo) * k as f64 / UNDERCUT_SAMPLES as f64))
        .collect();
    let right: Vec<[[f64; 2]; 2]> = points
        .windows(2)
        .filter_map(|pair| Some([pair[0]?, pair[1]?]))
        .collect();
    let mirror = |[x, y]: [f64; 2]| [-x, y];
    let left = right.iter().map(|&[a, b]| [mirror(a), mirror(b)]);
    right.iter().copied().chain(left).collect()
}

/// The undercut segments in red.
fn undercut_marks(
    push: &mut impl FnMut(Option<Shape>),
    segments: &[[[f64; 2]; 2]],
    at: &impl Fn([f64; 2]) -> Vec2,
    width: f32,
) {
    for &[a, b] in segments {
        let (a, b) = (at(a), at(b));
        push(Shape::new(
            Kind::Line,
            [a, b, a],
            width,
            colour::PAST_LIMIT,
            [0.0; 2],
        ));
    }
}

/// The cutter's datum line (dash-dotted look: dashed) and the line of action from the
/// pitch point P to N1, where it touches the base circle, at the cutter's position
/// `phi`: the undercut happens where the cutter's tip line passes beyond N1.
fn cutter_lines(
    push: &mut impl FnMut(Option<Shape>),
    g: &Gear,
    phi: f64,
    at: &impl Fn([f64; 2]) -> Vec2,
    width: f32,
) {
    let (sin, cos) = phi.sin_cos();
    let to_gear = |[u, y]: [f64; 2]| [u * cos - y * sin, u * sin + y * cos];
    let m = g.spec.module_m;
    let r = g.pitch_radius_m;
    let datum = r + g.spec.shift * m;
    let half = (CUTTER_TEETH as f64 + 0.5) * std::f64::consts::PI * m;
    let u0 = r * phi;
    // The datum line in dashes of a quarter pitch.
    let dashes = 4 * (2 * CUTTER_TEETH + 1);
    for k in (0..dashes).step_by(2) {
        let u = |j: usize| u0 - half + 2.0 * half * j as f64 / dashes as f64;
        let (a, b) = (at(to_gear([u(k), datum])), at(to_gear([u(k + 1), datum])));
        push(Shape::new(
            Kind::Line,
            [a, b, a],
            width,
            CUTTER_EDGE,
            [0.0; 2],
        ));
    }
    // The line of action through the pitch point (0, r) of the rolling, at α, to
    // N1 on the base circle: r cos α (sin α, cos α) in the cutter's frame.
    let alpha = g.spec.pressure_angle_rad;
    let n1 = [r * alpha.cos() * alpha.sin(), r * alpha.cos() * alpha.cos()];
    let p = [0.0, r];
    let beyond = [2.0 * p[0] - n1[0], 2.0 * p[1] - n1[1]];
    let (a, b) = (at(to_gear(n1)), at(to_gear(beyond)));
    push(Shape::new(
        Kind::Line,
        [a, b, a],
        width,
        LINE_OF_ACTION,
        [0.0; 2],
    ));
    push(Shape::new(
        Kind::Pin,
        [a; 3],
        2.5 * width,
        LINE_OF_ACTION,
        [0.0; 2],
    ));
}

/// Where N1, the line of action's end on the base circle, is at the cutter's
/// position `phi`, in the gear's frame, m: for its name on the canvas.
pub fn limit_point(g: &Gear, phi: f64) -> [f64; 2] {
    let (sin, cos) = phi.sin_cos();
    let (r, alpha) = (g.pitch_radius_m, g.spec.pressure_angle_rad);
    let [u, y] = [r * alpha.cos() * alpha.sin(), r * alpha.cos() * alpha.cos()];
    [u * cos - y * sin, u * sin + y * cos]
}
