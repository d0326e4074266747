//! Analyses of any 1-DOF chain: assembly range, limit positions of every output
//! (found by Brent root-finding on the output's velocity ratio, bracketed on a grid),
//! strokes, swings, time ratio K, Grashof class, transmission angle and toggles.

use serde::Serialize;

use crate::closed_form::Group;
use crate::error::{AssemblyFailure, LinkageError, Result};
use crate::kinematics::{Kinematics, PathKind};
use crate::motion::{Solution, Vec2, cross, perp};
use crate::roots_util::{refine, sign_changes};

pub use crate::assembly::AssemblyRanges;

const TAU: f64 = std::f64::consts::TAU;
/// Velocity ratio below which an output counts as at rest, per radian of input and,
/// for a slider, per metre of the mechanism's size: dimensionless, so that a 50 µm
/// mechanism rests exactly when its 50 m twin does (round-off of a ratio of order 1 is
/// 1e-16; a real limit's neighbours on the grid have ratios of 1e-3 and up).
const RESTING_RATE: f64 = 1e-9;

/// Assembly ranges: of a closed-form chain by root-finding on the groups' margins; of
/// a chain solved by Newton alone, the range its branch was traced over (between
/// folds) when it was built.
pub fn assembly_ranges_of(k: &Kinematics) -> AssemblyRanges {
    k.assembly_ranges()
}

/// The input interval a sweep covers: a full turn from the start angle, or the
/// assembly interval that holds the start angle (ends pulled in by a hair, since
/// the ends are dead points).
pub fn sweep_range(k: &Kinematics) -> Result<([f64; 2], bool)> {
    let start = k.mechanism().driver.start_rad;
    let ranges = assembly_ranges_of(k);
    if ranges.full_rotation {
        return Ok(([start, start + std::f64::consts::TAU], true));
    }
    let [a, b] = ranges
        .containing(start)
        .ok_or_else(|| LinkageError::CannotAssemble {
            input_deg: start.to_degrees(),
            reason: AssemblyFailure::Nowhere,
            reachable: ranges.clone(),
        })?;
    // Velocities grow as 1/√(distance to the dead point) and accelerations as its
    // -3/2 power: a hair of 1e-6 of the range keeps the round-off in the range's ends
    // (an ulp of the input) below 1e-9 of the end rows' values.
    let hair = 1e-6 * (b - a);
    Ok(([a + hair, b - hair], false))
}

/// An output whose extremes are sought: a link pinned to ground, or a slider.
#[derive(Clone, Debug, PartialEq)]
pub enum Output {
    /// Angle of a link pinned to ground (other than the input).
    Rocker {
        /// Link index.
        link: usize,
        /// Link name.
        name: String,
    },
    /// Displacement of a prismatic joint.
    Slide {
        /// Index into `Mechanism::sliders`.
        slider: usize,
        /// Slider link name.
        name: String,
    },
}

impl Output {
    /// Display name.
    pub fn name(&self) -> &str {
        match self {
            Self::Rocker { name, .. } | Self::Slide { name, .. } => name,
        }
    }

    /// Value at a solution (rad or m; rocker angles in (-π, π]).
    pub fn value(&self, s: &Solution) -> f64 {
        match self {
            Self::Rocker { link, .. } => s.links[*link].angle_rad(),
            Self::Slide { slider, .. } => s.slides[*slider].displacement_m,
        }
    }

    /// Rate at a solution (rad/s or m/s).
    pub fn rate(&self, s: &Solution) -> f64 {
        match self {
            Self::Rocker { link, .. } => s.links[*link].omega_rad_s,
            Self::Slide { slider, .. } => s.slides[*slider].velocity_m_s,
        }
    }

    /// Second derivative at a solution (rad/s² or m/s²).
    pub fn acceleration(&self, s: &Solution) -> f64 {
        match self {
            Self::Rocker { link, .. } => s.links[*link].alpha_rad_s2,
            Self::Slide { slider, .. } => s.slides[*slider].acceleration_m_s2,
        }
    }

    /// Whether the value is an angle (rad) rather than a displacement (m).
    pub fn is_angle(&self) -> bool {
        matches!(self, Self::Rocker { .. })
    }

    /// The rate as a pure number: per radian of input at unit input speed, and for a
    /// slider per metre of `size_m` too, so that thresholds on it hold at any scale.
    fn relative_rate(&self, s: &Solution, size_m: f64) -> f64 {
        match self {
            Self::Rocker { .. } => self.rate(s),
            Self::Slide { .. } => self.rate(s) / size_m,
        }
    }
}

