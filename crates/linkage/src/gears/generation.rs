//! The tooth as a rack cutter cuts it (范成法): the gear turns, the cutter's
//! straight-sided teeth (GB/T 1356's basic rack, its tips rounded by the arc tangent
//! to the flank and the tip line) slide along its rolling line without slip, and what is left
//! of the blank is the tooth. At each radius the tooth's edge is the nearest the
//! cutter comes to it over all its positions, found by a golden-section search over
//! the gear's turn, from the cutter's lines alone (no involute formula): where the
//! cutter's flank generates the edge it is the involute, where its tip corner does
//! it is the trochoid of the root fillet, and where the corner cuts deeper than the
//! flank the tooth is undercut, as on a cut gear. External gears (a rack cuts them);
//! an internal gear is cut by a pinion cutter ([`super::shaper`]).

use std::f64::consts::{FRAC_PI_2, PI};

use super::gear::{Gear, GearKind};

/// Points of the grid over the gear's turn that brackets the cut edge's minima.
const GRID: usize = 256;

/// The cutter: its rolling line tangent to the pitch circle at (0, r), its datum
/// line x·m further out, its teeth reaching (h_a* + c*)·m below the datum line to
/// the root circle, a tooth centred on the y axis when the gear is at 0.
struct Cutter {
    /// The pitch radius r, m.
    r: f64,
    /// The root radius r_f (the cutter's tip line), m.
    tip_line: f64,
    /// The right flank's line: u = offset + y tan α (at the gear's angle 0).
    offset: f64,
    /// tan α.
    tan_alpha: f64,
    /// The tip fillet's radius, c*·m / (1 − sin α) (GB/T 1356's 0.38·m): the arc
    /// tangent to the flank h_a*·m below the datum line and to the tip line.
    fillet: f64,
}

impl Cutter {
    fn of(g: &Gear) -> Self {
        let s = g.spec;
        let m = s.module_m;
        let datum = g.pitch_radius_m + s.shift * m;
        let tan_alpha = s.pressure_angle_rad.tan();
        Self {
            r: g.pitch_radius_m,
            tip_line: g.root_radius_m,
            offset: 0.25 * PI * m - datum * tan_alpha,
            tan_alpha,
            fillet: fillet(g),
        }
    }

    /// Where the circle of radius `rho` meets the cutter's right tip fillet with
    /// the cutter moved by `shift`, given the sharp corner's exit angle `beta`: the
    /// same where the exit is not in the corner the fillet rounds off; the fillet's
    /// meeting past it where it is; +∞ where the circle passes the corner outside the
    /// fillet.
    fn rounded(&self, rho: f64, shift: f64, beta: f64) -> f64 {
        let alpha = self.tan_alpha.atan();
        let cy = self.tip_line + self.fillet;
        let cx = self.offset + shift + cy * self.tan_alpha - self.fillet / alpha.cos();
        let q = [rho * beta.cos() - cx, rho * beta.sin() - cy];
        let direction = q[1].atan2(q[0]);
        let in_corner = (-0.5 * PI..=-alpha).contains(&direction) && q[0].hypot(q[1]) > self.fillet;
        if !in_corner {
            return beta;
        }
        // The circles |p| = ρ and |p − c| = fillet.
        let d = cx.hypot(cy);
        let a = (rho * rho - self.fillet * self.fillet + d * d) / (2.0 * d);
        let h2 = rho * rho - a * a;
        if h2 < 0.0 {
            return f64::INFINITY;
        }
        let (ux, uy) = (cx / d, cy / d);
        let h = h2.sqrt();
        [
            [a * ux + h * uy, a * uy - h * ux],
            [a * ux - h * uy, a * uy + h * ux],
        ]
        .into_iter()
        .filter(|p| {
            let dir = (p[1] - cy).atan2(p[0] - cx);
            (-0.5 * PI..=-alpha).contains(&dir)
        })
        .map(|p| p[1].atan2(p[0]))
        .filter(|b| *b >= beta)
        .fold(f64::INFINITY, f64::min)
    }

