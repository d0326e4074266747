//! An internal gear as a pinion cutter (插齿刀, a gear shaper's cutter) cuts it: the
//! cutter, an external involute gear of the ring's module and pressure angle whose
//! teeth reach (h_a* + c*)·m above its pitch circle, turns inside the ring blank as
//! a pinion meshing with it, and what is left of the blank is the ring's teeth. At
//! each radius the space's edge is the farthest the cutter's tooth reaches over all
//! its positions, found as in [`super::generation`] (a grid over the ring's turn,
//! then a golden-section search), from the cutter's own involute and tip circle: where
//! the cutter's involute generates the edge it is the ring's involute; where its tip
//! corner does, the root fillet; where the cutter cuts away more than the involute
//! (a cutter too large for the ring), the ring's tips are trimmed, as on a cut ring.
//!
//! The cutter is unshifted and its tip corners sharp (a shaper cutter's are rounded
//! by a few hundredths of a module, which moves the root fillet only). The cutting
//! centre distance follows from the ring's shift as a backlash-free mesh, with
//! ISO 21771's signs (a positive x₂ thickens the ring's teeth, as in
//! [`super::GearPair`]): inv α₀' = inv α − 2 tan α (x_c + x₂)/(z₂ − z_c),
//! a₀ = (z₂ − z_c) m cos α / (2 cos α₀').

use std::f64::consts::{FRAC_PI_2, PI};

use super::gear::{Gear, GearKind};
use super::involute::{inv, inv_inverse};

/// Points of the grid over the ring's turn that brackets the cut edge's extremum.
const GRID: usize = 256;
/// Points along the cutter's flank where the circle's crossing is bracketed.
const FLANK_SAMPLES: usize = 24;

/// The pinion cutter inside a ring, and where it cuts from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShaperCut {
    /// The cutter's teeth z_c.
    pub cutter_teeth: u32,
    /// The cutter's pitch radius, m.
    pub cutter_pitch_radius_m: f64,
    /// The cutter's base radius, m.
    pub cutter_base_radius_m: f64,
    /// The cutter's tip radius, r_c + (h_a* + c*)·m.
    pub cutter_tip_radius_m: f64,
    /// The cutter's root radius, r_c − (h_a* + c*)·m.
    pub cutter_root_radius_m: f64,
    /// The cutting centre distance a₀, m.
    pub centre_m: f64,
    /// The ring's root radius as cut, a₀ + the cutter's tip radius, m.
    pub cut_root_radius_m: f64,
    /// Half the cutter's tooth on its pitch circle, as an angle, rad.
    half_tooth_rad: f64,
    /// The ring's teeth z₂.
    ring_teeth: u32,
}

impl ShaperCut {
    /// The cut of `ring` by a pinion cutter of `cutter_teeth`: `None` for an external
    /// gear, a cutter with as many teeth as the ring or more, or one whose mesh has
    /// no working pressure angle (a shift far outside a ring's range).
    pub fn new(ring: &Gear, cutter_teeth: u32) -> Option<Self> {
        let s = ring.spec;
        if s.kind != GearKind::Internal || cutter_teeth < 3 || cutter_teeth >= s.teeth {
            return None;
        }
        let (m, alpha) = (s.module_m, s.pressure_angle_rad);
        let difference = f64::from(s.teeth - cutter_teeth);
        let working = inv_inverse(inv(alpha) - 2.0 * alpha.tan() * s.shift / difference)?;
        let centre_m = 0.5 * difference * m * alpha.cos() / working.cos();
        let rc = 0.5 * m * f64::from(cutter_teeth);
        let depth = (s.addendum_coefficient + s.clearance_coefficient) * m;
        let cut = Self {
            cutter_teeth,
            cutter_pitch_radius_m: rc,
            cutter_base_radius_m: rc * alpha.cos(),
            cutter_tip_radius_m: rc + depth,
            cutter_root_radius_m: rc - depth,
            centre_m,
            cut_root_radius_m: centre_m + rc + depth,
            half_tooth_rad: 0.25 * PI * m / rc,
            ring_teeth: s.teeth,
        };
        (cut.half_angle(cut.cutter_tip_radius_m) > 0.0 && centre_m.is_finite()).then_some(cut)
    }

