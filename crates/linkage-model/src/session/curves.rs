//! Everything plotted against the crank angle, computed once per change of the
//! mechanism (not per frame): output motion, transmission angle and coupler traces
//! with the edit (they are always on screen), and what the scene models beyond
//! kinematics (input torque and force amplification; equivalent inertia J(q) and
//! moment M(q)) only when its plot is shown ([`ModelCurves`]).

use linkage::analysis::{Output, TimingDiagram, outputs, timing_of_sweep, transmission_angle_at};
use linkage::dynamics::{ForceModel, Method, Settings, simulate};
use linkage::kinetostatics::Kinetostatics;
use linkage::machine::{
    BalanceAim, Counterweight, FlywheelSizing, Shaking, SteadyState, counterweights, shaking,
    size_flywheel, steady_state, with_counterweights,
};
use linkage::scene::Models;
use linkage::sweep::{Sweep, sweep};
use linkage::{Kinematics, LinkId, LinkageError, PointId, Solution};

use super::cam_curves::CamCurves;

/// The coefficient of speed fluctuation the app sizes flywheels for (a common design
/// value for presses and punches; `linkage flywheel --delta` takes any).
pub const FLYWHEEL_DELTA: f64 = 0.05;

/// Positions per cycle in the curves (one per degree of a full turn).
pub const CURVE_STEPS: usize = 361;

/// One output (rocker or slider) over the cycle.
#[derive(Clone, Debug)]
pub struct OutputCurve {
    /// Link name.
    pub name: String,
    /// Whether it is a rocker angle (plotted in degrees) or a slider (metres).
    pub is_angle: bool,
    /// Value against input angle (deg): rocker deg or slider m.
    pub value: Vec<[f64; 2]>,
    /// Rate: deg/s or m/s.
    pub rate: Vec<[f64; 2]>,
    /// Second derivative: deg/s² or m/s².
    pub acceleration: Vec<[f64; 2]>,
}

/// A named point's path over the cycle (a coupler curve).
#[derive(Clone, Debug)]
pub struct Trace {
    /// The point in the mechanism.
    pub point: PointId,
    /// Positions in sweep order, m.
    pub path: Vec<[f64; 2]>,
}

/// The curves of one mechanism.
#[derive(Clone, Debug, Default)]
pub struct Curves {
    /// Input angles of the sweep, deg (unwrapped from the start angle).
    pub input_deg: Vec<f64>,
    /// Every rocker and slider.
    pub outputs: Vec<OutputCurve>,
    /// Transmission angle, deg, against input angle.
    pub transmission_deg: Vec<[f64; 2]>,
    /// Coupler traces of points on links not pinned to ground.
    pub traces: Vec<Trace>,
    /// Per slider: the least and greatest displacement over the cycle, m (`None` if
    /// no position gave a finite one).
    pub slide_travel_m: Vec<Option<[f64; 2]>>,
    /// Bounding box of every pin over the cycle, m: [min x, min y, max x, max y].
    pub bounds_m: [f64; 4],
    /// Sweep range, rad.
    pub range_rad: [f64; 2],
    /// Whether the input turns fully.
    pub full_rotation: bool,
    /// The timing diagram: every output against the main shaft, with its dwells.
    pub timing: TimingDiagram,
    /// Every cam joint over its turn.
    pub cams: Vec<CamCurves>,
    /// The joints' largest velocity (m/s) and acceleration (m/s²) at a position,
    /// the 90th percentile over the cycle: the view's arrows are drawn to it, so
    /// that an arrow's length compares between crank angles (a velocity scale per
    /// drawing, as the textbooks' μv), with no spike near a dead point setting it.
    pub typical_largest: [f64; 2],
}

