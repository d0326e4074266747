//! A meshing pair of spur gears, external (two external gears) or internal (an
//! external pinion in a ring): the working pressure angle from the shifts,
//! inv α' = inv α ± 2 tan α (x₁ + x₂)/(z₂ ± z₁), or from a centre distance given;
//! the working pitch circles, the path of contact and the contact ratio, the
//! clearances, backlash, and the checks a designer reads (undercut, interference,
//! pointed tips, a contact ratio below one).

use serde::Serialize;

use super::error::{GearError, Member};
use super::gear::{Gear, GearKind, GearSpec};
use super::involute::{inv, inv_inverse};

/// Where the centres sit.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum CentreDistance {
    /// Where the shifts put them: the pair meshes without backlash.
    FromShifts,
    /// At a distance given, m; the shifts must fit it.
    Given {
        /// The distance, m.
        centre_m: f64,
    },
}

/// A pair as a designer gives it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PairSpec {
    /// The first gear (external).
    pub pinion: GearSpec,
    /// The second gear (external, or internal: a ring round the pinion).
    pub wheel: GearSpec,
    /// Where the centres sit.
    pub centre: CentreDistance,
}

/// Something a designer should know of a pair that meshes.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum PairIssue {
    /// A rack cutter undercuts this gear: its shift is short of the least by this much.
    Undercut {
        /// The gear.
        member: Member,
        /// How far short the shift is.
        shift_short: f64,
    },
    /// This gear's tooth comes to a point inside its tip circle.
    PointedTip {
        /// The gear.
        member: Member,
    },
    /// This gear's tooth is thinner on its tip circle than 0.25·m (the textbooks'
    /// least; 0.4·m for hardened teeth), but not pointed.
    ThinTip {
        /// The gear.
        member: Member,
        /// Its tip thickness s_a, m.
        thickness_m: f64,
        /// The least, 0.25·m, m.
        least_m: f64,
    },
    /// This gear's tip passes the other's interference point (where the line of action
    /// touches the other's base circle): it would cut into the other's root.
    TipInterference {
        /// The gear whose tip interferes.
        member: Member,
    },
    /// The ring's tip circle lies inside its base circle: its teeth are not involute
    /// to the tip.
    RingTipInsideBase,
    /// This gear's tip circle meets the other's root circle.
    NoClearance {
        /// The gear whose tip touches.
        member: Member,
        /// The clearance, m (negative: the circles overlap).
        clearance_m: f64,
    },
    /// Less than one pair of teeth in contact at a time: the motion is not continuous.
    ContactRatioBelowOne {
        /// The contact ratio.
        contact_ratio: f64,
    },
}

/// A pair's geometry. Lengths in metres, angles in radians.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct GearPair {
    /// The first gear.
    pub pinion: Gear,
    /// The second gear.
    pub wheel: Gear,
    /// Whether the wheel is internal.
    pub internal: bool,
    /// The wheel's speed over the pinion's: −z₁/z₂ for an external pair (they turn
    /// opposite ways), +z₁/z₂ for an internal one.
    pub speed_ratio: f64,
    /// The centre distance of the standard pair, a = m (z₂ ± z₁)/2.
    pub standard_centre_m: f64,
    /// The centre distance, a' = a cos α / cos α'.
    pub centre_m: f64,
    /// The working pressure angle α'.
    pub working_pressure_angle_rad: f64,
    /// The working pitch circles' radii, r' = r_b / cos α' (pinion, wheel).
    pub working_pitch_radii_m: [f64; 2],
    /// The centre distance modification coefficient y = (a' − a)/m.
    pub centre_modification: f64,
    /// The tip shortening coefficient Δy = x₁ + x₂ − y of an external pair (0 for a
    /// standard or an equal-and-opposite shift): where positive, both gears' tip
    /// circles here are cut down by Δy·m to keep the standard clearance.
    pub tip_shortening: Option<f64>,
    /// The shifts' sum that meshes without backlash at this centre distance.
    pub shift_sum_without_backlash: f64,
    /// The backlash on the working pitch circle (arc), 0 from the shifts.
    pub backlash_m: f64,
    /// The clearance at the pinion's tip and at the wheel's tip.
    pub clearances_m: [f64; 2],
    /// The length of the path of contact g_α, between the tip circles along the line of
    /// action.
    pub path_of_contact_m: f64,
    /// The contact ratio ε_α = g_α / p_b.
    pub contact_ratio: f64,
    /// What a designer should know (empty: a sound pair).
    pub issues: Vec<PairIssue>,
}