    /// Half the cutter's tooth at radius `rho` as an angle from the tooth's middle:
    /// the involute's above the base circle, radial below it.
    fn half_angle(&self, rho: f64) -> f64 {
        let rb = self.cutter_base_radius_m;
        let at = |radius: f64| {
            let t = (radius * radius / (rb * rb) - 1.0).max(0.0).sqrt();
            t - t.atan()
        };
        self.half_tooth_rad + at(self.cutter_pitch_radius_m) - at(rho.max(rb))
    }

    /// The cutter's centre and its middle tooth's direction, in the ring's frame, with
    /// the ring turned by `phi` (clockwise) and the cutter by φ·z₂/z_c the same way.
    fn pose(&self, phi: f64) -> ([f64; 2], f64) {
        let centre = [-self.centre_m * phi.sin(), self.centre_m * phi.cos()];
        let ratio = f64::from(self.ring_teeth) / f64::from(self.cutter_teeth);
        (centre, FRAC_PI_2 + phi * (1.0 - ratio))
    }

    /// The smallest polar angle, in the ring's frame, where the circle of radius
    /// `rho` crosses the middle cutter tooth's edge (its right flank or its tip arc)
    /// with the ring turned by `phi`; +∞ where it does not cross it.
    fn right_exit(&self, rho: f64, phi: f64) -> f64 {
        let (c, dir) = self.pose(phi);
        let at =
            |radius: f64, angle: f64| [c[0] + radius * angle.cos(), c[1] + radius * angle.sin()];
        let mut least = f64::INFINITY;
        let mut keep = |p: [f64; 2]| least = least.min(p[1].atan2(p[0]));
        // The right flank (the left one's crossings lie at larger angles: the cutter's
        // centre is nearer the ring's than the circle).
        let flank = |radius: f64| at(radius, dir - self.half_angle(radius));
        let miss = |radius: f64| {
            let p = flank(radius);
            p[0].hypot(p[1]) - rho
        };
        for root in crossings(miss, self.cutter_root_radius_m, self.cutter_tip_radius_m) {
            keep(flank(root));
        }
        // The tip arc: |p| = ρ and |p − c| = r_tip, within the tooth's angle.
        let (ra, d) = (self.cutter_tip_radius_m, self.centre_m);
        let cos = (rho * rho - ra * ra - d * d) / (2.0 * ra * d);
        if cos.abs() <= 1.0 {
            // The angle at the cutter's centre between the direction to the ring's
            // centre and to the crossing.
            let towards_ring = (-c[1]).atan2(-c[0]);
            let half = self.half_angle(ra);
            for turn in [cos.acos(), -cos.acos()] {
                let angle = towards_ring + turn;
                let off = wrap(angle - dir);
                if off.abs() <= half {
                    keep(at(ra, angle));
                }
            }
        }
        least
    }

    /// How far either way the ring turns while the middle cutter tooth is within the
    /// ring's teeth: until its tip falls inside the ring's tip circle (`bore`), found
    /// in steps of a fortieth of the ring's pitch, at most half a turn.
    fn reach(&self, bore: f64) -> f64 {
        let step = 2.0 * PI / f64::from(self.ring_teeth) / 40.0;
        let mut phi = step;
        while phi < PI {
            let (c, dir) = self.pose(phi);
            let tip = [
                c[0] + self.cutter_tip_radius_m * dir.cos(),
                c[1] + self.cutter_tip_radius_m * dir.sin(),
            ];
            if tip[0].hypot(tip[1]) < bore {
                return phi;
            }
            phi += step;
        }
        PI
    }
}