/// The outputs of a mechanism: rockers (links pinned to ground), then sliders.
pub fn outputs(k: &Kinematics) -> Vec<Output> {
    let m = k.mechanism();
    let mut out: Vec<Output> = m
        .moving_links()
        .filter(|&l| l != m.driver.link)
        .filter(|&l| m.ground_pivot_of(l).is_some())
        .map(|l| Output::Rocker {
            link: l,
            name: m.links[l].name.clone(),
        })
        .collect();
    out.extend(m.sliders.iter().enumerate().map(|(i, s)| Output::Slide {
        slider: i,
        name: m.links[s.slider].name.clone(),
    }));
    out
}

/// Which extreme of an output a limit position is (`"max"` or `"min"` in JSON).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Extreme {
    /// The output's largest value.
    Max,
    /// The output's smallest value.
    Min,
}

impl std::fmt::Display for Extreme {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Extreme::Max => "max",
            Extreme::Min => "min",
        })
    }
}

/// An extreme of one output.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LimitPosition {
    /// Input angle, rad.
    pub input_rad: f64,
    /// Output name.
    pub output: String,
    /// Whether the output is largest or smallest there.
    pub kind: Extreme,
    /// Output value there (rad or m).
    pub value: f64,
}

/// Acute transmission angle summary, rad.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TransmissionAngle {
    /// Smallest transmission angle over the cycle (0 = locked, π/2 = ideal).
    pub min: f64,
    /// Largest.
    pub max: f64,
    /// Input angle where the minimum occurs, rad.
    pub at: f64,
    /// Input angle where the maximum occurs, rad.
    pub at_max: f64,
    /// The group where the minimum occurs.
    pub group: String,
}

/// The Grashof class of a four-bar loop, by which link is shortest (JSON: the words
/// [`std::fmt::Display`] shows).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum GrashofClass {
    /// Grashof, the input shortest: it turns fully, the output rocks.
    #[serde(rename = "crank-rocker")]
    CrankRocker,
    /// Grashof, the ground shortest: both side links turn fully.
    #[serde(rename = "double-crank (drag link)")]
    DoubleCrank,
    /// Grashof, the coupler shortest: both side links rock.
    #[serde(rename = "double-rocker (Grashof, coupler shortest)")]
    DoubleRocker,
    /// Grashof, the output shortest: the output turns fully, the input rocks.
    #[serde(rename = "rocker-crank")]
    RockerCrank,
    /// s + l = p + q: the chain can fold flat and change its assembly mode.
    #[serde(rename = "change-point")]
    ChangePoint,
    /// Not Grashof: no link turns fully.
    #[serde(rename = "triple-rocker (non-Grashof)")]
    TripleRocker,
}

impl GrashofClass {
    /// The class of a four-bar of lengths ground, input, coupler, output (any unit).
    pub fn of_lengths(lengths: [f64; 4]) -> Self {
        Self::with_sums(lengths).0
    }

    /// The class, s + l and p + q.
    fn with_sums(lengths: [f64; 4]) -> (Self, f64, f64) {
        let mut sorted = lengths;
        sorted.sort_by(f64::total_cmp);
        let (sl, pq) = (sorted[0] + sorted[3], sorted[1] + sorted[2]);
        let shortest = (0..4)
            .min_by(|&x, &y| lengths[x].total_cmp(&lengths[y]))
            .unwrap_or(0);
        let class = if (sl - pq).abs() <= 1e-9 * sl {
            Self::ChangePoint
        } else if sl > pq {
            Self::TripleRocker
        } else {
            match shortest {
                0 => Self::DoubleCrank,
                1 => Self::CrankRocker,
                2 => Self::DoubleRocker,
                _ => Self::RockerCrank,
            }
        };
        (class, sl, pq)
    }
}

impl std::fmt::Display for GrashofClass {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::CrankRocker => "crank-rocker",
            Self::DoubleCrank => "double-crank (drag link)",
            Self::DoubleRocker => "double-rocker (Grashof, coupler shortest)",
            Self::RockerCrank => "rocker-crank",
            Self::ChangePoint => "change-point",
            Self::TripleRocker => "triple-rocker (non-Grashof)",
        })
    }
}

