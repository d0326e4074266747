//! The viewer's model, free of any GUI type: the scene being edited, its solver, the
//! current pose (always the last valid one), the analyses and curves, the polygon
//! data at the current pose, and the dynamic run where the scene has one. Every edit
//! goes through here and either succeeds or leaves a message and the old state.

pub mod curves;
pub mod dynamic_run;
pub mod params;
pub mod topology;
pub mod url_state;

use linkage::analysis::{Report, report};
use linkage::polygon::{VectorEquation, polygons};
use linkage::scene::Models;
use linkage::sweep::{csv_header, csv_row, sweep};
use linkage::{Kinematics, Mechanism, SceneFile, Solution};

use crate::catalog::builtin;
use curves::Curves;
use dynamic_run::{DynamicRun, IntegratorChoice};
use params::{LengthParam, length_params};
use topology::Topology;

/// Bisection steps when searching the assembly limit of a length: 2^-40 of the
/// interval is far below what a slider can set.
const LIMIT_BISECTIONS: usize = 40;

/// Where the scene came from.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneSource {
    /// A scene shipped in `assets/scenes`, by file name without `.ron`.
    Builtin(String),
    /// A file the user opened, by its name.
    File(String),
}

/// The viewer's state over one scene.
pub struct Session {
    source: SceneSource,
    original: SceneFile,
    scene: SceneFile,
    kin: Kinematics,
    pose: Solution,
    topology: Topology,
    lengths: Vec<LengthParam>,
    report: Result<Report, String>,
    curves: Curves,
    polygons: Vec<VectorEquation>,
    dynamics: Option<Result<DynamicRun, String>>,
    integrator: IntegratorChoice,
    message: Option<String>,
    /// Playback time of the dynamic run, s.
    time_s: f64,
    /// +1 or −1: the direction of play over a limited input range (it rocks).
    play_direction: f64,
    /// Counts rebuilds: views that cache per mechanism (plot bounds) key on it.
    generation: u64,
}

impl Session {
    /// Opens a shipped scene by key (`die_cutter`, ...).
    ///
    /// # Errors
    /// An unknown key, or a scene that does not solve (a bug in the shipped file).
    pub fn open_builtin(key: &str) -> Result<Self, String> {
        let b = builtin(key).ok_or_else(|| format!("no built-in scene named {key:?}"))?;
        Self::open_text(SceneSource::Builtin(key.to_string()), b.text)
    }

    /// Opens a scene from its RON text.
    ///
    /// # Errors
    /// The parse error with line and column, or why the mechanism does not assemble.
    pub fn open_text(source: SceneSource, text: &str) -> Result<Self, String> {
        let scene = SceneFile::parse(text).map_err(|e| e.to_string())?;
        let built = Built::new(&scene, None, IntegratorChoice::default())?;
        let lengths = length_params(&scene);
        let mut session = Self {
            source,
            original: scene.clone(),
            scene,
            kin: built.kin,
            pose: built.pose,
            topology: built.topology,
            lengths,
            report: built.report,
            curves: built.curves,
            polygons: Vec::new(),
            dynamics: built.dynamics,
            integrator: IntegratorChoice::default(),
            message: None,
            time_s: 0.0,
            play_direction: 1.0,
            generation: 0,
        };
        session.refresh_polygons();
        Ok(session)
    }

    /// Where the scene came from.
    pub fn source(&self) -> &SceneSource {
        &self.source
    }

    /// The scene as edited (what Save writes).
    pub fn scene(&self) -> &SceneFile {
        &self.scene
    }

    /// The scene as opened (slider ranges and URL state are relative to it).
    pub fn original(&self) -> &SceneFile {
        &self.original
    }

    /// The mechanism.
    pub fn mechanism(&self) -> &Mechanism {
        self.kin.mechanism()
    }

    /// The solver (for its path and tolerances).
    pub fn kinematics(&self) -> &Kinematics {
        &self.kin
    }

    /// Joints and links by index (fixed per mechanism).
    pub fn topology(&self) -> &Topology {
        &self.topology
    }

    /// The current pose: always a valid, solved one.
    pub fn pose(&self) -> &Solution {
        &self.pose
    }

    /// Current input angle, rad.
    pub fn input_rad(&self) -> f64 {
        self.pose.input_rad
    }

    /// The report (Grashof, K, strokes, limits, transmission angle) or why it failed.
    pub fn report(&self) -> &Result<Report, String> {
        &self.report
    }

    /// The curves over the cycle.
    pub fn curves(&self) -> &Curves {
        &self.curves
    }

    /// The velocity and acceleration polygon equations at the current pose.
    pub fn polygons(&self) -> &[VectorEquation] {
        &self.polygons
    }

    /// The editable lengths.
    pub fn lengths(&self) -> &[LengthParam] {
        &self.lengths
    }

