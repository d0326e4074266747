//! `linkage simulate`: samples on a uniform time grid with every link's angle and
//! speed and the energy terms; JSON adds the events and the run's cost.

use linkage::dynamics::{Method, Sample, simulate};
use linkage::{Kinematics, Solution};
use serde_json::{Value, json};

use crate::commands::{check_finite, json_text, load, to_csv};
use crate::{Format, SceneArgs};

/// Every moving link's (name, angle, omega) at a state of the run.
fn link_states(
    k: &mut Kinematics,
    sol: &mut Solution,
    s: &Sample,
) -> Result<Vec<(String, f64, f64)>, String> {
    k.solve_into(s.q, s.q_dot, sol)
        .map_err(|e| format!("at t = {} s: {e}", s.t))?;
    let m = k.mechanism();
    Ok(m.moving_links()
        .map(|l| {
            (
                m.links[l].name.clone(),
                sol.links[l].angle_rad(),
                sol.links[l].omega_rad_s,
            )
        })
        .collect())
}

/// Runs the simulation and formats it.
pub fn run(
    args: &SceneArgs,
    method: Method,
    step: f64,
    t_end: f64,
    stops: bool,
    dt_out: f64,
    format: Format,
) -> Result<String, String> {
    let mut k = load(args)?;
    let sim = simulate(&mut k, method, step, t_end, 0.0, stops).map_err(|e| e.to_string())?;
    let grid = sim.resample(dt_out);
    let mut sol = k.empty_solution();
    let m = k.mechanism().clone();
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
    let mut rows = Vec::with_capacity(grid.len());
    let mut previous: Option<Vec<f64>> = None;
    for s in &grid {
        let mut row = vec![s.t, s.q, s.q_dot];
        let links = link_states(&mut k, &mut sol, s)?;
        for (n, (_, theta, omega)) in links.iter().enumerate() {
            // Angles unwrapped along the run, like `sweep`.
            let theta = match &previous {
                Some(p) => linkage::sweep::unwrap_near(*theta, p[3 + 2 * n]),
                None => *theta,
            };
            row.extend([theta, *omega]);
        }
        row.extend([
            s.kinetic,
            s.potential,
            s.work_nonconservative,
            s.energy_balance(),
        ]);
        check_finite(&row, "simulation")?;
        previous = Some(row.clone());
        rows.push(row);
    }
    match format {
        Format::Csv => to_csv(&header, &rows),
        Format::Json => {
            let mut events = Vec::new();
            for e in &sim.events {
                let links: serde_json::Map<String, Value> =
                    link_states(&mut k, &mut sol, &e.state)?
                        .into_iter()
                        .map(|(n, th, w)| (n, json!({"theta": th, "omega": w})))
                        .collect();
                events.push(
                    json!({"name": e.name, "t": e.state.t, "q": e.state.q, "q_dot": e.state.q_dot,
                    "stopped": e.stopped, "links": links}),
                );
            }
            let e0 = sim.samples.first().map_or(0.0, Sample::energy_balance);
            let drift = sim
                .samples
                .iter()
                .map(|s| (s.energy_balance() - e0).abs())
                .fold(0.0, f64::max);
            json_text(&json!({
                "scene": m.name,
                "method": format!("{:?}", sim.method),
                "step": step,
                "columns": header,
                "rows": rows,
                "events": events,
                "stats": {
                    "steps": sim.stats.steps,
                    "rhs_evaluations": sim.stats.rhs_evaluations,
                    "cpu_seconds": sim.stats.cpu_seconds,
                    "max_energy_balance_error_j": drift,
                },
            }))
        }
    }
}