impl Curves {
    /// Sweeps `k` and derives the kinematic curves; a cam joint's curves are taken
    /// from `earlier_cams` where the joint is unchanged ([`CamCurves::of`]).
    ///
    /// # Errors
    /// The sweep's own error (e.g. the start angle does not assemble).
    pub fn compute(k: &mut Kinematics, earlier_cams: &[CamCurves]) -> linkage::Result<Self> {
        let sw = sweep(k, CURVE_STEPS)?;
        let full_rotation = {
            let [a, b] = sw.range;
            (b - a - std::f64::consts::TAU).abs() < 1e-9
        };
        let input_deg: Vec<f64> = sw
            .solutions
            .iter()
            .map(|s| s.input_rad.to_degrees())
            .collect();
        let xy = |f: &dyn Fn(&Solution) -> f64| -> Vec<[f64; 2]> {
            sw.solutions
                .iter()
                .zip(&input_deg)
                .map(|(s, &x)| [x, f(s)])
                .filter(|p| p[1].is_finite())
                .collect()
        };
        let outputs = outputs(k)
            .into_iter()
            .map(|out| output_curve(&out, &sw, &xy))
            .collect();
        let transmission_deg =
            xy(&|s| transmission_angle_at(k, s).map_or(f64::NAN, f64::to_degrees));
        Ok(Self {
            outputs,
            transmission_deg,
            traces: traces(k, &sw),
            slide_travel_m: slide_travel(k, &sw),
            bounds_m: bounds(&sw),
            range_rad: sw.range,
            full_rotation,
            input_deg,
            timing: timing_of_sweep(k, &sw),
            cams: CamCurves::of(k.mechanism(), earlier_cams),
            typical_largest: typical_largest(k, &sw),
        })
    }
}

/// The 90th percentile over the sweep's positions of the joints' largest velocity
/// and acceleration at a position ([`Curves::typical_largest`]); 0 where none is
/// finite.
fn typical_largest(k: &Kinematics, sw: &Sweep) -> [f64; 2] {
    let joints = k.mechanism().joint_points();
    let percentile = |of: fn(&linkage::PointMotion) -> linkage::Vec2| {
        let mut largest: Vec<f64> = sw
            .solutions
            .iter()
            .map(|s| {
                joints
                    .iter()
                    .map(|&p| of(&s.points[p]).norm())
                    .filter(|v| v.is_finite())
                    .fold(0.0, f64::max)
            })
            .collect();
        largest.sort_by(f64::total_cmp);
        largest.get(largest.len() * 9 / 10).copied().unwrap_or(0.0)
    };
    [percentile(|m| m.velocity), percentile(|m| m.acceleration)]
}

/// The curves of what a scene models beyond kinematics, over the input angles of its
/// [`Curves`].
#[derive(Clone, Debug, Default)]
pub struct ModelCurves {
    /// Kinetostatic scenes: input torque, N·m.
    pub torque_n_m: Vec<[f64; 2]>,
    /// Kinetostatic scenes: force amplification (output force per N·m), absent at toggles.
    pub amplification: Vec<[f64; 2]>,
    /// Kinetostatic scenes: the flywheel by the energy method at the scene's speed,
    /// for a speed fluctuation of [`FLYWHEEL_DELTA`], or why there is none (a rocking
    /// input).
    pub flywheel: Option<Result<FlywheelSizing, LinkageError>>,
    /// Scenes with a drive: the periodic steady state (the real speed through the
    /// cycle), or why there is none.
    pub steady: Option<Result<SteadyState, LinkageError>>,
    /// Scenes with a drive: the run-up from rest, ω against t (s, rad/s), over
    /// [`RUN_UP_PERIODS`] periods of the steady state, or why there is none.
    pub run_up: Option<Result<Vec<[f64; 2]>, LinkageError>>,
    /// Kinetostatic scenes: the shaking force before and after the crank's
    /// least-squares counterweight, or why there is none.
    pub shaking: Option<Result<ShakingCurves, LinkageError>>,
    /// Dynamic scenes: equivalent inertia J(q), kg·m².
    pub inertia_kg_m2: Vec<[f64; 2]>,
    /// Dynamic scenes: equivalent moment M(q) at rest, N·m.
    pub moment_n_m: Vec<[f64; 2]>,
    /// Why a modelled curve is missing (e.g. a kinetostatic failure), if one is.
    pub notes: Vec<String>,
}