/// Grashof classification of a four-bar loop.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Grashof {
    /// The class.
    pub class: GrashofClass,
    /// s + l ≤ p + q.
    pub grashof: bool,
    /// s + l = p + q (within 1e-9 relative).
    pub change_point: bool,
    /// Shortest plus longest, m.
    pub s_plus_l_m: f64,
    /// The other two, m.
    pub p_plus_q_m: f64,
    /// Lengths: ground, input, coupler, output, m.
    pub lengths_m: [f64; 4],
    /// Link names in the same order.
    pub links: [String; 4],
    /// False: the mechanism is this four-bar; true: the four-bar is its driving loop.
    pub embedded: bool,
}

/// A position where an output/input velocity ratio is zero or infinite.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Toggle {
    /// Input angle, rad.
    pub input_rad: f64,
    /// "zero" (a limit of `output`) or "infinite" (a dead point of the input).
    pub ratio: &'static str,
    /// The output, or the group that locks.
    pub output: String,
    /// Revolute joints whose two links are collinear there (within 0.1 deg).
    pub collinear_joints: Vec<String>,
}

/// A near-singular position met during a sweep.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Tangency {
    /// Input angle, rad.
    pub input_rad: f64,
    /// Conditioning there.
    pub conditioning: f64,
}

/// Everything `linkage report` prints.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Report {
    /// Mechanism name.
    pub name: String,
    /// Solver path used.
    pub solver_path: PathKind,
    /// Assembly ranges, rad.
    pub assembly_range_rad: Vec<[f64; 2]>,
    /// Whether the input turns fully.
    pub full_rotation: bool,
    /// Limit positions of every output.
    pub limit_positions: Vec<LimitPosition>,
    /// Stroke of every slider, m.
    pub strokes_m: indexmap::IndexMap<String, f64>,
    /// Swing of every rocker, rad.
    pub swings_rad: indexmap::IndexMap<String, f64>,
    /// Time ratio K ≥ 1 of the main output (null when undefined).
    pub time_ratio: Option<f64>,
    /// Which output K refers to and which stroke is slower, or why there is no K.
    pub time_ratio_note: Option<TimeRatioNote>,
    /// Grashof class (null when the chain has no driving four-bar loop).
    pub grashof: Option<Grashof>,
    /// Transmission angle summary (null when no group has one).
    pub transmission_angle_rad: Option<TransmissionAngle>,
    /// Toggle positions.
    pub toggles: Vec<Toggle>,
    /// Branch points: inputs inside the range where a group's two assembly modes meet
    /// (a change-point chain), so that the motion may continue in either.
    pub branch_points: Vec<crate::branch_points::BranchPoint>,
    /// Input speed the scene uses, rad/s.
    pub input_speed_rad_s: f64,
    /// Notes from the scene.
    pub notes: Vec<String>,
}

/// Evaluates solutions at unit input speed (rates are velocity ratios).
struct Probe<'a> {
    k: &'a mut Kinematics,
    sol: Solution,
}

impl Probe<'_> {
    fn at(&mut self, x: f64) -> Option<&Solution> {
        self.k
            .solve_into(x, 1.0, &mut self.sol)
            .ok()
            .map(|_| &self.sol)
    }
}

/// Limit positions of `out` over the assembly ranges, by root-finding on its rate.
pub fn limit_positions(
    k: &mut Kinematics,
    out: &Output,
    ranges: &AssemblyRanges,
) -> Vec<LimitPosition> {
    found_limits(k, out, ranges)
        .into_iter()
        .map(|f| f.limit)
        .collect()
}

/// A limit position and whether its rate vanishes to a higher order there (see
/// [`flat`]).
struct FoundLimit {
    limit: LimitPosition,
    flat: bool,
}