    /// The dynamic run: `None` for scenes that model no dynamics.
    pub fn dynamics(&self) -> Option<&Result<DynamicRun, String>> {
        self.dynamics.as_ref()
    }

    /// The integrator settings of the dynamic run.
    pub fn integrator(&self) -> IntegratorChoice {
        self.integrator
    }

    /// Playback time of the dynamic run, s.
    pub fn time_s(&self) -> f64 {
        self.time_s
    }

    /// How many times the mechanism was rebuilt by edits (0 as opened).
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// What the last edit could not do, and why.
    pub fn message(&self) -> Option<&str> {
        self.message.as_deref()
    }

    /// What the scene models.
    pub fn models(&self) -> Models {
        self.scene.models
    }

    /// The input slider's range, deg: a full turn (wrapping) or the assembly interval.
    pub fn input_range_deg(&self) -> [f64; 2] {
        if self.curves.full_rotation {
            [0.0, 360.0]
        } else {
            let [a, b] = self.curves.range_rad;
            [a.to_degrees(), b.to_degrees()]
        }
    }

    /// Moves the crank to `input_deg` (wrapped for a full turn).
    ///
    /// On failure the pose stays and the message says why, with the reachable range.
    pub fn set_input_deg(&mut self, input_deg: f64) {
        if !input_deg.is_finite() {
            self.message = Some(format!(
                "input angle {input_deg} is not a number; the pose is unchanged"
            ));
            return;
        }
        let x = if self.curves.full_rotation {
            input_deg.rem_euclid(360.0)
        } else {
            input_deg
        }
        .to_radians();
        match self.kin.solve(x) {
            Ok(s) => {
                self.pose = s;
                self.message = None;
                self.refresh_polygons();
            }
            Err(e) => self.message = Some(e.to_string()),
        }
    }

    /// Advances the animation by `dt_s` of real time at `speed` times real speed: the
    /// dynamic run plays in its own time; kinematic scenes turn at the crank speed.
    pub fn advance(&mut self, dt_s: f64, speed: f64) {
        let dt = dt_s * speed;
        if !(dt.is_finite() && dt > 0.0) {
            return;
        }
        if let Some(Ok(run)) = &mut self.dynamics {
            let end = run.duration_s();
            self.time_s = if self.time_s + dt > end + 0.5 {
                0.0 // loop after half a second at the end
            } else {
                self.time_s + dt
            };
            if let Some((_, pose)) = run.pose_at(self.time_s) {
                self.pose = pose;
                self.refresh_polygons();
            }
            return;
        }
        let speed_rad_s = self.mechanism().driver.speed_rad_s;
        // A scene without a crank speed still turns, at one turn per 4 s, for viewing.
        let w = if speed_rad_s != 0.0 {
            speed_rad_s
        } else {
            std::f64::consts::FRAC_PI_2
        };
        let mut next = self.input_rad().to_degrees() + (w * dt * self.play_direction).to_degrees();
        if !self.curves.full_rotation {
            let [a, b] = self.input_range_deg();
            if next > b || next < a {
                self.play_direction = -self.play_direction;
                next = next.clamp(a, b);
            }
        }
        self.set_input_deg(next);
    }

    /// Sets the playback time of the dynamic run and shows its pose.
    pub fn set_time_s(&mut self, t: f64) {
        if let Some(Ok(run)) = &mut self.dynamics {
            let t = t.clamp(0.0, run.duration_s());
            if let Some((_, pose)) = run.pose_at(t) {
                self.time_s = t;
                self.pose = pose;
                self.refresh_polygons();
            }
        }
    }

    /// Sets length `index` to `value` (scene units).
    ///
    /// If the chain cannot assemble at the current input with it, nothing changes and
    /// the message names the cause and the limit found by bisection.
    pub fn set_length(&mut self, index: usize, value: f64) {
        let Some(param) = self.lengths.get(index).cloned() else {
            return;
        };
        let mut scene = self.scene.clone();
        if let Err(e) = param.apply(&mut scene, value) {
            self.message = Some(e);
            return;
        }
        if let Err(why) = self.rebuild(scene) {
            let limit = self.length_limit(&param, value);
            let unit = unit_label(&self.scene);
            let at = self.input_rad().to_degrees();
            self.message = Some(match limit {
                Some(l) => format!(
                    "{} = {value:.4} {unit} cannot assemble at input {at:.2} deg: {why}. At this input {} can go to {l:.4} {unit}; the last valid pose stays.",
                    param.label, param.label
                ),
                None => format!(
                    "{} = {value:.4} {unit}: {why}; the last valid pose stays.",
                    param.label
                ),
            });
        }
    }