    /// The polar angle, in the gear's frame, where the circle of radius `rho` leaves
    /// the cutter's tooth on its right (towards the tooth beside the cut space) with
    /// the gear turned by `phi` (clockwise) and the cutter moved r·φ; +∞ where the
    /// circle misses the tooth.
    ///
    /// Rotation keeps distances, so the circle meets the cutter in the world frame
    /// where it meets it in the gear's, turned by φ. A point ρ(cos β, sin β) is in the
    /// cutter's tooth where it is above the tip line (β between asin(r_f/ρ) and its
    /// supplement), left of the right flank u = c_R + y tan α (ρ cos(β + α) ≤ c_R cos α)
    /// and right of the left flank u = c_L − y tan α (ρ cos(β − α) ≥ c_L cos α).
    fn right_exit(&self, rho: f64, phi: f64) -> f64 {
        let alpha = self.tan_alpha.atan();
        let tip = (self.tip_line / rho).clamp(-1.0, 1.0).asin();
        let shift = self.r * phi;
        // Right flank: β ≥ acos(c_R cos α / ρ) − α.
        let k_right = (self.offset + shift) * alpha.cos() / rho;
        // Left flank (the right one mirrored about the tooth's middle u = r φ):
        // β ≤ α + acos(c_L cos α / ρ).
        let k_left = (shift - self.offset) * alpha.cos() / rho;
        if k_right <= -1.0 || k_left >= 1.0 {
            return f64::INFINITY;
        }
        let from_right = if k_right >= 1.0 {
            f64::NEG_INFINITY
        } else {
            k_right.acos() - alpha
        };
        let to_left = if k_left <= -1.0 {
            f64::INFINITY
        } else {
            alpha + k_left.acos()
        };
        let (lo, hi) = (tip.max(from_right), (PI - tip).min(to_left));
        if lo > hi {
            return f64::INFINITY;
        }
        let exit = self.rounded(rho, shift, lo);
        if exit <= hi {
            exit + phi
        } else {
            f64::INFINITY
        }
    }
}

/// The half-width of the cutter's tooth on its tip line, m: negative where the
/// basic rack comes to a point above it (a pressure angle over 32° with h_a* = 1,
/// c* = 0.25, or h_a* = 2 at 20°).
fn tip_half_width(g: &Gear) -> f64 {
    let s = g.spec;
    let depth = (s.addendum_coefficient + s.clearance_coefficient) * s.module_m;
    0.25 * PI * s.module_m - depth * s.pressure_angle_rad.tan()
}

/// The tip fillet's radius: c*·m / (1 − sin α), or less where the two fillets of
/// the cutter's tip would overlap (above about 22.4° with GB/T 1356's coefficients):
/// then the largest that fits the tip's half-width.
fn fillet(g: &Gear) -> f64 {
    let s = g.spec;
    let (sin, cos) = s.pressure_angle_rad.sin_cos();
    let standard = s.clearance_coefficient * s.module_m / (1.0 - sin);
    standard.min(tip_half_width(g).max(0.0) * cos / (1.0 - sin))
}

/// The polar angle of the cut tooth's edge at `radius_m`, in the gear's frame where
/// the space the cutter's middle tooth cuts is centred at 90° and the tooth beside it
/// at 90° − 180°/z; `None` below the root or above the tip circle, where the cutter
/// does not reach (its tip is pointed above the root circle), or for an internal
/// gear.
pub fn cut_edge_angle(g: &Gear, radius_m: f64) -> Option<f64> {
    let inside = radius_m > g.root_radius_m && radius_m <= g.tip_radius_m;
    if g.spec.kind != GearKind::External || !inside || tip_half_width(g) <= 0.0 {
        return None;
    }
    let cutter = Cutter::of(g);
    // The cutter touches a tooth while its teeth cross the line of action's length;
    // a turn of a few pitches either side holds every contact.
    let reach = (3.0 * PI / f64::from(g.spec.teeth))
        .max(4.0 * (g.tip_radius_m - g.root_radius_m + g.spec.module_m) / g.pitch_radius_m);
    let f = |phi: f64| cutter.right_exit(radius_m, phi);
    // Two minima may compete (the flank's contact, and the tip corner's pass where
    // it undercuts): the least of a grid first, then golden section between its
    // neighbours.
    let step = 2.0 * reach / GRID as f64;
    let best = (0..=GRID)
        .map(|k| -reach + step * k as f64)
        .min_by(|a, b| f(*a).total_cmp(&f(*b)))
        .unwrap_or(0.0);
    // The crate's golden-section search for a maximum, on −f.
    let least = crate::extremum::golden_max(|phi| Some(-f(phi)), best - step, best + step)?;
    Some(-least.value).filter(|a| a.is_finite())
}

