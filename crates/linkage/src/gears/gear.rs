//! One involute spur gear, external or internal: its circles, its tooth thickness
//! and space width at any radius, undercut and a pointed tip (GB/T 1356 basic rack:
//! h_a* = 1, c* = 0.25, α = 20° unless the designer says otherwise).
//!
//! An internal gear's shift follows ISO 21771's signs: a positive x thickens its teeth
//! and moves its tip circle towards the centre, as it thickens an external gear's
//! teeth and moves its tip outwards; the pair's formulas then hold for both kinds.

use std::f64::consts::PI;

use serde::{Deserialize, Serialize};

use super::error::{GearError, GearParam, Member};
use super::involute::{inv, pressure_angle_at};

/// Which side of the rim the teeth are on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum GearKind {
    /// Teeth outside (a pinion, a wheel).
    #[default]
    External,
    /// Teeth inside a ring.
    Internal,
}

/// A spur gear as a designer gives it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct GearSpec {
    /// The module m, metres (the pitch circle's diameter per tooth).
    pub module_m: f64,
    /// The number of teeth z.
    pub teeth: u32,
    /// The pressure angle α of the basic rack, rad.
    pub pressure_angle_rad: f64,
    /// The addendum coefficient h_a*.
    pub addendum_coefficient: f64,
    /// The clearance coefficient c*.
    pub clearance_coefficient: f64,
    /// The profile shift coefficient x (the cutter moved out by x·m).
    pub shift: f64,
    /// External or internal.
    pub kind: GearKind,
}

impl GearSpec {
    /// A standard external gear: α = 20°, h_a* = 1, c* = 0.25, no shift.
    pub fn standard(module_m: f64, teeth: u32) -> Self {
        Self {
            module_m,
            teeth,
            pressure_angle_rad: 20f64.to_radians(),
            addendum_coefficient: 1.0,
            clearance_coefficient: 0.25,
            shift: 0.0,
            kind: GearKind::External,
        }
    }

    /// The same gear with the shift `x`.
    pub fn shifted(self, x: f64) -> Self {
        Self { shift: x, ..self }
    }

    /// The same gear with internal teeth.
    pub fn internal(self) -> Self {
        Self {
            kind: GearKind::Internal,
            ..self
        }
    }
}

/// The least tooth thickness on the tip circle the textbooks allow, in modules:
/// s_a ≥ 0.25·m (0.4·m for hardened teeth, whose thin tips chip).
pub const LEAST_TIP_THICKNESS_MODULES: f64 = 0.25;

/// The ranges a gear's numbers must keep: wide enough for every gear a course or a
/// machine uses (modules of 0.05 to 100 mm, 3 to 10 000 teeth, pressure angles of
/// 10° to 35°), narrow enough that the geometry stays meaningful.
pub mod limits {
    /// Module, m.
    pub const MODULE_M: [f64; 2] = [1e-5, 1.0];
    /// Teeth.
    pub const TEETH: [u32; 2] = [3, 10_000];
    /// Pressure angle, degrees.
    pub const PRESSURE_ANGLE_DEG: [f64; 2] = [10.0, 35.0];
    /// Addendum coefficient.
    pub const ADDENDUM: [f64; 2] = [0.0, 2.0];
    /// Clearance coefficient.
    pub const CLEARANCE: [f64; 2] = [0.0, 1.0];
    /// Profile shift coefficient.
    pub const SHIFT: [f64; 2] = [-3.0, 3.0];
}

/// A gear's geometry, from its [`GearSpec`]. Radii and lengths in metres.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Gear {
    /// What it was made from.
    pub spec: GearSpec,
    /// The pitch (reference) circle's radius r = m z / 2.
    pub pitch_radius_m: f64,
    /// The base circle's radius r_b = r cos α.
    pub base_radius_m: f64,
    /// The tip circle's radius.
    pub tip_radius_m: f64,
    /// The root circle's radius.
    pub root_radius_m: f64,
    /// The circular pitch p = π m.
    pub pitch_m: f64,
    /// The base pitch p_b = p cos α (the normal pitch along the line of action).
    pub base_pitch_m: f64,
    /// The tooth thickness on the pitch circle, s = m (π/2 + 2 x tan α).
    pub tooth_thickness_m: f64,
    /// The space width on the pitch circle, e = p − s.
    pub space_width_m: f64,
}

impl Gear {
    /// The gear of `spec`.
    ///
    /// # Errors
    /// A number outside [`limits`], or a shift that leaves no rim.
    pub fn new(spec: GearSpec) -> Result<Self, GearError> {
        Self::of(spec, None)
    }

    /// The gear of `spec`, a refusal naming `member` of a pair.
    pub(crate) fn of(spec: GearSpec, member: Option<Member>) -> Result<Self, GearError> {
        check(spec, member)?;
        let m = spec.module_m;
        let (ha, c, x) = (
            spec.addendum_coefficient,
            spec.clearance_coefficient,
            spec.shift,
        );
        let r = 0.5 * m * f64::from(spec.teeth);
        let alpha = spec.pressure_angle_rad;
        let (tip, root) = match spec.kind {
            GearKind::External => (r + (ha + x) * m, r - (ha + c - x) * m),
            GearKind::Internal => (r - (ha + x) * m, r + (ha + c - x) * m),
        };
        let pitch = PI * m;
        let s = m * (0.5 * PI + 2.0 * x * alpha.tan());
        Ok(Self {
            spec,
            pitch_radius_m: r,
            base_radius_m: r * alpha.cos(),
            tip_radius_m: tip,
            root_radius_m: root,
            pitch_m: pitch,
            base_pitch_m: pitch * alpha.cos(),
            tooth_thickness_m: s,
            space_width_m: pitch - s,
        })
    }

