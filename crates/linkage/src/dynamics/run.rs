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
use crate::angles::unwrap_near;
use crate::error::{LinkageError, Result, RunRefusal, RunWarning, StabilityLimit};
use crate::ids::LinkId;
use crate::model::SceneProblem;
use crate::roots_util::refine;
use crate::scene::StopAction;
use crate::solve::Kinematics;

/// An end stop resolved to the link it watches.
struct Stop {
    name: String,
    link: LinkId,
    angle: f64,
    stops: bool,
}

/// Signed angle of the stop's link past its stop angle at coordinate `x`, wrapped to
/// (−π, π]; NaN where the chain does not assemble.
fn gap(rhs: &mut Rhs, x: f64, stop: &Stop) -> f64 {
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
    driver: LinkId,
    last_q: Option<f64>,
}

impl Sampler {
    fn sample(&mut self, rhs: &mut Rhs, t: f64, y: &State, segment: usize) -> Result<Sample> {
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
fn stiffness(rhs: &mut Rhs, a: &Point) -> Result<f64> {
    let (acc_x, acc_v) = rhs.linearise(a)?;
    // Eigenvalues of [[0, 1], [acc_x, acc_v]]; complex ones have |λ|² = −acc_x.
    let disc = acc_v * acc_v + 4.0 * acc_x;
    Ok(if disc >= 0.0 {
        0.5 * (acc_v.abs() + disc.sqrt())
    } else {
        (-acc_x).sqrt()
    })
}

/// The run's own rate scale, 1/s: the stiffest mode's |λ|, or the starting speed
/// where that is faster, or one over the run's length for a machine with neither
/// (no force and at rest: it does not move). Speeds are measured against it, so that
/// the tolerances and first step are the same for a machine at any scale.
fn rate_scale(stiffness_per_s: f64, start_speed: f64, t_end: f64) -> f64 {
    let rate = stiffness_per_s.max(start_speed.abs());
    if rate > 0.0 && rate.is_finite() {
        rate
    } else {
        1.0 / t_end
    }
}

/// The error of a run that spent its step budget: where it got to, and whether the
/// stiffness set its steps (then an implicit method is the change to make).
fn budget_spent(stats: &RunStats, t: f64, settings: &Settings) -> LinkageError {
    let stiff = StabilityLimit::of(settings.method, stats.stiffness_per_s)
        .filter(|l| t / (stats.steps.max(1) as f64) < 2.0 * l.h_limit_s);
    LinkageError::Run(Box::new(RunRefusal::StepBudgetSpent {
        t_end_s: settings.t_end,
        max_steps: settings.max_steps,
        reached_t_s: t,
        stiff,
    }))
}

/// Integrates the scene of `k` as `settings` say: from its start position (the
/// driver's start angle) at `settings.q_dot0`, to `t_end` or the first end stop.
///
/// # Errors
/// Invalid settings (named with their valid range), a scene without masses, a fixed
/// explicit step beyond the method's stability limit, a step-size collapse of an
/// adaptive method, or a kinematic failure the method cannot step around.
pub fn simulate(k: &Kinematics, settings: &Settings) -> Result<Simulation> {
    let mut run = Run::start(k, settings)?;
    while !run.advance(usize::MAX)? {}
    Ok(run.finish())
}

/// A run in progress, advanced a slice of steps at a time, so that a caller without
/// threads (the browser) can spread it over frames. Slicing does not change the
/// result: the steps, events and samples are those of one [`simulate`] call.
pub struct Run {
    settings: Settings,
    rhs: Rhs,
    segments: Vec<Kinematics>,
    /// The state at the end of the last accepted step.
    a: Point,
    stats: RunStats,
    stops: Vec<Stop>,
    /// Signed gap of each stop at `a`.
    gaps: Vec<f64>,
    sampler: Sampler,
    samples: Vec<Sample>,
    events: Vec<SimEvent>,
    /// Index on the output grid of the next sample (the first, at t = 0, is taken
    /// at the start).
    next_output: u64,
    pair: Option<Pair>,
    tol: Tolerance,
    max_step: f64,
    /// The next step size to try.
    h: f64,
    stages: Stages,
    controller: Controller,
    finished: bool,
    /// CPU time spent in this run so far, s.
    cpu_s: f64,
}

/// The chain as the run integrates it and the coordinate's start value and rate:
/// the driver's angle, or another link's (`settings.coordinate`, the chain driven
/// from that link), its rate `q_dot0` times the link's own rate per unit of the
/// driver's.
fn generalised_coordinate(
    base: Kinematics,
    start: &crate::motion::Solution,
    settings: &Settings,
) -> Result<(Kinematics, f64, f64)> {
    let m = base.mechanism();
    match settings.coordinate {
        Some(link) if link != m.driver.link => {
            let redriven = base.redriven(link, start)?;
            let omega = start.links[link].omega_rad_s;
            Ok((
                redriven,
                start.links[link].angle_rad(),
                omega * settings.q_dot0,
            ))
        }
        _ => {
            let x0 = m.driver.start_rad;
            Ok((base, x0, settings.q_dot0))
        }
    }
}

/// The largest step the settings allow and the first step: an adaptive pair's
/// estimate from the start (within the largest), or the fixed step.
fn first_step(
    rhs: &mut Rhs,
    settings: &Settings,
    pair: Option<Pair>,
    tol: &Tolerance,
    a: &Point,
) -> (f64, f64) {
    let max_step = if settings.step > 0.0 {
        settings.step
    } else {
        f64::INFINITY
    };
    let h = match pair {
        Some(p) => adaptive::initial_step(rhs, p, tol, a, settings.t_end).min(max_step),
        None => settings.step,
    };
    (max_step, h)
}

impl Run {
    /// Validates `settings` and sets the run up at its start state (the first sample).
    ///
    /// # Errors
    /// As [`simulate`], for what can be known before the first step.
    pub fn start(k: &Kinematics, settings: &Settings) -> Result<Self> {
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
            return Err(LinkageError::from(SceneProblem::Massless));
        }
        let (kin, x0, v0) = generalised_coordinate(base, &start, settings)?;
        let stops = resolved_stops(k, settings);
        let mut rhs = Rhs::new(kin, forces, settings.switch_coordinates);
        let segments = vec![rhs.k.clone()];
        let a = rhs.point(0.0, [x0, v0, 0.0])?;
        let stats = RunStats {
            stiffness_per_s: stiffness(&mut rhs, &a)?,
            ..Default::default()
        };
        check_stability(settings, stats.stiffness_per_s)?;
        let mut sampler = Sampler {
            driver: m.driver.link,
            last_q: None,
        };
        let samples = vec![sampler.sample(&mut rhs, 0.0, &a.y, 0)?];
        let gaps = stops.iter().map(|s| gap(&mut rhs, a.y[0], s)).collect();
        let pair = match settings.method {
            Method::Dp5 => Some(Pair::Dp5),
            Method::Dop853 => Some(Pair::Dop853),
            _ => None,
        };
        let tol = Tolerance {
            rtol: settings.rtol,
            atol: settings.atol,
            rate: rate_scale(stats.stiffness_per_s, v0, settings.t_end),
        };
        let (max_step, h) = first_step(&mut rhs, settings, pair, &tol, &a);
        Ok(Self {
            settings: settings.clone(),
            rhs,
            segments,
            a,
            stats,
            stops,
            gaps,
            sampler,
            samples,
            events: Vec::new(),
            next_output: 1,
            pair,
            tol,
            max_step,
            h,
            stages: Stages::default(),
            controller: Controller::default(),
            finished: false,
            cpu_s: clock.elapsed().as_secs_f64(),
        })
    }

    /// Takes up to `max_steps` more steps (accepted or rejected); returns whether the
    /// run is finished (it reached `t_end`, an end stop, or rest in equilibrium).
    ///
    /// # Errors
    /// As [`simulate`]; after an error the run cannot go on.
    pub fn advance(&mut self, max_steps: usize) -> Result<bool> {
        let clock = Instant::now();
        let mut taken = 0;
        let result = loop {
            if self.finished || self.a.t >= self.settings.t_end {
                self.finished = true;
                break Ok(true);
            }
            if taken >= max_steps {
                break Ok(false);
            }
            let before = self.stats.steps + self.stats.rejected_steps;
            if let Err(e) = self.step() {
                self.finished = true;
                break Err(e);
            }
            taken += (self.stats.steps + self.stats.rejected_steps - before).max(1);
        };
        self.cpu_s += clock.elapsed().as_secs_f64();
        result
    }

    /// Time reached, s.
    pub fn time_s(&self) -> f64 {
        self.a.t
    }

    /// Ends the run where it got to (normally after [`Run::advance`] returned `true`),
    /// with its cost and warnings.
    pub fn finish(mut self) -> Simulation {
        let method = self.settings.method;
        let limit = StabilityLimit::of(method, self.stats.stiffness_per_s);
        if let Some(limit) = limit.filter(|_| method.is_adaptive()) {
            // An adaptive method stays stable by itself, but when its mean step sits
            // near the stability limit it is the stiffness, not the accuracy, that
            // sets the cost.
            let t_run = self.samples.last().map_or(0.0, |s| s.t);
            let mean_step = t_run / self.stats.steps.max(1) as f64;
            if mean_step > 0.5 * limit.h_limit_s {
                self.stats.warnings.push(RunWarning::Stiff {
                    mean_step_s: mean_step,
                    limit,
                });
            }
        }
        self.stats.rhs_evaluations = self.rhs.evaluations;
        self.stats.kinematic_solves = self.rhs.solves;
        self.stats.cpu_seconds = self.cpu_s;
        Simulation {
            method,
            samples: self.samples,
            events: self.events,
            stats: self.stats,
            segments: self.segments,
        }
    }

    /// One accepted step a -> b with its events, samples and coordinate switch.
    fn step(&mut self) -> Result<()> {
        if self.stats.steps + self.stats.rejected_steps >= self.settings.max_steps {
            return Err(budget_spent(&self.stats, self.a.t, &self.settings));
        }
        let Some(b) = self.accepted_step()? else {
            return Ok(()); // at rest: the run is finished
        };
        self.stats.steps += 1;
        let segment = self.segments.len() - 1;
        let mut dense = DenseCache::new(self.pair, self.a);
        let hit = self.first_stop_crossed(&b, &mut dense)?;
        // A stop ends the run at the hit; a reported event leaves the rest of the step
        // to sample from this step's dense output, like any other.
        let stop_hit = hit.filter(|&(_, i)| self.stops[i].stops);
        let t_until = stop_hit.map_or(b.t, |(t, _)| t);
        if self.settings.output_dt.is_some() {
            while let Some(t_out) = self.output_time(self.next_output).filter(|&t| t <= t_until) {
                let y = dense.get(&mut self.rhs, &b, &mut self.stages)?.eval(t_out);
                let s = self.sampler.sample(&mut self.rhs, t_out, &y, segment)?;
                self.samples.push(s);
                self.next_output += 1;
            }
        } else if stop_hit.is_none() {
            let s = self.sampler.sample(&mut self.rhs, b.t, &b.y, segment)?;
            self.samples.push(s);
        }
        if let Some((t_hit, i)) = hit {
            let y = dense.get(&mut self.rhs, &b, &mut self.stages)?.eval(t_hit);
            let state = self.sampler.sample(&mut self.rhs, t_hit, &y, segment)?;
            let stops = self.stops[i].stops;
            self.events.push(SimEvent {
                name: self.stops[i].name.clone(),
                state,
                stopped: stops,
            });
            if stops {
                self.samples.push(state);
                self.finished = true;
                return Ok(());
            }
        }
        if self.settings.output_dt.is_some() && b.t >= self.settings.t_end {
            let last = self.samples.last().map_or(0.0, |s| s.t);
            if last < b.t {
                let s = self.sampler.sample(&mut self.rhs, b.t, &b.y, segment)?;
                self.samples.push(s);
            }
        }
        self.a = b;
        self.switch_coordinate_if_needed()
    }

    /// The time of sample `index` of the output grid, `None` past the end. Times are
    /// the index times the grid step, not sums of steps: a sum's round-off would decide
    /// whether the last sample falls on the end or just past it, differently for the
    /// same run in other units. A time within 1e-9 of a step past the end is the end.
    fn output_time(&self, index: u64) -> Option<f64> {
        let dt = self.settings.output_dt?;
        let t = index as f64 * dt;
        let end = self.settings.t_end;
        if t <= end {
            Some(t)
        } else if t - end <= 1e-9 * dt {
            Some(end)
        } else {
            None
        }
    }

    /// The next accepted step of the method, or `None` where the energy method finds
    /// the chain at rest in equilibrium (recorded as the stopping event).
    fn accepted_step(&mut self) -> Result<Option<Point>> {
        let (a, t_end, rhs) = (self.a, self.settings.t_end, &mut self.rhs);
        let h = self.h;
        Ok(Some(match (self.settings.method, self.pair) {
            (_, Some(p)) => loop {
                let h_try = self.h.min(t_end - a.t).min(self.max_step);
                let attempt = adaptive::step(
                    rhs,
                    p,
                    &self.tol,
                    &a,
                    h_try,
                    &mut self.controller,
                    &mut self.stages,
                );
                match attempt {
                    Attempt::Accepted { end, error, h_next } => {
                        self.stats.max_error_estimate = self.stats.max_error_estimate.max(error);
                        self.h = h_next;
                        break end;
                    }
                    Attempt::Rejected { h_next } => {
                        self.stats.rejected_steps += 1;
                        self.h = h_next;
                        if self.h < 1e-12 * (1.0 + a.t.abs()) {
                            return Err(step_collapsed(&a, &self.settings));
                        }
                    }
                }
            },
            (Method::EnergyIncrement, None) => match fixed::energy_increment(rhs, &a, h)? {
                Some(b) => b,
                None => {
                    let segment = self.segments.len() - 1;
                    let state = self.sampler.sample(rhs, a.t, &a.y, segment)?;
                    self.events.push(SimEvent {
                        name: "at rest in equilibrium".into(),
                        state,
                        stopped: true,
                    });
                    self.finished = true;
                    return Ok(None);
                }
            },
            (Method::SemiImplicitEuler, None) => fixed::euler(rhs, &a, h.min(t_end - a.t))?,
            (Method::ImplicitMidpoint, None) => implicit::midpoint(rhs, &a, h.min(t_end - a.t))?,
            (_, None) => fixed::rk4(rhs, &a, h.min(t_end - a.t))?,
        }))
    }

    /// The first stop crossed in the step a -> `b`, located on the dense output: its
    /// time and index. Updates the stops' gaps to `b`.
    fn first_stop_crossed(
        &mut self,
        b: &Point,
        dense: &mut DenseCache,
    ) -> Result<Option<(f64, usize)>> {
        let mut hit: Option<(f64, usize)> = None;
        for (i, stop) in self.stops.iter().enumerate() {
            let gb = gap(&mut self.rhs, b.y[0], stop);
            let ga = self.gaps[i];
            self.gaps[i] = gb;
            if !(ga.is_finite() && gb.is_finite() && ga != 0.0)
                || ga.signum() == gb.signum()
                || (ga - gb).abs() >= 1.0
            {
                continue;
            }
            let d = dense.get(&mut self.rhs, b, &mut self.stages)?;
            let rhs = &mut self.rhs;
            let t_hit = refine(self.a.t, b.t, |t| gap(rhs, d.eval(t)[0], stop)).unwrap_or(b.t);
            if hit.is_none_or(|(t, _)| t_hit < t) {
                hit = Some((t_hit, i));
            }
        }
        Ok(hit)
    }

    /// Near a dead point of the coordinate, continues in a regular one (an event).
    fn switch_coordinate_if_needed(&mut self) -> Result<()> {
        let from = self.rhs.coordinate_link();
        let Some(switched) = self.rhs.switch_if_needed(&self.a)? else {
            return Ok(());
        };
        self.segments.push(self.rhs.k.clone());
        let segment = self.segments.len() - 1;
        let state = self
            .sampler
            .sample(&mut self.rhs, switched.t, &switched.y, segment)?;
        let links = &self.rhs.k.mechanism().links;
        self.events.push(SimEvent {
            name: format!(
                "coordinate switch from {} to {}",
                links[from].name,
                links[self.rhs.coordinate_link()].name
            ),
            state,
            stopped: false,
        });
        // The step size carries over: it is a time scale of the motion, which does not
        // depend on the coordinate that describes it.
        self.a = switched;
        Ok(())
    }
}

/// The dense output of the current step, made on first use.
struct DenseCache {
    pair: Option<Pair>,
    a: Point,
    dense: Option<Dense>,
}

impl DenseCache {
    fn new(pair: Option<Pair>, a: Point) -> Self {
        Self {
            pair,
            a,
            dense: None,
        }
    }