    /// Sets the constant of spring `index`, N/m.
    pub fn set_spring_k(&mut self, index: usize, k_n_per_m: f64) {
        if !(k_n_per_m.is_finite() && k_n_per_m >= 0.0) {
            self.message = Some(format!(
                "spring constant {k_n_per_m} N/m is invalid: it must be finite and >= 0"
            ));
            return;
        }
        let mut scene = self.scene.clone();
        let Some(spring) = scene.forces.springs.get_mut(index) else {
            return;
        };
        spring.k_n_per_m = k_n_per_m;
        if let Err(why) = self.rebuild(scene) {
            self.message = Some(why);
        }
    }

    /// Sets the mass of link `index`, kg.
    pub fn set_mass(&mut self, index: usize, mass_kg: f64) {
        if !(mass_kg.is_finite() && mass_kg > 0.0) {
            self.message = Some(format!(
                "mass {mass_kg} kg is invalid: it must be finite and > 0"
            ));
            return;
        }
        let mut scene = self.scene.clone();
        let Some(link) = scene.links.get_mut(index) else {
            return;
        };
        // Scale the inertia with the mass: same shape, denser material.
        if let (Some(old), Some(i)) = (link.mass, link.inertia.as_mut())
            && old > 0.0
        {
            *i *= mass_kg / old;
        }
        link.mass = Some(mass_kg);
        if let Err(why) = self.rebuild(scene) {
            self.message = Some(why);
        }
    }

    /// The assembly branches of the chain, by the point of each dyad: (point, branch
    /// in words, whether it differs from the scene as opened).
    pub fn branches(&self) -> Vec<(String, String, bool)> {
        let m = self.mechanism();
        m.branches
            .iter()
            .map(|(p, b)| {
                let name = m.points[*p].name.clone();
                let flipped = self
                    .original
                    .branches
                    .get(&name)
                    .is_some_and(|orig| orig != b);
                (name, branch_words(b), flipped)
            })
            .collect()
    }

    /// Flips the assembly branch of the dyad at `point`.
    pub fn flip_branch(&mut self, point: &str) {
        let m = self.mechanism();
        let Some(b) = m
            .branches
            .iter()
            .find(|(p, _)| m.points[*p].name == point)
            .map(|(_, b)| b.flipped())
        else {
            return;
        };
        let mut scene = self.scene.clone();
        scene.branches.insert(point.to_string(), b);
        if let Err(why) = self.rebuild(scene) {
            self.message = Some(format!("flipping the branch at {point}: {why}"));
        }
    }

    /// Changes the integrator of the dynamic run and runs it again.
    pub fn set_integrator(&mut self, choice: IntegratorChoice) {
        self.integrator = choice;
        if self.scene.models == Models::Dynamics {
            self.dynamics = Some(DynamicRun::compute(&self.kin, choice));
            self.generation += 1;
            self.time_s = self.time_s.min(self.dynamics_duration());
        }
    }

    /// Puts back the scene as opened.
    pub fn reset(&mut self) {
        let scene = self.original.clone();
        if let Err(why) = self.rebuild(scene) {
            self.message = Some(why);
        }
    }

    /// The edited scene as RON text.
    ///
    /// # Errors
    /// Serialisation failure, as text.
    pub fn to_ron(&self) -> Result<String, String> {
        self.scene.to_ron().map_err(|e| e.to_string())
    }

    /// The current mechanism's sweep as CSV, in the `linkage sweep` format (same
    /// header, SI units, velocities at the scene's crank speed).
    ///
    /// # Errors
    /// The sweep's error, as text.
    pub fn sweep_csv(&self) -> Result<String, String> {
        let mut k = self.kin.clone();
        let sw = sweep(&mut k, curves::CURVE_STEPS).map_err(|e| e.to_string())?;
        let m = k.mechanism();
        let mut out = csv_header(m).join(",");
        out.push('\n');
        for (s, angles) in sw.solutions.iter().zip(&sw.angles) {
            let row: Vec<String> = csv_row(m, s, angles).iter().map(f64::to_string).collect();
            out.push_str(&row.join(","));
            out.push('\n');
        }
        Ok(out)
    }

    fn dynamics_duration(&self) -> f64 {
        match &self.dynamics {
            Some(Ok(run)) => run.duration_s(),
            _ => 0.0,
        }
    }

    /// Rebuilds everything from `scene` at the current input; on failure nothing
    /// changes.
    fn rebuild(&mut self, scene: SceneFile) -> Result<(), String> {
        let built = Built::new(&scene, Some(self.input_rad()), self.integrator)?;
        self.scene = scene;
        self.kin = built.kin;
        self.pose = built.pose;
        self.topology = built.topology;
        self.report = built.report;
        self.curves = built.curves;
        self.dynamics = built.dynamics;
        self.time_s = 0.0;
        self.message = None;
        self.generation += 1;
        self.refresh_polygons();
        Ok(())
    }

