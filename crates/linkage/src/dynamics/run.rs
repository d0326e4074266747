//! The run: steps of the chosen method, end-stop events located on the step's dense
//! output, samples on the output grid, and the coordinate switch near dead points.

use std::f64::consts::TAU;
use web_time::Instant;

use super::adaptive::{self, Attempt, Controller, Pair, Stages, Tolerance};
use super::dense::Dense;
use super::fixed;
use super::forces::ForceModel;
use super::implicit;
use super::output::{RunStats, Sample, SimEvent, Simulation};
use super::rhs::{Point, Rhs, State};
use super::settings::{Method, Settings};
use crate::error::{LinkageError, Result};
use crate::kinematics::Kinematics;
use crate::roots_util::refine;
use crate::scene::StopAction;
use crate::sweep::unwrap_near;

/// An end stop resolved to the link it watches.
struct Stop {
    name: String,
    link: usize,
    angle: f64,
    stops: bool,
}

/// Signed angle of the stop's link past its stop angle at coordinate `x`, wrapped to
/// (−π, π]; NaN where the chain does not assemble.
fn gap(rhs: &mut Rhs<'_>, x: f64, stop: &Stop) -> f64 {
    let angle = if stop.link == rhs.coordinate_link() {
        x
    } else {
        if rhs.ensure_position(x).is_err() {
            return f64::NAN;
        }
        rhs.sol.links[stop.link].angle_rad()
    };
    let a = angle - stop.angle;
    a - (a / TAU).round() * TAU
}

/// Builds samples in the scene's input coordinate from states in the current one.
struct Sampler {
    driver: usize,
    last_q: Option<f64>,
}

impl Sampler {
    fn sample(&mut self, rhs: &mut Rhs<'_>, t: f64, y: &State, segment: usize) -> Result<Sample> {
        rhs.ensure_position(y[0])?;
        let r = rhs.reduce_here(y)?;
        let e = rhs.forces.energy(&rhs.sol, r.j, y[1]);
        let d = &rhs.sol.links[self.driver];
        let acc = r.acceleration(y[1]);
        let q = if rhs.coordinate_link() == self.driver {
            y[0]
        } else {
            let angle = d.angle_rad();
            self.last_q.map_or(angle, |last| unwrap_near(angle, last))
        };
        self.last_q = Some(q);
        Ok(Sample {
            t,
            q,
            q_dot: d.omega_rad_s * y[1],
            q_ddot: d.omega_rad_s * acc + d.alpha_rad_s2 * y[1] * y[1],
            coordinate_link: rhs.coordinate_link(),
            x: y[0],
            x_dot: y[1],
            kinetic: e.kinetic,
            potential: e.gravity + e.spring + e.forces,
            work_nonconservative: y[2],
            segment,
        })
    }
}

/// |λ| of the stiffest mode of the linearised motion at `a`, from q̈ ≈ a_x δx + a_v δv
/// (one evaluation).
fn stiffness(rhs: &mut Rhs<'_>, a: &Point) -> Result<f64> {
    let (acc_x, acc_v) = rhs.linearise(a)?;
    // Eigenvalues of [[0, 1], [acc_x, acc_v]]; complex ones have |λ|² = −acc_x.
    let disc = acc_v * acc_v + 4.0 * acc_x;
    Ok(if disc >= 0.0 {
        0.5 * (acc_v.abs() + disc.sqrt())
    } else {
        (-acc_x).sqrt()
    })
}

/// The error of a run that spent its step budget: where it got to, and what to change.
fn budget_spent(stats: &RunStats, t: f64, settings: &Settings) -> LinkageError {
    let stiff = settings
        .method
        .stability_limit()
        .map(|limit| limit / stats.stiffness_per_s)
        .filter(|h_limit| t / (stats.steps.max(1) as f64) < 2.0 * h_limit);
    let advice = match stiff {
        Some(h_limit) => format!(
            "the motion is stiff (|λ| = {:.4e} 1/s; {} is stable only below h = {h_limit:.3e} s): use --method implicit",
            stats.stiffness_per_s,
            settings.method.label()
        ),
        None => "loosen rtol/atol or take a larger step".to_string(),
    };
    LinkageError::InvalidParameter {
        name: "t_end".into(),
        value: settings.t_end,
        valid: format!(
            "the run took {} steps (the most this run may take) and reached only t = {t:.6e} s: {advice}",
            settings.max_steps
        ),
    }
}