/// The cut tooth's thickness (arc) at `radius_m`: twice the edge's angle from the
/// tooth's middle, times the radius; `None` where [`cut_edge_angle`] is.
pub fn cut_tooth_thickness_at(g: &Gear, radius_m: f64) -> Option<f64> {
    let edge = cut_edge_angle(g, radius_m)?;
    let middle = FRAC_PI_2 - PI / f64::from(g.spec.teeth);
    Some(2.0 * radius_m * (edge - middle))
}

/// One flank of the cut tooth from just above the root to the tip, `samples` points
/// (x, y) in metres, the tooth's middle on the y axis: what a drawing of the cut
/// gear traces (the other flank is its mirror image).
pub fn cut_flank(g: &Gear, samples: usize) -> Vec<[f64; 2]> {
    let (lo, hi) = (g.root_radius_m, g.tip_radius_m);
    let middle = FRAC_PI_2 - PI / f64::from(g.spec.teeth);
    (1..=samples.max(2))
        .filter_map(|k| {
            let rho = lo + (hi - lo) * k as f64 / samples.max(2) as f64;
            let angle = cut_edge_angle(g, rho)? - middle + FRAC_PI_2;
            Some([rho * angle.cos(), rho * angle.sin()])
        })
        .collect()
}

/// The rack cutter as drawn at the gear's turn `phi` (clockwise; the cutter moved
/// r·φ along its rolling line), in the gear's frame: `teeth` cutter teeth either side
/// of the middle one, each a convex polygon (its flanks, its tip fillets in
/// `fillet_points` each, its tip line), then the cutter's body above them, a
/// rectangle. `None` for an internal gear or a pointed rack.
pub fn cutter_outline(
    g: &Gear,
    phi: f64,
    teeth: usize,
    fillet_points: usize,
) -> Option<Vec<Vec<[f64; 2]>>> {
    if g.spec.kind != GearKind::External || tip_half_width(g) <= 0.0 {
        return None;
    }
    let c = Cutter::of(g);
    let m = g.spec.module_m;
    let top = c.tip_line + 2.0 * (g.spec.addendum_coefficient + g.spec.clearance_coefficient) * m;
    let pitch = PI * m;
    let (sin, cos) = phi.sin_cos();
    let to_gear = |[u, y]: [f64; 2]| [u * cos - y * sin, u * sin + y * cos];
    let half = teeth as f64;
    let mut out: Vec<Vec<[f64; 2]>> = (-(teeth as i64)..=teeth as i64)
        .map(|k| {
            let centre = c.r * phi + k as f64 * pitch;
            cutter_tooth(&c, centre, top, fillet_points)
                .into_iter()
                .map(to_gear)
                .collect()
        })
        .collect();
    let (left, right) = (
        c.r * phi - (half + 0.5) * pitch,
        c.r * phi + (half + 0.5) * pitch,
    );
    let body = [
        [left, top],
        [right, top],
        [right, top + 1.5 * m],
        [left, top + 1.5 * m],
    ];
    out.push(body.into_iter().map(to_gear).collect());
    Some(out)
}

/// One cutter tooth centred at `centre` on the rolling line, from its tip line up to
/// `top`, counter-clockwise, in the cutter's frame.
fn cutter_tooth(c: &Cutter, centre: f64, top: f64, fillet_points: usize) -> Vec<[f64; 2]> {
    let alpha = c.tan_alpha.atan();
    let cy = c.tip_line + c.fillet;
    let cx = centre + c.offset + cy * c.tan_alpha - c.fillet / alpha.cos();
    let n = fillet_points.max(2);
    // The right fillet from the tip line (−90°) to the flank (−α).
    let right: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let t = -FRAC_PI_2 + (FRAC_PI_2 - alpha) * i as f64 / (n - 1) as f64;
            [cx + c.fillet * t.cos(), cy + c.fillet * t.sin()]
        })
        .chain(std::iter::once([
            centre + c.offset + top * c.tan_alpha,
            top,
        ]))
        .collect();
    let mirror = |[u, y]: [f64; 2]| [2.0 * centre - u, y];
    right
        .iter()
        .copied()
        .chain(right.iter().rev().map(|&p| mirror(p)))
        .collect()
}