/// The largest working pressure angle, degrees.
pub const MAX_WORKING_ANGLE_DEG: f64 = 45.0;

impl GearPair {
    /// The pair of `spec`.
    ///
    /// # Errors
    /// A gear's number outside its range, gears that cannot mesh (other modules or
    /// pressure angles, an internal pinion, a ring no larger than the pinion), or a
    /// centre distance they cannot keep.
    pub fn new(spec: PairSpec) -> Result<Self, GearError> {
        let pinion = Gear::of(spec.pinion, Some(Member::Pinion))?;
        let wheel = Gear::of(spec.wheel, Some(Member::Wheel))?;
        check_meshing(&pinion, &wheel)?;
        let internal = wheel.spec.kind == GearKind::Internal;
        let sigma = if internal { -1.0 } else { 1.0 };
        let (z1, z2) = (f64::from(pinion.spec.teeth), f64::from(wheel.spec.teeth));
        let (m, alpha) = (pinion.spec.module_m, pinion.spec.pressure_angle_rad);
        let teeth_sum = z2 + sigma * z1;
        let standard_centre_m = 0.5 * m * teeth_sum;
        let shift_sum = pinion.spec.shift + wheel.spec.shift;
        // inv α' − inv α per unit of the shifts' sum.
        let per_shift = sigma * 2.0 * alpha.tan() / teeth_sum;
        let max_angle = MAX_WORKING_ANGLE_DEG.to_radians();
        let working = match spec.centre {
            CentreDistance::FromShifts => inv_inverse(inv(alpha) + per_shift * shift_sum)
                .filter(|a| *a <= max_angle)
                .ok_or(GearError::NoWorkingAngle {
                    shift_sum,
                    max_angle_deg: MAX_WORKING_ANGLE_DEG,
                })?,
            CentreDistance::Given { centre_m } => {
                let (min_m, max_m) = (
                    standard_centre_m * alpha.cos(),
                    standard_centre_m * alpha.cos() / max_angle.cos(),
                );
                if !(centre_m.is_finite() && (min_m..=max_m).contains(&centre_m)) {
                    return Err(GearError::CentreDistance {
                        given_m: centre_m,
                        min_m,
                        max_m,
                        max_angle_deg: MAX_WORKING_ANGLE_DEG,
                    });
                }
                (standard_centre_m * alpha.cos() / centre_m).min(1.0).acos()
            }
        };
        let centre_m = standard_centre_m * alpha.cos() / working.cos();
        let radii = [pinion, wheel].map(|g| g.base_radius_m / working.cos());
        let shift_sum_without_backlash = match spec.centre {
            CentreDistance::FromShifts => shift_sum,
            CentreDistance::Given { .. } => (inv(working) - inv(alpha)) / per_shift,
        };
        // Below a billionth of the module the backlash is the round-off of the
        // teeth's thicknesses: none.
        let backlash_m = Some(backlash(&pinion, &wheel, radii)).filter(|b| b.abs() > 1e-9 * m);
        let backlash_m = backlash_m.unwrap_or(0.0);
        if backlash_m < -1e-9 * m {
            return Err(GearError::TeethJam {
                centre_m,
                overlap_m: -backlash_m,
                shift_sum,
                shift_sum_max: shift_sum_without_backlash,
            });
        }
        let y = (centre_m - standard_centre_m) / m;
        let mut pair = Self {
            pinion,
            wheel,
            internal,
            speed_ratio: -sigma * z1 / z2,
            standard_centre_m,
            centre_m,
            working_pressure_angle_rad: working,
            working_pitch_radii_m: radii,
            centre_modification: y,
            tip_shortening: (!internal).then_some(shift_sum - y),
            shift_sum_without_backlash,
            backlash_m: backlash_m.max(0.0),
            clearances_m: [0.0; 2],
            path_of_contact_m: 0.0,
            contact_ratio: 0.0,
            issues: Vec::new(),
        };
        pair.shorten_tips();
        pair.contact();
        pair.check();
        Ok(pair)
    }

    /// Both tips cut down by Δy·m where Δy > 0 (GB practice: d_a = d + 2(h_a* + x −
    /// Δy)m), so that a shifted pair keeps the standard clearance; its contact ratio,
    /// interference and pointed tips are then of the shortened teeth.
    fn shorten_tips(&mut self) {
        let Some(dy) = self.tip_shortening.filter(|dy| *dy > 0.0) else {
            return;
        };
        let cut = dy * self.pinion.spec.module_m;
        self.pinion.tip_radius_m -= cut;
        self.wheel.tip_radius_m -= cut;
    }