    /// The length closest to `bad` (between the current, valid length and `bad`) at
    /// which the chain still assembles at the current input.
    fn length_limit(&self, param: &LengthParam, bad: f64) -> Option<f64> {
        let mut good = param.value(&self.scene)?;
        let mut bad = bad;
        let input = self.input_rad();
        let assembles = |len: f64| {
            let mut s = self.scene.clone();
            param.apply(&mut s, len).is_ok()
                && Mechanism::from_scene(&s)
                    .and_then(Kinematics::new)
                    .and_then(|mut k| k.solve(input))
                    .is_ok()
        };
        for _ in 0..LIMIT_BISECTIONS {
            let mid = 0.5 * (good + bad);
            if assembles(mid) {
                good = mid;
            } else {
                bad = mid;
            }
        }
        Some(good)
    }

    fn refresh_polygons(&mut self) {
        self.polygons = polygons(&self.kin, &self.pose);
    }
}

/// A mechanism built from a scene with everything derived from it.
struct Built {
    kin: Kinematics,
    pose: Solution,
    topology: Topology,
    report: Result<Report, String>,
    curves: Curves,
    dynamics: Option<Result<DynamicRun, String>>,
}

impl Built {
    /// Builds at `input` (or the scene's start angle).
    fn new(
        scene: &SceneFile,
        input: Option<f64>,
        integrator: IntegratorChoice,
    ) -> Result<Self, String> {
        let mech = Mechanism::from_scene(scene).map_err(|e| e.to_string())?;
        let mut kin = Kinematics::new(mech).map_err(|e| e.to_string())?;
        let start = kin.mechanism().driver.start_rad;
        let pose = kin
            .solve(input.unwrap_or(start))
            .map_err(|e| e.to_string())?;
        let curves = Curves::compute(&mut kin).map_err(|e| e.to_string())?;
        let report = report(&mut kin).map_err(|e| e.to_string());
        let dynamics =
            (scene.models == Models::Dynamics).then(|| DynamicRun::compute(&kin, integrator));
        Ok(Self {
            topology: Topology::of(kin.mechanism()),
            kin,
            pose,
            report,
            curves,
            dynamics,
        })
    }
}

fn branch_words(b: &linkage::scene::Branch) -> String {
    use linkage::scene::Branch;
    match b {
        Branch::Left(a, c) => format!("left of {a}->{c}"),
        Branch::Right(a, c) => format!("right of {a}->{c}"),
        Branch::Along => "ahead along the guide".into(),
        Branch::Against => "behind along the guide".into(),
    }
}

/// The scene's length unit as shown on sliders.
pub fn unit_label(scene: &SceneFile) -> &'static str {
    use linkage::scene::LengthUnit;
    match scene.length_unit {
        LengthUnit::Metre => "m",
        LengthUnit::Millimetre => "mm",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_scene_computes_only_what_it_models() {
        let kin = Session::open_builtin("slider_crank").expect("opens");
        assert!(kin.dynamics().is_none());
        assert!(kin.curves().torque_n_m.is_empty() && kin.curves().inertia_kg_m2.is_empty());

        let ks = Session::open_builtin("die_cutter").expect("opens");
        assert!(ks.dynamics().is_none());
        assert!(ks.curves().torque_n_m.len() > 300, "torque over the cycle");
        assert!(ks.curves().inertia_kg_m2.is_empty());

        let dy = Session::open_builtin("gravity_flipper").expect("opens");
        let run = dy.dynamics().expect("a run").as_ref().expect("runs");
        // The CLI's DOP853 run reaches the end stop at t = 0.244660 s; rtol 1e-8 here.
        assert!(
            (run.duration_s() - 0.244660).abs() < 1e-5,
            "{}",
            run.duration_s()
        );
        assert!(!dy.curves().inertia_kg_m2.is_empty() && !dy.curves().moment_n_m.is_empty());
    }

    #[test]
    fn non_finite_edits_leave_a_message_and_the_pose() {
        let mut s = Session::open_builtin("quick_return").expect("opens");
        let pose = s.pose().clone();
        s.set_input_deg(f64::NAN);
        assert!(s.message().expect("message").contains("not a number"));
        s.set_length(0, f64::INFINITY);
        assert!(s.message().expect("message").contains("positive length"));
        s.set_spring_k(0, -1.0); // no spring: nothing to change, no panic
        assert_eq!(s.pose(), &pose);
    }

    #[test]
    fn playback_follows_the_run_and_loops() {
        let mut s = Session::open_builtin("gravity_flipper").expect("opens");
        let start = s.input_rad();
        s.advance(0.1, 1.0);
        assert!((s.time_s() - 0.1).abs() < 1e-12);
        assert!(
            s.input_rad() < start,
            "the table falls: link 1 turns clockwise"
        );
        s.advance(10.0, 1.0);
        assert_eq!(s.time_s(), 0.0, "loops after the end");
    }
}