    /// The tooth's thickness along the circle of `radius_m` (arc length), where the
    /// flank is an involute; `None` inside the base circle. Negative past a pointed tip.
    ///
    /// s_y = s r_y / r ∓ 2 r_y (inv α_y − inv α): an external tooth narrows outwards,
    /// an internal one (the ring's) widens.
    pub fn tooth_thickness_at(&self, radius_m: f64) -> Option<f64> {
        let alpha_y = pressure_angle_at(self.base_radius_m, radius_m)?;
        let spread = 2.0 * radius_m * (inv(alpha_y) - inv(self.spec.pressure_angle_rad));
        let scaled = self.tooth_thickness_m * radius_m / self.pitch_radius_m;
        Some(match self.spec.kind {
            GearKind::External => scaled - spread,
            GearKind::Internal => scaled + spread,
        })
    }

    /// The space width along the circle of `radius_m` (arc length): the circle's
    /// share per tooth less the tooth; `None` inside the base circle.
    pub fn space_width_at(&self, radius_m: f64) -> Option<f64> {
        let share = 2.0 * PI * radius_m / f64::from(self.spec.teeth);
        Some(share - self.tooth_thickness_at(radius_m)?)
    }

    /// The tooth's thickness on the tip circle (arc length); `None` where the tip
    /// circle is inside the base circle (an internal gear's tip may be).
    pub fn tip_thickness_m(&self) -> Option<f64> {
        self.tooth_thickness_at(self.tip_radius_m)
    }

    /// Whether the tooth comes to a point before the tip circle (its flanks meet
    /// inside it): an external gear with too large a shift.
    pub fn is_pointed(&self) -> bool {
        self.spec.kind == GearKind::External && self.tip_thickness_m().is_some_and(|s| s <= 0.0)
    }

    /// The tooth's thickness on the tip circle where it is thinner than the textbooks'
    /// least, [`LEAST_TIP_THICKNESS_MODULES`]·m, but not pointed (an external gear
    /// shifted far out): `None` where it is thick enough, pointed or internal.
    pub fn thin_tip_m(&self) -> Option<f64> {
        if self.spec.kind != GearKind::External {
            return None;
        }
        let least = LEAST_TIP_THICKNESS_MODULES * self.spec.module_m;
        self.tip_thickness_m().filter(|s| *s > 0.0 && *s < least)
    }

    /// The least shift that cuts the gear without undercut with a rack cutter,
    /// x_min = h_a* − z sin²α / 2 (negative where the gear has teeth to spare).
    pub fn least_shift_without_undercut(&self) -> f64 {
        least_shift(
            self.spec.addendum_coefficient,
            self.spec.pressure_angle_rad,
            self.spec.teeth,
        )
    }

    /// How far short of [`Self::least_shift_without_undercut`] the shift is, where a
    /// rack cutter undercuts the root of an external gear; `None` where it does not.
    pub fn undercut_shift_short(&self) -> Option<f64> {
        let short = self.least_shift_without_undercut() - self.spec.shift;
        (self.spec.kind == GearKind::External && short > 0.0).then_some(short)
    }
}

/// The least teeth a rack cutter cuts without undercut and without shift,
/// z_min = 2 h_a* / sin²α: 17.1 at 20° (the textbooks' 17), 32.0 at 14.5°.
pub fn least_teeth_without_undercut(addendum_coefficient: f64, pressure_angle_rad: f64) -> f64 {
    2.0 * addendum_coefficient / pressure_angle_rad.sin().powi(2)
}

/// x_min = h_a* − z sin²α / 2 = h_a* (z_min − z) / z_min.
fn least_shift(addendum_coefficient: f64, pressure_angle_rad: f64, teeth: u32) -> f64 {
    addendum_coefficient - 0.5 * f64::from(teeth) * pressure_angle_rad.sin().powi(2)
}

/// Every number of `spec` in its range, and a rim left.
fn check(spec: GearSpec, member: Option<Member>) -> Result<(), GearError> {
    let out = |param, value: f64, [min, max]: [f64; 2]| {
        let inside = value.is_finite() && (min..=max).contains(&value);
        if inside {
            Ok(())
        } else {
            Err(GearError::OutOfRange {
                member,
                param,
                value,
                min,
                max,
            })
        }
    };
    out(GearParam::Module, spec.module_m, limits::MODULE_M)?;
    let [lo, hi] = limits::TEETH;
    out(
        GearParam::Teeth,
        f64::from(spec.teeth),
        [f64::from(lo), f64::from(hi)],
    )?;
    let angle = limits::PRESSURE_ANGLE_DEG.map(f64::to_radians);
    out(GearParam::PressureAngle, spec.pressure_angle_rad, angle)?;
    out(
        GearParam::AddendumCoefficient,
        spec.addendum_coefficient,
        limits::ADDENDUM,
    )?;
    out(
        GearParam::ClearanceCoefficient,
        spec.clearance_coefficient,
        limits::CLEARANCE,
    )?;
    out(GearParam::Shift, spec.shift, limits::SHIFT)?;
    let half_teeth = 0.5 * f64::from(spec.teeth);
    let internal = spec.kind == GearKind::Internal;
    // The root circle of an external gear, the tip circle of an internal one, at
    // least a tenth of a module from the centre.
    let limit = if internal {
        half_teeth - spec.addendum_coefficient - 0.1
    } else {
        spec.addendum_coefficient + spec.clearance_coefficient - half_teeth + 0.1
    };
    let rim = if internal {
        spec.shift < limit
    } else {
        spec.shift > limit
    };
    if rim {
        Ok(())
    } else {
        Err(GearError::NoRim {
            member,
            shift: spec.shift,
            limit,
            internal,
        })
    }
}
