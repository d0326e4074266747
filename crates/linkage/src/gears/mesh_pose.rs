//! An external pair in mesh as drawn at a turn of the pinion: where each gear is
//! turned, the line of action between the base circles' tangent points, the ends of
//! the path of contact, and the points where teeth touch now. The pinion's centre
//! is at the origin and the wheel's straight above it at the working centre distance;
//! the pinion turns counter-clockwise and drives with its teeth's left flanks (seen
//! with the tooth pointing up), so the line of action runs from N1, right of the
//! line of centres on the pinion's base circle, up through the pitch point to N2.
//!
//! Both gears' teeth as [`super::generation::cut_flank`] gives them, their middles on
//! the +y axis: at a turn of 0 the pinion's tooth that drives stands with its left
//! flank on the pitch point and the wheel's tooth it drives stands left of it, so that
//! a gear drawn from its outline turned by [`MeshPose::pinion_turn_rad`] and
//! [`MeshPose::wheel_turn_rad`] meshes without backlash (the pair's shifts give none)
//! and touches where [`MeshPose::contacts`] says.

use std::f64::consts::PI;

use super::pair::GearPair;

/// The pair at one turn of the pinion.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshPose {
    /// The pinion's outline turned by this about its centre (counter-clockwise), rad.
    pub pinion_turn_rad: f64,
    /// The wheel's outline turned by this about its centre, rad.
    pub wheel_turn_rad: f64,
    /// The wheel's centre, m (the pinion's is the origin).
    pub wheel_centre_m: [f64; 2],
    /// The line of action's ends, the base circles' tangent points N1 and N2, m.
    pub line_of_action_m: [[f64; 2]; 2],
    /// The path of contact's ends: B2 where the wheel's tip circle meets the line
    /// (contact begins), B1 where the pinion's does (it ends), m.
    pub path_of_contact_m: [[f64; 2]; 2],
    /// The points where teeth touch now (one, or two while ε > 1 allows), m.
    pub contacts: Vec<[f64; 2]>,
}

impl MeshPose {
    /// The pose of an external `pair` with the pinion turned by `turn_rad`
    /// (counter-clockwise) from the turn where a tooth's left flank is on the pitch
    /// point. `None` for an internal pair.
    pub fn at(pair: &GearPair, turn_rad: f64) -> Option<Self> {
        if pair.internal {
            return None;
        }
        let (p, w) = (&pair.pinion, &pair.wheel);
        let [r1, r2] = pair.working_pitch_radii_m;
        let alpha = pair.working_pressure_angle_rad;
        let (sin, cos) = alpha.sin_cos();
        let a = pair.centre_m;
        // Half each tooth's angle on its working pitch circle.
        let psi1 = 0.5 * p.tooth_thickness_at(r1)? / r1;
        let psi2 = 0.5 * w.tooth_thickness_at(r2)? / r2;
        let (z1, z2) = (f64::from(p.spec.teeth), f64::from(w.spec.teeth));
        let n1 = [p.base_radius_m * sin, p.base_radius_m * cos];
        let direction = [-cos, sin];
        let along = |s: f64| [n1[0] + s * direction[0], n1[1] + s * direction[1]];
        let length = a * sin;
        let reach = |g: &super::gear::Gear| {
            (g.tip_radius_m.powi(2) - g.base_radius_m.powi(2))
                .max(0.0)
                .sqrt()
        };
        let (start, end) = (length - reach(w), reach(p));
        // The driving flank's contact moves along the line at r_b1 per radian; the
        // next tooth's is a base pitch behind.
        let on_pitch_point = r1 * sin;
        let base_pitch = p.base_pitch_m;
        let first = on_pitch_point + p.base_radius_m * turn_rad;
        let k_low = ((start - first) / base_pitch).ceil() as i64;
        let k_high = ((end - first) / base_pitch).floor() as i64;
        let contacts = (k_low..=k_high)
            .map(|k| along(first + k as f64 * base_pitch))
            .collect();
        Some(Self {
            pinion_turn_rad: turn_rad - psi1,
            wheel_turn_rad: -PI - psi2 - turn_rad * z1 / z2,
            wheel_centre_m: [0.0, a],
            line_of_action_m: [n1, along(length)],
            path_of_contact_m: [along(start), along(end)],
            contacts,
        })
    }
}
