//! Shaking force and moment: what the moving mechanism does to its frame over a
//! cycle at the nominal crank speed. The force is the sum of the ground joints'
//! reactions on the frame and of the loads the frame takes back (the work piece's
//! reaction to a pressing force, the weights); the moment, about a point the user
//! picks, adds the joints' couples and the reaction of the driving torque on the
//! motor's stator. Together they are −Σ m a and −Σ ((r − P) × m a + I α): only the
//! motion shakes the foundation, not a press's own working force, which the frame
//! closes on itself.
//!
//! The counterweights that balance it are [`super::counterweights`].

use serde::Serialize;

use super::torque::full_turn;
use crate::dynamics::Load;
use crate::error::{MachineAnalysis, Result};
use crate::extremum::{Extreme, locate_max};
use crate::ids::LinkId;
use crate::kinetostatics::{KinetostaticState, Kinetostatics};
use crate::model::Mechanism;
use crate::motion::{Solution, Vec2, cross};
use crate::solve::Kinematics;

const TAU: f64 = std::f64::consts::TAU;

/// Positions over the cycle.
pub const SHAKING_SAMPLES: usize = 360;

/// The load on the frame at one crank angle.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ShakingPoint {
    /// Crank angle, rad.
    pub angle_rad: f64,
    /// The force on the frame, N (x, y).
    pub force_n: [f64; 2],
    /// The moment on the frame about the chosen point, N·m.
    pub moment_n_m: f64,
}

/// Shaking force and moment over one cycle.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Shaking {
    /// The point moments are taken about, m.
    pub about_m: [f64; 2],
    /// Largest force magnitude, N (located, not sampled: [`crate::extremum`]).
    pub peak_force_n: f64,
    /// The crank angle where it is, rad.
    pub peak_force_at_rad: f64,
    /// Root mean square of the force magnitude over the crank angle, N.
    pub rms_force_n: f64,
    /// Largest moment magnitude, N·m (located).
    pub peak_moment_n_m: f64,
    /// The crank angle where it is, rad.
    pub peak_moment_at_rad: f64,
    /// The cycle.
    pub cycle: Vec<ShakingPoint>,
}

/// The load on the frame at one solved state: the ground joints' reactions reversed,
/// their couples, and the driving torque's reaction on the stator.
fn on_frame(
    m: &Mechanism,
    sol: &Solution,
    state: &KinetostaticState,
    applied: &[Load],
    about: Vec2,
) -> (Vec2, f64) {
    let ground = m.ground;
    let (mut force, mut moment) = (Vec2::zeros(), -state.torque_newton_euler);
    for l in m.moving_links() {
        // The frame takes their reactions back (a load's moment is about the world
        // origin).
        force -= applied[l].force;
        moment -= applied[l].moment - cross(&about, &applied[l].force);
    }
    let mut add = |f: Vec2, at: Vec2, couple: f64| {
        force += f;
        moment += cross(&(at - about), &f) + couple;
    };
    let nr = m.revolutes.len();
    for (j, rv) in m.revolutes.iter().enumerate() {
        // The reaction is on link b from link a.
        let f = Vec2::new(state.joints[j].force.0, state.joints[j].force.1);
        let at = sol.points[rv.point].position;
        if rv.b == ground {
            add(f, at, 0.0);
        } else if rv.a == ground {
            add(-f, at, 0.0);
        }
    }
    for (j, sl) in m.sliders.iter().enumerate() {
        // On the slider from the guide: a force at the slider's point and a couple.
        let r = &state.joints[nr + j];
        let (f, couple) = (Vec2::new(r.force.0, r.force.1), r.couple);
        let at = sol.points[sl.point].position;
        if sl.guide == ground {
            add(-f, at, -couple);
        } else if sl.slider == ground {
            add(f, at, couple);
        }
    }
    (force, moment)
}

/// Shaking force and moment (about `about`, m) of `k`'s mechanism over a turn of the
/// crank at its scene speed.
///
/// # Errors
/// A scene without kinetostatics (masses and a crank speed), an input that does not
/// turn fully, or a position that does not solve.
pub fn shaking(k: &mut Kinematics, about: [f64; 2]) -> Result<Shaking> {
    full_turn(k, MachineAnalysis::Shaking)?;
    let mut ks = Kinetostatics::new(k)?;
    let (start, w) = (
        k.mechanism().driver.start_rad,
        k.mechanism().driver.speed_rad_s,
    );
    let point = Vec2::new(about[0], about[1]);
    let mut at = |angle: f64| -> Result<ShakingPoint> {
        let state = ks.at(k, angle)?;
        let sol = ks.solution();
        let applied = ks.forces().applied_loads(sol);
        let (f, m) = on_frame(k.mechanism(), sol, &state, &applied, point);
        Ok(ShakingPoint {
            angle_rad: angle,
            force_n: [f.x, f.y],
            moment_n_m: m,
        })
    };
    let cycle = (0..SHAKING_SAMPLES)
        .map(|i| at(start + TAU.copysign(w) * i as f64 / SHAKING_SAMPLES as f64))
        .collect::<Result<Vec<_>>>()?;
    let magnitude = |p: &ShakingPoint| p.force_n[0].hypot(p.force_n[1]);
    let force = peak(&cycle, magnitude, |x| at(x).ok().as_ref().map(magnitude));
    let couple = |p: &ShakingPoint| p.moment_n_m.abs();
    let moment = peak(&cycle, couple, |x| at(x).ok().as_ref().map(couple));
    Ok(Shaking {
        about_m: about,
        peak_force_n: force.value,
        peak_force_at_rad: force.angle_rad,
        rms_force_n: (cycle.iter().map(|p| magnitude(p).powi(2)).sum::<f64>() / cycle.len() as f64)
            .sqrt(),
        peak_moment_n_m: moment.value,
        peak_moment_at_rad: moment.angle_rad,
        cycle,
    })
}

/// The largest `size` over the turn: the cycle's samples bracket it, `at` locates it.
fn peak(
    cycle: &[ShakingPoint],
    size: impl Fn(&ShakingPoint) -> f64,
    at: impl FnMut(f64) -> Option<f64>,
) -> Extreme {
    let mut samples: Vec<[f64; 2]> = cycle.iter().map(|p| [p.angle_rad, size(p)]).collect();
    samples.sort_by(|a, b| a[0].total_cmp(&b[0]));
    locate_max(&samples, Some(TAU), at).unwrap_or(Extreme {
        angle_rad: 0.0,
        value: 0.0,
    })
}

/// Adds a point mass `mass` at `at` (link coordinates) to `link`.
pub(super) fn add_point_mass(m: &mut Mechanism, link: LinkId, mass: f64, at: Vec2) {
    let l = &mut m.links[link];
    let (m0, g0, i0) = (
        l.mass_kg.unwrap_or(0.0),
        l.centroid_m.unwrap_or_default(),
        l.inertia_kg_m2.unwrap_or(0.0),
    );
    let total = m0 + mass;
    if total <= 0.0 {
        return;
    }
    let g = (g0 * m0 + at * mass) / total;
    l.mass_kg = Some(total);
    l.centroid_m = Some(g);
    l.inertia_kg_m2 = Some(i0 + m0 * (g0 - g).norm_squared() + mass * (at - g).norm_squared());
}