/// The roots of `f` on `[a, b]`: each sign change of a grid of [`FLANK_SAMPLES`]
/// refined by bisection to round-off.
fn crossings(f: impl Fn(f64) -> f64, a: f64, b: f64) -> Vec<f64> {
    let step = (b - a) / FLANK_SAMPLES as f64;
    let mut roots = Vec::new();
    let mut x0 = a;
    let mut f0 = f(x0);
    for k in 1..=FLANK_SAMPLES {
        let x1 = a + step * k as f64;
        let f1 = f(x1);
        if f0 == 0.0 {
            roots.push(x0);
        } else if f0 * f1 < 0.0 {
            let (mut lo, mut hi, mut flo) = (x0, x1, f0);
            for _ in 0..64 {
                let mid = 0.5 * (lo + hi);
                let fm = f(mid);
                if fm * flo > 0.0 {
                    (lo, flo) = (mid, fm);
                } else {
                    hi = mid;
                }
            }
            roots.push(0.5 * (lo + hi));
        }
        (x0, f0) = (x1, f1);
    }
    roots
}

/// An angle in (−π, π].
fn wrap(a: f64) -> f64 {
    let t = a.rem_euclid(2.0 * PI);
    if t > PI { t - 2.0 * PI } else { t }
}

/// The polar angle of the ring's cut space edge at `radius_m` (its right side,
/// towards the tooth at 90° − 180°/z₂), in the ring's frame where the space the
/// cutter's middle tooth cuts is centred at 90°; `None` outside the ring's tip and
/// cut root circles or where [`ShaperCut::new`] is.
pub fn shaper_cut_edge_angle(ring: &Gear, cutter_teeth: u32, radius_m: f64) -> Option<f64> {
    ShaperCut::new(ring, cutter_teeth)?.edge_angle(ring.tip_radius_m, radius_m)
}

impl ShaperCut {
    /// [`shaper_cut_edge_angle`] of this cut, on a ring whose tip circle is
    /// `tip_radius_m`: the least exit angle over the cutter's turn, found on a grid
    /// and refined by golden section.
    fn edge_angle(&self, tip_radius_m: f64, radius_m: f64) -> Option<f64> {
        if radius_m < tip_radius_m || radius_m >= self.cut_root_radius_m {
            return None;
        }
        let reach = self.reach(tip_radius_m);
        let f = |phi: f64| self.right_exit(radius_m, phi);
        let step = 2.0 * reach / GRID as f64;
        let best = (0..=GRID)
            .map(|k| -reach + step * k as f64)
            .min_by(|a, b| f(*a).total_cmp(&f(*b)))?;
        if !f(best).is_finite() {
            return None;
        }
        let least = crate::extremum::golden_max(|phi| Some(-f(phi)), best - step, best + step)?;
        Some(-least.value).filter(|a| a.is_finite())
    }
}

/// The ring's cut tooth thickness (arc) at `radius_m`: the pitch's share less the
/// space the cutter opened; `None` where [`shaper_cut_edge_angle`] is.
pub fn shaper_cut_tooth_thickness_at(ring: &Gear, cutter_teeth: u32, radius_m: f64) -> Option<f64> {
    let edge = shaper_cut_edge_angle(ring, cutter_teeth, radius_m)?;
    let share = 2.0 * PI * radius_m / f64::from(ring.spec.teeth);
    Some(share - 2.0 * radius_m * (FRAC_PI_2 - edge))
}

/// The right edge of the ring's space as cut, from its tip circle out to the cut
/// root, `samples` points (x, y) in metres, the space's middle on the y axis: what a
/// drawing of the cut ring traces (the left edge is its mirror image). Empty where
/// [`ShaperCut::new`] is `None`.
pub fn shaper_cut_flank(ring: &Gear, cutter_teeth: u32, samples: usize) -> Vec<[f64; 2]> {
    let Some(cut) = ShaperCut::new(ring, cutter_teeth) else {
        return Vec::new();
    };
    let (lo, hi) = (ring.tip_radius_m, cut.cut_root_radius_m);
    let n = samples.max(2);
    (0..n)
        .filter_map(|k| {
            // Short of the cut root, where the edge meets the root arc.
            let rho = lo + (hi - lo) * k as f64 / n as f64;
            // The cut built once for every sample (it was built again for each).
            let angle = cut.edge_angle(ring.tip_radius_m, rho)?;
            Some([rho * angle.cos(), rho * angle.sin()])
        })
        .collect()
}