    fn get(&mut self, rhs: &mut Rhs, b: &Point, stages: &mut Stages) -> Result<Dense> {
        if let Some(d) = &self.dense {
            return Ok(d.clone());
        }
        let d = match self.pair {
            Some(p) => adaptive::dense(rhs, p, &self.a, b, stages)?,
            None => Dense::Hermite { a: self.a, b: *b },
        };
        self.dense = Some(d.clone());
        Ok(d)
    }
}

/// The scene's end stops resolved to links (none when the settings ignore them).
fn resolved_stops(k: &Kinematics, settings: &Settings) -> Vec<Stop> {
    if !settings.use_stops {
        return Vec::new();
    }
    let m = k.mechanism();
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
}

/// Refuses a fixed explicit step beyond the method's stability limit.
fn check_stability(settings: &Settings, stiffness_per_s: f64) -> Result<()> {
    let method = settings.method;
    let (Some(h_lambda), Some(limit)) = (
        method.stability_limit(),
        StabilityLimit::of(method, stiffness_per_s),
    ) else {
        return Ok(());
    };
    if method.is_adaptive() || settings.step <= limit.h_limit_s {
        return Ok(());
    }
    Err(LinkageError::Run(Box::new(
        RunRefusal::StepBeyondStability {
            step_s: settings.step,
            limit,
            h_lambda,
        },
    )))
}

/// The error of an adaptive run whose step size collapsed at `a`.
fn step_collapsed(a: &Point, settings: &Settings) -> LinkageError {
    LinkageError::Singular {
        input_deg: a.y[0].to_degrees(),
        reason: crate::error::Singularity::StepCollapsed {
            t_s: a.t,
            rtol: settings.rtol,
            atol: settings.atol,
        },
    }
}
