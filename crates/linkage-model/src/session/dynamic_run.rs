//! The forward-dynamics run of a dynamic scene (computed off the frame, `run_job`) once
//! per change of the scene or integrator settings, and played back frame by frame.

use linkage::Solution;
use linkage::dynamics::{Method, RunStats, Sample, Settings, Simulation};

/// Output interval of the run, s: 2 ms gives smooth playback and plots.
pub const OUTPUT_DT_S: f64 = 2e-3;

/// Longest simulated time, s (a run that hits an end stop ends earlier).
pub const RUN_TIME_S: f64 = 3.0;

/// Integrator choice the user makes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IntegratorChoice {
    /// Method.
    pub method: Method,
    /// Relative tolerance (adaptive methods).
    pub rtol: f64,
    /// Fixed step, s (fixed-step methods; rad for the energy method).
    pub step: f64,
}

impl Default for IntegratorChoice {
    fn default() -> Self {
        Self {
            method: Method::Dop853,
            rtol: 1e-8,
            step: 1e-4,
        }
    }
}

/// Every method the user can pick, in the order of the menu.
pub const METHODS: [Method; 6] = [
    Method::Dop853,
    Method::Dp5,
    Method::Rk4,
    Method::ImplicitMidpoint,
    Method::SemiImplicitEuler,
    Method::EnergyIncrement,
];

/// The solver settings of a choice: the app's run length and output grid.
pub fn settings_for(choice: IntegratorChoice) -> Settings {
    let mut settings = Settings::new(choice.method);
    if choice.method.is_adaptive() {
        settings.rtol = choice.rtol;
        settings.atol = choice.rtol * 1e-2;
    } else {
        settings.step = choice.step;
    }
    settings.t_end = RUN_TIME_S;
    settings.output_dt = Some(OUTPUT_DT_S);
    settings
}

/// A finished run with its plot data.
pub struct DynamicRun {
    /// The settings used.
    pub choice: IntegratorChoice,
    /// The run itself (samples on the output grid, events, stats).
    pub sim: Simulation,
    /// Input rate against input angle: (deg, rad/s).
    pub omega_phi: Vec<[f64; 2]>,
    /// Input rate against time: (s, rad/s).
    pub omega_t: Vec<[f64; 2]>,
    /// Input angle against time: (s, deg).
    pub phi_t: Vec<[f64; 2]>,
    /// Largest drift of the energy balance over the run, J.
    pub energy_drift_j: f64,
}

impl DynamicRun {
    /// The plot data of a finished run.
    pub fn from_simulation(choice: IntegratorChoice, sim: Simulation) -> Self {
        let samples = &sim.samples;
        let finite = |p: &[f64; 2]| p[0].is_finite() && p[1].is_finite();
        let omega_phi = samples
            .iter()
            .map(|s| [s.q.to_degrees(), s.q_dot])
            .filter(finite)
            .collect();
        let omega_t = samples
            .iter()
            .map(|s| [s.t, s.q_dot])
            .filter(finite)
            .collect();
        let phi_t = samples
            .iter()
            .map(|s| [s.t, s.q.to_degrees()])
            .filter(finite)
            .collect();
        let energy_drift_j = sim.energy_drift();
        Self {
            choice,
            sim,
            omega_phi,
            omega_t,
            phi_t,
            energy_drift_j,
        }
    }

    /// Duration of the run, s.
    pub fn duration_s(&self) -> f64 {
        let last = self.sim.samples.last().map_or(0.0, |s| s.t);
        let stop = self
            .sim
            .events
            .iter()
            .find(|e| e.stopped)
            .map_or(0.0, |e| e.state.t);
        last.max(stop)
    }

    /// The run's cost and error estimate.
    pub fn stats(&self) -> &RunStats {
        &self.sim.stats
    }

    /// The sample at time `t` (the last one at or before it; the stop state after the
    /// last sample).
    pub fn sample_at(&self, t: f64) -> Option<Sample> {
        let samples = &self.sim.samples;
        let i = samples.partition_point(|s| s.t <= t);
        let last = samples.get(i.saturating_sub(1)).copied();
        match self.sim.events.iter().find(|e| e.stopped) {
            Some(e) if t >= e.state.t => Some(e.state),
            _ => last,
        }
    }

    /// The full pose at time `t`.
    pub fn pose_at(&mut self, t: f64) -> Option<(Sample, Solution)> {
        let s = self.sample_at(t)?;
        let pose = self.sim.pose(&s).ok()?;
        Some((s, pose))
    }
}