fn found_limits(k: &mut Kinematics, out: &Output, ranges: &AssemblyRanges) -> Vec<FoundLimit> {
    let start = k.mechanism().driver.start_rad;
    let size = k.mechanism().size_m;
    let mut probe = Probe {
        sol: k.empty_solution(),
        k,
    };
    let ratio =
        |probe: &mut Probe, x: f64| probe.at(x).map_or(f64::NAN, |s| out.relative_rate(s, size));
    let mut found = Vec::new();
    for xs in ranges.grids(start) {
        let rates: Vec<f64> = xs.iter().map(|&x| ratio(&mut probe, x)).collect();
        for i in sign_changes(&rates) {
            // An output at rest (a change-point chain's folded mode holds its rocker
            // still) changes the sign of round-off only: no limit there.
            if rates[i].abs().max(rates[i + 1].abs()) < RESTING_RATE {
                continue;
            }
            let Some(root) = refine(xs[i], xs[i + 1], |x| ratio(&mut probe, x)) else {
                continue;
            };
            let flat = flat(&mut |x| ratio(&mut probe, x), root);
            let Some(s) = probe.at(root) else { continue };
            found.push(FoundLimit {
                limit: LimitPosition {
                    input_rad: root.rem_euclid(TAU),
                    output: out.name().to_string(),
                    kind: if rates[i] > 0.0 {
                        Extreme::Max
                    } else {
                        Extreme::Min
                    },
                    value: out.value(s),
                },
                flat,
            });
        }
    }
    found
}

/// Whether `rate` vanishes at `root` to a higher (third or odd higher) order: then
/// round-off hides the root within about (1e-16)^(1/3) ≈ 5e-6 rad of where it is, and
/// a root found there is only that good. A simple root's rate grows tenfold from 1e-3
/// to 1e-2 rad away, a triple root's a thousandfold.
fn flat(rate: &mut dyn FnMut(f64) -> f64, root: f64) -> bool {
    let growth = |h: f64, rate: &mut dyn FnMut(f64) -> f64| {
        (rate(root + 10.0 * h) * rate(root - 10.0 * h) / (rate(root + h) * rate(root - h)))
            .abs()
            .sqrt()
    };
    let g = growth(1e-3, rate);
    // Between 10 (order 1) and 1000 (order 3).
    g.is_finite() && g > 100.0
}

/// How far from a flat root (see [`flat`]) a simple root of another output may lie
/// and still be taken for the same, rad: several times the round-off band of a triple
/// root, far below the grid step that separates distinct roots.
const SAME_ROOT: f64 = 1e-4;

/// Moves each flat limit onto a simple limit of another output found within
/// [`SAME_ROOT`], where there is one, and takes the output's value there. A flat
/// limit is where an output's rate is the product of two rates that vanish together
/// (the die cutter's die at its toggle: the die's rate through the rocker's, the
/// rocker at its own limit): the simple root of the other output is the same place,
/// known to round-off instead of to 5e-6 rad.
fn align_flat_limits(k: &mut Kinematics, outs: &[Output], found: &mut [Vec<FoundLimit>]) {
    let simple: Vec<(usize, f64)> = found
        .iter()
        .enumerate()
        .flat_map(|(o, limits)| {
            limits
                .iter()
                .filter(|f| !f.flat)
                .map(move |f| (o, f.limit.input_rad))
        })
        .collect();
    let mut sol = k.empty_solution();
    for (o, limits) in found.iter_mut().enumerate() {
        for f in limits.iter_mut().filter(|f| f.flat) {
            let near = simple
                .iter()
                .filter(|&&(other, _)| other != o)
                .map(|&(_, x)| (x, angle_between(x, f.limit.input_rad)))
                .filter(|&(_, d)| d <= SAME_ROOT)
                .min_by(|a, b| a.1.total_cmp(&b.1));
            if let Some((x, _)) = near
                && k.solve_into(x, 1.0, &mut sol).is_ok()
            {
                f.limit.input_rad = x;
                f.limit.value = outs[o].value(&sol);
            }
        }
    }
}

/// The angle between two angles, rad, in [0, π].
fn angle_between(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d)
}

/// Range swept by an output: the span between its extremes, including the ends of
/// limited input ranges; a rocker that turns fully sweeps 2π.
fn span(
    k: &mut Kinematics,
    out: &Output,
    limits: &[LimitPosition],
    ranges: &AssemblyRanges,
) -> f64 {
    let mut values: Vec<f64> = limits.iter().map(|l| l.value).collect();
    if !ranges.full_rotation {
        for [a, b] in &ranges.intervals {
            values.extend(dead_point_value(k, out, *a, 1.0, b - a));
            values.extend(dead_point_value(k, out, *b, -1.0, b - a));
        }
    }
    if values.is_empty() {
        return if out.is_angle() { TAU } else { 0.0 };
    }
    if out.is_angle() {
        // Angles: the smallest arc that holds every extreme.
        let base = values[0];
        let rel: Vec<f64> = values
            .iter()
            .map(|v| (v - base + std::f64::consts::PI).rem_euclid(TAU))
            .collect();
        let hi = rel.iter().cloned().fold(f64::MIN, f64::max);
        let lo = rel.iter().cloned().fold(f64::MAX, f64::min);
        hi - lo
    } else {
        let hi = values.iter().cloned().fold(f64::MIN, f64::max);
        let lo = values.iter().cloned().fold(f64::MAX, f64::min);
        hi - lo
    }
}