/// How many steady-state periods the run-up from rest is shown over.
pub const RUN_UP_PERIODS: f64 = 8.0;

/// The drive's run-up from rest: ω against t over [`RUN_UP_PERIODS`] periods, by
/// DOP853 at rtol 1e-8.
fn run_up(k: &Kinematics, period_s: f64) -> Result<Vec<[f64; 2]>, LinkageError> {
    let mut settings = Settings::new(Method::Dop853);
    settings.rtol = 1e-8;
    settings.atol = 1e-10;
    settings.t_end = RUN_UP_PERIODS * period_s;
    settings.output_dt = Some(period_s / 60.0);
    let sim = simulate(k, &settings)?;
    Ok(sim.samples.iter().map(|s| [s.t, s.q_dot]).collect())
}

/// The shaking force over a cycle, before and after a crank counterweight.
#[derive(Clone, Debug)]
pub struct ShakingCurves {
    /// Without a counterweight.
    pub before: Shaking,
    /// The crank counterweight that minimises the force's mean square.
    pub counterweight: Counterweight,
    /// With it.
    pub after: Shaking,
}

impl ShakingCurves {
    /// The shaking force of `k`'s mechanism about the origin, before and after.
    ///
    /// # Errors
    /// As [`shaking`] and [`counterweights`].
    pub fn compute(k: &mut Kinematics) -> Result<Self, LinkageError> {
        let before = shaking(k, [0.0, 0.0])?;
        let crank = [k.mechanism().driver.link];
        let weights = counterweights(k, &before, &crank, BalanceAim::Rms)?;
        let mut balanced = Kinematics::new(with_counterweights(k.mechanism(), &weights))?;
        let after = shaking(&mut balanced, [0.0, 0.0])?;
        Ok(Self {
            before,
            counterweight: weights[0],
            after,
        })
    }
}

impl ModelCurves {
    /// The curves the scene of `k` models, at the input angles `input_deg`.
    pub fn compute(k: &Kinematics, input_deg: &[f64]) -> Self {
        let mut k = k.clone();
        let inputs: Vec<f64> = input_deg.iter().map(|d| d.to_radians()).collect();
        let mut curves = Self::default();
        match k.mechanism().models {
            Models::Kinetostatics => curves.add_kinetostatics(&mut k, &inputs),
            Models::Dynamics => curves.add_reduced_model(&mut k, &inputs),
            Models::Kinematics => {}
        }
        if k.mechanism().models != Models::Kinematics && k.mechanism().drive.is_some() {
            let steady = steady_state(&k);
            curves.run_up = steady.as_ref().ok().map(|st| run_up(&k, st.period_s));
            curves.steady = Some(steady);
        }
        curves
    }

    fn add_kinetostatics(&mut self, k: &mut Kinematics, inputs: &[f64]) {
        self.flywheel = Some(size_flywheel(k, FLYWHEEL_DELTA));
        self.shaking = Some(ShakingCurves::compute(k));
        let mut ks = match Kinetostatics::new(k) {
            Ok(ks) => ks,
            Err(e) => {
                self.notes.push(format!("no kinetostatics: {e}"));
                return;
            }
        };
        for &input in inputs {
            let x = input.to_degrees();
            match ks.at(k, input) {
                Ok(state) => {
                    if state.torque_virtual_work.is_finite() {
                        self.torque_n_m.push([x, state.torque_virtual_work]);
                    }
                    if let Some(a) = state.amplification.filter(|a| a.is_finite()) {
                        self.amplification.push([x, a]);
                    }
                }
                Err(e) => {
                    self.notes.push(format!("kinetostatics at {x:.1} deg: {e}"));
                }
            }
        }
    }