/// Integrates the scene of `k` as `settings` say: from its start position (the
/// driver's start angle) at `settings.q_dot0`, to `t_end` or the first end stop.
///
/// # Errors
/// Invalid settings (named with their valid range), a scene without masses, a fixed
/// explicit step beyond the method's stability limit, a step-size collapse of an
/// adaptive method, or a kinematic failure the method cannot step around.
pub fn simulate(k: &Kinematics, settings: &Settings) -> Result<Simulation> {
    settings.validate()?;
    let clock = Instant::now();
    let m = k.mechanism();
    let mut base = k.clone();
    let start = {
        let mut s = base.empty_solution();
        base.solve_into(m.driver.start_rad, 1.0, &mut s)?;
        s
    };
    let forces = ForceModel::new(m, &start)?;
    if forces.is_massless() {
        return Err(LinkageError::SceneInvalid(
            "no link has a mass: there is nothing to integrate".into(),
        ));
    }
    let (kin, x0, v0) = match settings.coordinate {
        Some(link) if link != m.driver.link => {
            let redriven = base.redriven(link, &start)?;
            let omega = start.links[link].omega_rad_s;
            (
                redriven,
                start.links[link].angle_rad(),
                omega * settings.q_dot0,
            )
        }
        _ => (base, m.driver.start_rad, settings.q_dot0),
    };
    let mut rhs = Rhs::new(kin, &forces, settings.switch_coordinates);
    let mut segments = vec![rhs.k.clone()];
    let mut a = rhs.point(0.0, [x0, v0, 0.0])?;
    let mut stats = RunStats {
        stiffness_per_s: stiffness(&mut rhs, &a)?,
        ..Default::default()
    };
    let method = settings.method;
    if let Some(limit) = method.stability_limit() {
        let h_limit = limit / stats.stiffness_per_s;
        if !method.is_adaptive() && settings.step > h_limit {
            return Err(LinkageError::InvalidParameter {
                name: "step".into(),
                value: settings.step,
                valid: format!(
                    "below {h_limit:.3e} s, the stability limit of {} for the stiffest mode here (|λ| = {:.4e} 1/s, h|λ| < {limit:.3}); or use --method implicit, which has no limit",
                    method.label(),
                    stats.stiffness_per_s
                ),
            });
        }
    }
    let stops: Vec<Stop> = if settings.use_stops {
        m.forces
            .stops
            .iter()
            .filter_map(|s| {
                m.link_index(&s.link).map(|link| Stop {
                    name: s.name.clone(),
                    link,
                    angle: s.angle,
                    stops: s.action == StopAction::Stop,
                })
            })
            .collect()
    } else {
        Vec::new()
    };
    let mut sampler = Sampler {
        driver: m.driver.link,
        last_q: None,
    };
    let mut samples = vec![sampler.sample(&mut rhs, 0.0, &a.y, 0)?];
    let mut events = Vec::new();
    let mut next_output = settings.output_dt;
    let mut gaps: Vec<f64> = stops.iter().map(|s| gap(&mut rhs, a.y[0], s)).collect();
    let pair = match method {
        Method::Dp5 => Some(Pair::Dp5),
        Method::Dop853 => Some(Pair::Dop853),
        _ => None,
    };
    let tol = Tolerance {
        rtol: settings.rtol,
        atol: settings.atol,
    };
    let max_step = if settings.step > 0.0 {
        settings.step
    } else {
        f64::INFINITY
    };
    let mut h = match pair {
        Some(p) => adaptive::initial_step(&mut rhs, p, &tol, &a, settings.t_end).min(max_step),
        None => settings.step,
    };
    let mut stages = Stages::default();
    let mut controller = Controller::default();
    'run: while a.t < settings.t_end {
        if stats.steps + stats.rejected_steps >= settings.max_steps {
            return Err(budget_spent(&stats, a.t, settings));
        }
        // One accepted step a -> b, with its dense output made on demand.
        let b = match (method, pair) {
            (_, Some(p)) => loop {
                let h_try = h.min(settings.t_end - a.t).min(max_step);
                match adaptive::step(&mut rhs, p, &tol, &a, h_try, &mut controller, &mut stages) {
                    Attempt::Accepted { end, error, h_next } => {
                        stats.max_error_estimate = stats.max_error_estimate.max(error);
                        h = h_next;
                        break end;
                    }
                    Attempt::Rejected { h_next } => {
                        stats.rejected_steps += 1;
                        h = h_next;
                        if h < 1e-12 * (1.0 + a.t.abs()) {
                            return Err(LinkageError::Singular {
                                input_deg: a.y[0].to_degrees(),
                                reason: format!(
                                    "the step size collapsed at t = {:.9} s (rtol {}, atol {}): the motion is not smooth or not assemblable here",
                                    a.t, settings.rtol, settings.atol
                                ),
                            });
                        }
                    }
                }
            },
            (Method::EnergyIncrement, None) => match fixed::energy_increment(&mut rhs, &a, h)? {
                Some(b) => b,
                None => {
                    let state = sampler.sample(&mut rhs, a.t, &a.y, segments.len() - 1)?;
                    events.push(SimEvent {
                        name: "at rest in equilibrium".into(),
                        state,
                        stopped: true,
                    });
                    break 'run;
                }
            },
            (Method::SemiImplicitEuler, None) => {
                fixed::euler(&mut rhs, &a, h.min(settings.t_end - a.t))?
            }
            (Method::ImplicitMidpoint, None) => {
                implicit::midpoint(&mut rhs, &a, h.min(settings.t_end - a.t))?
            }
            (_, None) => fixed::rk4(&mut rhs, &a, h.min(settings.t_end - a.t))?,
        };
        stats.steps += 1;
        let segment = segments.len() - 1;
        let mut dense: Option<Dense> = None;
        let mut make_dense = |rhs: &mut Rhs<'_>, dense: &mut Option<Dense>| -> Result<Dense> {
            if let Some(d) = dense {
                return Ok(d.clone());
            }
            let d = match pair {
                Some(p) => adaptive::dense(rhs, p, &a, &b, &mut stages)?,
                None => Dense::Hermite { a, b },
            };
            *dense = Some(d.clone());
            Ok(d)
        };
        // The first stop crossed in this step, if any.
        let mut hit: Option<(f64, usize)> = None;
        for (i, stop) in stops.iter().enumerate() {
            let gb = gap(&mut rhs, b.y[0], stop);
            let ga = gaps[i];
            gaps[i] = gb;
            if !(ga.is_finite() && gb.is_finite() && ga != 0.0)
                || ga.signum() == gb.signum()
                || (ga - gb).abs() >= 1.0
            {
                continue;
            }
            let d = make_dense(&mut rhs, &mut dense)?;
            let t_hit = refine(a.t, b.t, |t| gap(&mut rhs, d.eval(t)[0], stop)).unwrap_or(b.t);
            if hit.is_none_or(|(t, _)| t_hit < t) {
                hit = Some((t_hit, i));
            }
        }
        // A stop ends the run at the hit; a reported event leaves the rest of the step
        // to sample from this step's dense output, like any other.
        let stop_hit = hit.filter(|&(_, i)| stops[i].stops);
        let t_until = stop_hit.map_or(b.t, |(t, _)| t);
        if let Some(dt) = settings.output_dt {
            while let Some(t_out) = next_output.filter(|&t| t <= t_until) {
                let d = make_dense(&mut rhs, &mut dense)?;
                samples.push(sampler.sample(&mut rhs, t_out, &d.eval(t_out), segment)?);
                next_output = Some(t_out + dt).filter(|&t| t <= settings.t_end);
            }
        } else if stop_hit.is_none() {
            samples.push(sampler.sample(&mut rhs, b.t, &b.y, segment)?);
        }
        if let Some((t_hit, i)) = hit {
            let d = make_dense(&mut rhs, &mut dense)?;
            let state = sampler.sample(&mut rhs, t_hit, &d.eval(t_hit), segment)?;
            events.push(SimEvent {
                name: stops[i].name.clone(),
                state,
                stopped: stops[i].stops,
            });
            if stops[i].stops {
                samples.push(state);
                break 'run;
            }
        }
        if settings.output_dt.is_some() && b.t >= settings.t_end {
            let last = samples.last().map_or(0.0, |s| s.t);
            if last < b.t {
                samples.push(sampler.sample(&mut rhs, b.t, &b.y, segment)?);
            }
        }
        a = b;
        let from = rhs.coordinate_link();
        if let Some(switched) = rhs.switch_if_needed(&a)? {
            segments.push(rhs.k.clone());
            let state = sampler.sample(&mut rhs, switched.t, &switched.y, segments.len() - 1)?;
            events.push(SimEvent {
                name: format!(
                    "coordinate switch from {} to {}",
                    m.links[from].name,
                    m.links[rhs.coordinate_link()].name
                ),
                state,
                stopped: false,
            });
            a = switched;
            // The step size carries over: it is a time scale of the motion, which does
            // not depend on the coordinate that describes it.
        }
    }
    if let Some(limit) = method.stability_limit().filter(|_| method.is_adaptive()) {
        // An adaptive method stays stable by itself, but when its mean step sits near
        // the stability limit it is the stiffness, not the accuracy, that sets the cost.
        let h_limit = limit / stats.stiffness_per_s;
        let t_run = samples.last().map_or(0.0, |s| s.t);
        let mean_step = t_run / stats.steps.max(1) as f64;
        if mean_step > 0.5 * h_limit {
            stats.warnings.push(format!(
                "stiff: the mean step {mean_step:.3e} s of {} is set by its stability limit {h_limit:.3e} s (stiffest mode |λ| = {:.4e} 1/s at the start), not by rtol; --method implicit has no such limit",
                method.label(),
                stats.stiffness_per_s
            ));
        }
    }
    stats.rhs_evaluations = rhs.evaluations;
    stats.kinematic_solves = rhs.solves;
    stats.cpu_seconds = clock.elapsed().as_secs_f64();
    Ok(Simulation {
        method,
        samples,
        events,
        stats,
        segments,
    })
}
