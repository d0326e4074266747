//! `linkage simulate`: samples on a uniform time grid with every link's angle and
//! speed and the energy terms; JSON adds the events and the run's cost.

use linkage::dynamics::{Method, Settings, Simulation, simulate};
use linkage::machine::steady_state;
use linkage::{Kinematics, LinkId, Mechanism};
use serde_json::{Value, json};

use crate::args::{Format, MethodArg, SceneArgs, SimArgs};
use crate::error::{CliError, Result};
use crate::io::{check_finite, describe, json_text, load, to_csv};

impl MethodArg {
    /// The solver's method.
    pub fn method(self) -> Method {
        match self {
            MethodArg::Energy => Method::EnergyIncrement,
            MethodArg::Euler => Method::SemiImplicitEuler,
            MethodArg::Rk4 => Method::Rk4,
            MethodArg::Implicit => Method::ImplicitMidpoint,
            MethodArg::Dp5 => Method::Dp5,
            MethodArg::Dop853 => Method::Dop853,
        }
    }
}

impl SimArgs {
    /// The solver settings for `mech`.
    pub fn settings(&self, mech: &Mechanism) -> Result<Settings> {
        let method = self.method.method();
        let mut s = Settings::new(method);
        match method {
            Method::EnergyIncrement => s.step = self.dphi,
            _ => {
                if let Some(dt) = self.dt {
                    s.step = dt;
                }
            }
        }
        s.rtol = self.rtol;
        s.atol = self.atol;
        s.t_end = self.t_end;
        s.use_stops = !self.no_stops;
        s.output_dt = Some(self.dt_out);
        s.switch_coordinates = !self.no_switch;
        if let Some(name) = &self.coordinate {
            let link = mech.link_index(name).ok_or_else(|| {
                CliError::refused(format!(
                    "no link named `{name}` for --coordinate (links: {})",
                    mech.moving_links()
                        .map(|l| mech.links[l].name.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                ))
            })?;
            s.coordinate = Some(link);
        }
        Ok(s)
    }
}

/// Every moving link's (name, angle, omega) at each sample, angles unwrapped along
/// the run like `sweep`.
fn link_rows(sim: &mut Simulation, mech: &Mechanism) -> Result<Vec<Vec<f64>>> {
    let links: Vec<LinkId> = mech.moving_links().collect();
    let mut rows: Vec<Vec<f64>> = Vec::with_capacity(sim.samples.len());
    for s in sim.samples.clone() {
        let pose = sim
            .pose(&s)
            .map_err(|e| CliError::refused(format!("at t = {} s: {e}", s.t)))?;
        let mut row = Vec::with_capacity(2 * links.len());
        for (n, &l) in links.iter().enumerate() {
            let theta = pose.links[l].angle_rad();
            let theta = match rows.last() {
                Some(p) => linkage::sweep::unwrap_near(theta, p[2 * n]),
                None => theta,
            };
            row.extend([theta, pose.links[l].omega_rad_s]);
        }
        rows.push(row);
    }
    Ok(rows)
}

/// Runs the simulation and formats it.
pub fn run(args: &SceneArgs, sim_args: &SimArgs, format: Format) -> Result<String> {
    let k: Kinematics = load(args)?;
    let m = k.mechanism().clone();
    let settings = sim_args.settings(&m)?;
    let mut sim = simulate(&k, &settings)?;
    let mut header = vec!["t".to_string(), "q".into(), "q_dot".into()];
    for l in m.moving_links() {
        header.push(format!("{}_theta", m.links[l].name));
        header.push(format!("{}_omega", m.links[l].name));
    }
    header.extend(
        [
            "kinetic_j",
            "potential_j",
            "work_nonconservative_j",
            "energy_balance_j",
        ]
        .map(String::from),
    );
    let link_rows = link_rows(&mut sim, &m)?;
    let mut rows = Vec::with_capacity(sim.samples.len());
    for (s, links) in sim.samples.iter().zip(link_rows) {
        let mut row = vec![s.t, s.q, s.q_dot];
        row.extend(links);
        row.extend([
            s.kinetic,
            s.potential,
            s.work_nonconservative,
            s.energy_balance(),
        ]);
        check_finite(&row, "simulation")?;
        rows.push(row);
    }
    match format {
        Format::Csv => to_csv(&header, &rows),
        Format::Json => {
            let mut events = Vec::new();
            for e in sim.events.clone() {
                let pose = sim.pose(&e.state)?;
                let links: serde_json::Map<String, Value> = m
                    .moving_links()
                    .map(|l| {
                        (
                            m.links[l].name.clone(),
                            json!({"theta": pose.links[l].angle_rad(), "omega": pose.links[l].omega_rad_s}),
                        )
                    })
                    .collect();
                events.push(json!({
                    "name": e.name, "t": e.state.t, "q": e.state.q, "q_dot": e.state.q_dot,
                    "q_ddot": e.state.q_ddot, "stopped": e.stopped,
                    "coordinate": m.links[e.state.coordinate_link].name, "links": links,
                }));
            }
            json_text(&json!({
                "scene": m.name,
                "method": sim_args.method.method().label(),
                "step": settings.step,
                "rtol": settings.rtol,
                "atol": settings.atol,
                "columns": header,
                "rows": rows,
                "events": events,
                "stats": {
                    "steps": sim.stats.steps,
                    "rejected_steps": sim.stats.rejected_steps,
                    "rhs_evaluations": sim.stats.rhs_evaluations,
                    "kinematic_solves": sim.stats.kinematic_solves,
                    "cpu_seconds": sim.stats.cpu_seconds,
                    "estimated_error": sim.stats.max_error_estimate,
                    "stiffness_per_s": sim.stats.stiffness_per_s,
                    "max_energy_balance_error_j": sim.energy_drift(),
                    "warnings": sim.stats.warnings.iter().map(crate::run_words::warning).collect::<Vec<_>>(),
                },
            }))
        }
    }
}

/// `simulate --steady`: the periodic steady state, one turn of the crank's speed;
/// JSON adds the figures.
pub fn steady(args: &SceneArgs, format: Format) -> Result<String> {
    let k = load(args)?;
    let s = steady_state(&k).map_err(|e| describe(args, e))?;
    match format {
        Format::Csv => {
            let header = ["t_s", "angle_rad", "speed_rad_s"].map(String::from);
            let rows: Vec<Vec<f64>> = s
                .cycle
                .iter()
                .map(|p| vec![p.t_s, p.angle_rad, p.speed_rad_s])
                .collect();
            to_csv(&header, &rows)
        }
        Format::Json => json_text(&json!({"scene": k.mechanism().name, "steady_state": s})),
    }
}