    fn add_reduced_model(&mut self, k: &mut Kinematics, inputs: &[f64]) {
        let start = k.mechanism().driver.start_rad;
        let model = match k
            .solve(start)
            .and_then(|s0| ForceModel::new(k.mechanism(), &s0))
        {
            Ok(m) => m,
            Err(e) => {
                self.notes.push(format!("no reduced model: {e}"));
                return;
            }
        };
        let mut unit = k.empty_solution();
        for &input in inputs {
            // J and M per unit input speed.
            if k.solve_into(input, 1.0, &mut unit).is_err() {
                continue;
            }
            let r = model.reduce(&unit, 0.0);
            let x = input.to_degrees();
            if r.j.is_finite() && r.moment().is_finite() {
                self.inertia_kg_m2.push([x, r.j]);
                self.moment_n_m.push([x, r.moment()]);
            }
        }
    }
}

/// Samples a quantity of a solution over the sweep as (input deg, value) pairs.
type Sampler<'a> = &'a dyn Fn(&dyn Fn(&Solution) -> f64) -> Vec<[f64; 2]>;

fn output_curve(out: &Output, sw: &Sweep, xy: Sampler<'_>) -> OutputCurve {
    let is_angle = out.is_angle();
    let unit = if is_angle {
        f64::to_degrees
    } else {
        std::convert::identity
    };
    // Rocker angles unwrapped along the sweep so the curve has no 360 deg jumps.
    let value = match out {
        Output::Rocker { link, .. } => sw
            .solutions
            .iter()
            .zip(&sw.angles)
            .map(|(s, row)| [s.input_rad.to_degrees(), row[*link].to_degrees()])
            .collect(),
        Output::Slide { .. } => xy(&|s| out.value(s)),
    };
    OutputCurve {
        name: out.name().to_string(),
        is_angle,
        value,
        rate: xy(&|s| unit(out.rate(s))),
        acceleration: xy(&|s| unit(out.acceleration(s))),
    }
}

/// Points on links that are not pinned to ground: their paths are coupler curves
/// (points on cranks and rockers only trace circle arcs).
fn traces(k: &Kinematics, sw: &Sweep) -> Vec<Trace> {
    let m = k.mechanism();
    let pinned_to_ground = |link: LinkId| {
        link == m.ground
            || m.ground_pivot_of(link).is_some()
            || m.sliders
                .iter()
                .any(|s| s.slider == link && s.guide == m.ground)
    };
    m.point_ids()
        .zip(&m.points)
        .filter(|(_, p)| !pinned_to_ground(p.link))
        .map(|(i, _)| Trace {
            point: i,
            path: sw
                .solutions
                .iter()
                .map(|s| [s.points[i].position.x, s.points[i].position.y])
                .filter(|p| p[0].is_finite() && p[1].is_finite())
                .collect(),
        })
        .collect()
}

fn slide_travel(k: &Kinematics, sw: &Sweep) -> Vec<Option<[f64; 2]>> {
    (0..k.mechanism().sliders.len())
        .map(|i| {
            let t = sw
                .solutions
                .iter()
                .map(|s| s.slides[i].displacement_m)
                .filter(|d| d.is_finite())
                .fold([f64::INFINITY, f64::NEG_INFINITY], |a, d| {
                    [a[0].min(d), a[1].max(d)]
                });
            t[0].is_finite().then_some(t)
        })
        .collect()
}

fn bounds(sw: &Sweep) -> [f64; 4] {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in sw.solutions.iter().flat_map(|s| &s.points) {
        let (x, y) = (p.position.x, p.position.y);
        if x.is_finite() && y.is_finite() {
            b = [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)];
        }
    }
    if b[0].is_finite() {
        b
    } else {
        [-1.0, -1.0, 1.0, 1.0]
    }
}