    /// The clearances, the path of contact and the contact ratio.
    fn contact(&mut self) {
        let (p, w, a) = (&self.pinion, &self.wheel, self.centre_m);
        let across = a * self.working_pressure_angle_rad.sin();
        if self.internal {
            self.clearances_m = [
                w.root_radius_m - a - p.tip_radius_m,
                w.tip_radius_m - a - p.root_radius_m,
            ];
            self.path_of_contact_m = reach(p) - reach(w) + across;
        } else {
            self.clearances_m = [
                a - p.tip_radius_m - w.root_radius_m,
                a - w.tip_radius_m - p.root_radius_m,
            ];
            self.path_of_contact_m = reach(p) + reach(w) - across;
        }
        self.contact_ratio = self.path_of_contact_m / p.base_pitch_m;
    }

    /// The issues a designer should know.
    fn check(&mut self) {
        let mut issues = Vec::new();
        for (member, g) in [(Member::Pinion, &self.pinion), (Member::Wheel, &self.wheel)] {
            if let Some(shift_short) = g.undercut_shift_short() {
                issues.push(PairIssue::Undercut {
                    member,
                    shift_short,
                });
            }
            if g.is_pointed() {
                issues.push(PairIssue::PointedTip { member });
            }
            if let Some(thickness_m) = g.thin_tip_m() {
                issues.push(PairIssue::ThinTip {
                    member,
                    thickness_m,
                    least_m: super::gear::LEAST_TIP_THICKNESS_MODULES * g.spec.module_m,
                });
            }
        }
        let across = self.centre_m * self.working_pressure_angle_rad.sin();
        if self.internal {
            if self.wheel.tip_radius_m < self.wheel.base_radius_m {
                issues.push(PairIssue::RingTipInsideBase);
            }
            if reach(&self.wheel) < across {
                issues.push(PairIssue::TipInterference {
                    member: Member::Wheel,
                });
            }
        } else {
            for (member, g) in [(Member::Pinion, &self.pinion), (Member::Wheel, &self.wheel)] {
                if reach(g) > across {
                    issues.push(PairIssue::TipInterference { member });
                }
            }
        }
        for (member, clearance_m) in [Member::Pinion, Member::Wheel]
            .into_iter()
            .zip(self.clearances_m)
        {
            if clearance_m < 0.0 {
                issues.push(PairIssue::NoClearance {
                    member,
                    clearance_m,
                });
            }
        }
        if self.contact_ratio < 1.0 {
            issues.push(PairIssue::ContactRatioBelowOne {
                contact_ratio: self.contact_ratio,
            });
        }
        self.issues = issues;
    }
}

/// How far along the line of action a gear's tip circle reaches from its base
/// circle's tangent point, √(r_a² − r_b²) (0 where the tip is inside the base circle).
fn reach(g: &Gear) -> f64 {
    (g.tip_radius_m.powi(2) - g.base_radius_m.powi(2))
        .max(0.0)
        .sqrt()
}

/// The backlash on the working pitch circles (radii `radii`): the circular pitch
/// there less both teeth (an internal wheel's tooth fills the rest of its space).
fn backlash(pinion: &Gear, wheel: &Gear, radii: [f64; 2]) -> f64 {
    let pitch = 2.0 * std::f64::consts::PI * radii[0] / f64::from(pinion.spec.teeth);
    let thickness = |g: &Gear, r: f64| g.tooth_thickness_at(r).unwrap_or(0.0);
    pitch - thickness(pinion, radii[0]) - thickness(wheel, radii[1])
}

/// The two gears can mesh: one module and pressure angle, an external pinion, a
/// ring larger than the pinion.
fn check_meshing(pinion: &Gear, wheel: &Gear) -> Result<(), GearError> {
    let (p, w) = (&pinion.spec, &wheel.spec);
    let same = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(b.abs());
    if !(same(p.module_m, w.module_m) && same(p.pressure_angle_rad, w.pressure_angle_rad)) {
        return Err(GearError::Mismatched {
            pinion_module_m: p.module_m,
            pinion_angle_rad: p.pressure_angle_rad,
            wheel_module_m: w.module_m,
            wheel_angle_rad: w.pressure_angle_rad,
        });
    }
    if p.kind == GearKind::Internal {
        return Err(GearError::InternalPinion);
    }
    if w.kind == GearKind::Internal && w.teeth <= p.teeth {
        return Err(GearError::RingTooSmall {
            pinion: p.teeth,
            wheel: w.teeth,
            least: p.teeth + 1,
        });
    }
    Ok(())
}