/// The value of `out` at the dead point `end` of an input range of length `width`
/// (`inward` is +1 at the start of the range, -1 at its end).
///
/// Exactly at the dead point the solve is singular, and a hair inside it the output
/// is still off by c·√hair (the branch turns back there: v − v* ∝ √|x − x*|), which
/// is 1e-5 for a hair of 1e-9. So the dead point is found from two probes as the root
/// of 1/rate², which is linear in x there, and the value is extrapolated to it along
/// the square root. Where the rate does not follow that law (an output whose rate
/// stays finite at the dead point), the nearer probe's value is taken.
fn dead_point_value(
    k: &mut Kinematics,
    out: &Output,
    end: f64,
    inward: f64,
    width: f64,
) -> Option<f64> {
    let (d1, d2) = (1e-9 * width, 4e-9 * width);
    let mut sol = k.empty_solution();
    k.solve_into(end + inward * d1, 1.0, &mut sol).ok()?;
    let (v1, r1) = (out.value(&sol), out.rate(&sol));
    let Ok(()) = k.solve_into(end + inward * d2, 1.0, &mut sol) else {
        return Some(v1);
    };
    let (g1, g2) = (r1.powi(-2), out.rate(&sol).powi(-2));
    // Distance from the nearer probe back to the root of the line through (d, 1/rate²).
    let dist = g1 * (d2 - d1) / (g2 - g1);
    if !(dist.is_finite() && dist > 0.0 && dist < 2.0 * d1) {
        return Some(v1);
    }
    Some(v1 - 2.0 * dist * r1 * inward)
}

/// Which stroke of an output: from its minimum to its maximum, or back.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stroke {
    /// Minimum to maximum.
    Rising,
    /// Maximum to minimum.
    Falling,
}

/// Which output the time ratio K refers to and which stroke is slower, or why the
/// report has no K; worded by `Display` (and so serialized).
#[derive(Clone, Debug, PartialEq)]
pub enum TimeRatioNote {
    /// The two strokes of `output`: crank angles spent rising and falling, rad.
    Strokes {
        /// The output's name.
        output: String,
        /// The slower stroke.
        slower: Stroke,
        /// Crank angle from the minimum to the maximum, rad.
        rising_rad: f64,
        /// Crank angle from the maximum back to the minimum, rad.
        falling_rad: f64,
    },
    /// The main output has not exactly two limit positions.
    NotTwoLimits,
    /// The input does not turn fully.
    InputDoesNotTurn,
}

impl std::fmt::Display for TimeRatioNote {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Strokes {
                output,
                slower,
                rising_rad,
                falling_rad,
            } => write!(
                f,
                "{output}: {} stroke is slower; crank turns {:.3} deg rising, {:.3} deg falling; \
                 angle between limit positions theta = {:.3} deg",
                match slower {
                    Stroke::Rising => "rising (min to max)",
                    Stroke::Falling => "falling (max to min)",
                },
                rising_rad.to_degrees(),
                falling_rad.to_degrees(),
                (rising_rad - std::f64::consts::PI).abs().to_degrees()
            ),
            Self::NotTwoLimits => {
                f.write_str("the main output does not have exactly two limit positions")
            }
            Self::InputDoesNotTurn => {
                f.write_str("the input does not turn fully, so no time ratio")
            }
        }
    }
}

impl Serialize for TimeRatioNote {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// Time ratio K of an output with exactly two limits on a fully turning input (slower
/// stroke angle / faster stroke angle), with its strokes.
pub fn time_ratio(limits: &[LimitPosition], speed_rad_s: f64) -> Option<(f64, TimeRatioNote)> {
    let [a, b] = limits else { return None };
    let (max, min) = if a.kind == Extreme::Max {
        (a, b)
    } else {
        (b, a)
    };
    if max.kind == min.kind {
        return None;
    }
    let rising = if speed_rad_s >= 0.0 {
        (max.input_rad - min.input_rad).rem_euclid(TAU)
    } else {
        (min.input_rad - max.input_rad).rem_euclid(TAU)
    };
    let falling = TAU - rising;
    let k = rising.max(falling) / rising.min(falling);
    let slower = if rising > falling {
        Stroke::Rising
    } else {
        Stroke::Falling
    };
    Some((
        k,
        TimeRatioNote::Strokes {
            output: max.output.clone(),
            slower,
            rising_rad: rising,
            falling_rad: falling,
        },
    ))
}

/// Grashof class of the four-bar formed by ground, the crank and the first RRR dyad
/// when that dyad closes on ground.
pub fn grashof(k: &Kinematics) -> Option<Grashof> {
    let m = k.mechanism();
    let cf = k.closed_form()?;
    let Some(Group::Rrr(g)) = cf.groups.first() else {
        return None;
    };
    let crank = m.driver.link;
    let (a_on_crank, ground_pin) = if g.a.link == crank && g.c.link == m.ground {
        (g.a.local, g.c.local)
    } else {
        return None;
    };
    let pivot = &m.revolutes[m.driver.pivot];
    let (crank_pivot_local, ground_pivot) = if pivot.a == m.ground {
        (pivot.b_local, pivot.a_local)
    } else {
        (pivot.a_local, pivot.b_local)
    };
    let lengths = [
        (ground_pin - ground_pivot).norm(),
        (a_on_crank - crank_pivot_local).norm(),
        g.len_i,
        g.len_j,
    ];
    let names = [m.ground, crank, g.i, g.j].map(|l| m.links[l].name.clone());
    let (class, sl, pq) = GrashofClass::with_sums(lengths);
    let change_point = class == GrashofClass::ChangePoint;
    Some(Grashof {
        class,
        grashof: sl <= pq || change_point,
        change_point,
        s_plus_l_m: sl,
        p_plus_q_m: pq,
        lengths_m: lengths,
        links: names,
        embedded: m.links.len() != 4 || !m.sliders.is_empty(),
    })
}

/// The two lines whose acute angle is a group's transmission angle, with their
/// angular velocities: RRR: the two links at the inner joint; RRP: the coupler and
/// the normal of the guide (90° minus the pressure angle).
fn transmission_lines(k: &Kinematics, g: usize, s: &Solution) -> Option<(Vec2, f64, Vec2, f64)> {
    let cf = k.closed_form()?;
    match &cf.groups[g] {
        Group::Rrr(d) => {
            let mid = s.links[d.i].world(&d.mid_on_i);
            let a = s.links[d.a.link].world(&d.a.local);
            let c = s.links[d.c.link].world(&d.c.local);
            Some((
                mid - a,
                s.links[d.i].omega_rad_s,
                mid - c,
                s.links[d.j].omega_rad_s,
            ))
        }
        Group::Rrp(d) => {
            let mid = s.links[d.j].world(&d.mid_on_j);
            let a = s.links[d.a.link].world(&d.a.local);
            let guide = &s.links[d.slide.guide];
            let u = guide.rotation * d.slide.direction_local;
            Some((
                mid - a,
                s.links[d.i].omega_rad_s,
                perp(&u),
                guide.omega_rad_s,
            ))
        }
        _ => None,
    }
}

fn acute(l1: &Vec2, l2: &Vec2) -> f64 {
    cross(l1, l2).abs().atan2(l1.dot(l2).abs())
}

/// Transmission angle at one solved position, rad in [0, π/2]: the smallest over the
/// chain's dyads (the one that transmits worst), `None` for a chain without dyads.
pub fn transmission_angle_at(k: &Kinematics, s: &Solution) -> Option<f64> {
    (0..k.group_count())
        .filter_map(|g| transmission_lines(k, g, s))
        .map(|(l1, _, l2, _)| acute(&l1, &l2))
        .min_by(f64::total_cmp)
}

/// Transmission angle extremes over the assembly ranges (root-finding on the
/// angle's rate, plus the crossings of 90° and the ends of limited ranges).
pub fn transmission_angle(
    k: &mut Kinematics,
    ranges: &AssemblyRanges,
) -> Option<TransmissionAngle> {
    let groups = k.group_count();
    let start = k.mechanism().driver.start_rad;
    let names: Vec<String> = (0..groups).map(|g| k.group_name(g)).collect();
    // (input, angle, group) over all groups: the extremes are taken over all of them.
    let mut all: Vec<(f64, f64, usize)> = Vec::new();
    let mut sol = k.empty_solution();
    for g in 0..names.len() {
        let mut candidates: Vec<(f64, f64)> = Vec::new();
        let eval = |k: &mut Kinematics, x: f64, sol: &mut Solution| -> Option<(f64, f64, f64)> {
            k.solve_into(x, 1.0, sol).ok()?;
            let (l1, w1, l2, w2) = transmission_lines(k, g, sol)?;
            Some((acute(&l1, &l2), w1 - w2, l1.dot(&l2)))
        };
        for xs in ranges.grids(start) {
            let vals: Vec<Option<(f64, f64, f64)>> =
                xs.iter().map(|&x| eval(k, x, &mut sol)).collect();
            if vals.iter().all(Option::is_none) {
                continue;
            }
            for (x, v) in xs.iter().zip(&vals) {
                if let (Some((mu, _, _)), true) = (v, !ranges.full_rotation) {
                    candidates.push((*x, *mu));
                }
            }
            let rate: Vec<f64> = vals.iter().map(|v| v.map_or(f64::NAN, |t| t.1)).collect();
            let dot: Vec<f64> = vals.iter().map(|v| v.map_or(f64::NAN, |t| t.2)).collect();
            for (series, which) in [(rate, 1), (dot, 2)] {
                for i in sign_changes(&series) {
                    let root = refine(xs[i], xs[i + 1], |x| {
                        eval(k, x, &mut sol)
                            .map_or(f64::NAN, |t| if which == 1 { t.1 } else { t.2 })
                    });
                    if let Some(r) = root
                        && let Some((mu, _, _)) = eval(k, r, &mut sol)
                    {
                        candidates.push((r.rem_euclid(TAU), mu));
                    }
                }
            }
            if candidates.is_empty() {
                // Constant angle (e.g. a rocker whose coupler keeps its angle).
                if let Some((mu, _, _)) = vals.iter().flatten().next() {
                    candidates.push((xs[0], *mu));
                }
            }
        }
        all.extend(candidates.into_iter().map(|(x, mu)| (x, mu, g)));
    }
    let &(at, min, group) = all.iter().min_by(|a, b| a.1.total_cmp(&b.1))?;
    let &(at_max, max, _) = all.iter().max_by(|a, b| a.1.total_cmp(&b.1))?;
    Some(TransmissionAngle {
        min,
        max,
        at,
        at_max,
        group: names[group].clone(),
    })
}

/// Points where two moving links meet and lie on one line (within `tol_rad`): each
/// link's direction is taken from the point to its next joint point.
pub fn collinear_joints(k: &Kinematics, s: &Solution, tol_rad: f64) -> Vec<String> {
    let m = k.mechanism();
    let other_joint = |link: usize, not: usize| -> Option<Vec2> {
        m.links[link]
            .points
            .iter()
            .find(|(p, _)| *p != not && m.revolutes.iter().any(|r| r.point == *p))
            .map(|(_, local)| s.links[link].world(local))
    };
    let mut found = Vec::new();
    for (pi, point) in m.points.iter().enumerate() {
        let users: Vec<usize> = m
            .moving_links()
            .filter(|&l| m.links[l].local(pi).is_some())
            .collect();
        for (n, &a) in users.iter().enumerate() {
            for &b in &users[n + 1..] {
                let j = s.points[pi].position;
                let (Some(pa), Some(pb)) = (other_joint(a, pi), other_joint(b, pi)) else {
                    continue;
                };
                let angle = acute(&(pa - j), &(pb - j));
                if angle <= tol_rad {
                    found.push(format!(
                        "{} ({}-{}, {:.4} deg)",
                        point.name,
                        m.links[a].name,
                        m.links[b].name,
                        angle.to_degrees()
                    ));
                }
            }
        }
    }
    found
}

/// The full report of `linkage report`.
pub fn report(k: &mut Kinematics) -> Result<Report> {
    let ranges = assembly_ranges_of(k);
    if ranges.intervals.is_empty() {
        return Err(LinkageError::CannotAssemble {
            input_deg: k.mechanism().driver.start_rad.to_degrees(),
            reason: AssemblyFailure::Nowhere,
            reachable: ranges.clone(),
        });
    }
    // Extremes, strokes and toggles belong to the interval the mechanism starts in: a
    // disjoint interval is another assembly of the same links that it cannot reach.
    let working = AssemblyRanges {
        full_rotation: ranges.full_rotation,
        intervals: ranges
            .containing(k.mechanism().driver.start_rad)
            .into_iter()
            .collect(),
    };
    let outs = outputs(k);
    let mut found: Vec<Vec<FoundLimit>> = outs
        .iter()
        .map(|out| found_limits(k, out, &working))
        .collect();
    align_flat_limits(k, &outs, &mut found);
    let mut all_limits = Vec::new();
    let mut strokes_m = indexmap::IndexMap::new();
    let mut swings_rad = indexmap::IndexMap::new();
    let mut per_output = Vec::new();
    for (out, limits) in outs.iter().zip(found) {
        let limits: Vec<LimitPosition> = limits.into_iter().map(|f| f.limit).collect();
        let sp = span(k, out, &limits, &working);
        match out {
            Output::Rocker { .. } => swings_rad.insert(out.name().to_string(), sp),
            Output::Slide { .. } => strokes_m.insert(out.name().to_string(), sp),
        };
        all_limits.extend(limits.iter().cloned());
        per_output.push((out.clone(), limits));
    }
    let (time_ratio, time_ratio_note) = main_time_ratio(k, &per_output, ranges.full_rotation);
    let toggles = toggles(k, &all_limits, &working);
    let transmission_angle_rad = transmission_angle(k, &working);
    let branch_points = crate::branch_points::branch_points(k, &working);
    let m = k.mechanism();
    Ok(Report {
        name: m.name.clone(),
        solver_path: k.path(),
        assembly_range_rad: ranges.intervals.clone(),
        full_rotation: ranges.full_rotation,
        limit_positions: all_limits,
        strokes_m,
        swings_rad,
        time_ratio,
        time_ratio_note,
        grashof: grashof(k),
        transmission_angle_rad,
        toggles,
        branch_points,
        input_speed_rad_s: m.driver.speed_rad_s,
        notes: m.notes.clone(),
    })
}

/// K of the scene's main output (else the first), or why there is none.
fn main_time_ratio(
    k: &Kinematics,
    per_output: &[(Output, Vec<LimitPosition>)],
    full_rotation: bool,
) -> (Option<f64>, Option<TimeRatioNote>) {
    let m = k.mechanism();
    let main_link = m.output;
    let main = per_output
        .iter()
        .find(|entry| match &entry.0 {
            Output::Rocker { link, .. } => *link == main_link,
            Output::Slide { slider, .. } => m.sliders[*slider].slider == main_link,
        })
        .or(per_output.first());
    match main {
        Some((_, limits)) if full_rotation => match time_ratio(limits, m.driver.speed_rad_s) {
            Some((kk, note)) => (Some(kk), Some(note)),
            None => (None, Some(TimeRatioNote::NotTwoLimits)),
        },
        _ => (None, Some(TimeRatioNote::InputDoesNotTurn)),
    }
}

/// The toggles: every limit position of an output (its rate zero), and the ends of
/// a range that does not turn fully (the input's rate infinite there).
fn toggles(k: &mut Kinematics, limits: &[LimitPosition], working: &AssemblyRanges) -> Vec<Toggle> {
    let mut toggles = Vec::new();
    let mut sol = k.empty_solution();
    for lp in limits {
        if k.solve_into(lp.input_rad, 1.0, &mut sol).is_ok() {
            toggles.push(Toggle {
                input_rad: lp.input_rad,
                ratio: "zero",
                output: lp.output.clone(),
                collinear_joints: collinear_joints(k, &sol, 0.1_f64.to_radians()),
            });
        }
    }
    if working.full_rotation {
        return toggles;
    }
    for [a, b] in &working.intervals {
        // A hair inside the range: exactly at the dead point velocities are undefined.
        let hair = 1e-9 * (b - a);
        for x in [*a + hair, *b - hair] {
            let group = k
                .group_conditioning(x)
                .into_iter()
                .min_by(|p, q| p.1.total_cmp(&q.1))
                .map_or_else(|| "chain".to_string(), |(n, _)| n);
            let collinear = if k.solve_into(x, 1.0, &mut sol).is_ok() {
                collinear_joints(k, &sol, 0.1_f64.to_radians())
            } else {
                Vec::new()
            };
            toggles.push(Toggle {
                input_rad: x.rem_euclid(TAU),
                ratio: "infinite",
                output: group,
                collinear_joints: collinear,
            });
        }
    }
    toggles
}
