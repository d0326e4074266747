//! One input cycle (or the assemblable range) solved at evenly spaced inputs, and the
//! CSV contract of `linkage sweep`: `input_rad`, then `P_x,P_y,P_vx,P_vy,P_ax,P_ay`
//! per named point, then `L_theta,L_omega,L_alpha` per moving link, SI units.

pub use crate::angles::unwrap_near;
use crate::error::{LinkageError, Result};
use crate::error::{Param, Valid};
use crate::model::Mechanism;
use crate::motion::Solution;
pub use crate::ranges::sweep_range;
use crate::real::LANES;
use crate::solve::Kinematics;

/// Conditioning below which a sweep position is reported as near a tangency.
pub const NEAR_SINGULAR: f64 = 1e-3;

/// A solved sweep.
#[derive(Clone, Debug)]
pub struct Sweep {
    /// Solutions in input order.
    pub solutions: Vec<Solution>,
    /// Link angles unwrapped along the sweep, rad: `angles[row][link]`.
    pub angles: Vec<Vec<f64>>,
    /// Inputs (rad) where the conditioning fell below [`NEAR_SINGULAR`].
    pub near_singular: Vec<f64>,
    /// The range swept, rad.
    pub range: [f64; 2],
}

/// Most positions [`sweep`] holds in memory (about 1 kB each for a six-bar).
pub const MAX_SWEEP_STEPS: usize = 1_000_000;

/// What [`sweep_each`] found besides the positions it handed out.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepInfo {
    /// Inputs (rad) where the conditioning fell below [`NEAR_SINGULAR`].
    pub near_singular: Vec<f64>,
    /// The range swept, rad.
    pub range: [f64; 2],
}

/// Solves `steps` positions over [`sweep_range`] at the scene's input speed (a full
/// turn excludes its end, which repeats the start).
///
/// # Errors
/// Fewer than 2 or more than [`MAX_SWEEP_STEPS`] steps, or the solver's error.
pub fn sweep(k: &mut Kinematics, steps: usize) -> Result<Sweep> {
    if steps > MAX_SWEEP_STEPS {
        return Err(LinkageError::invalid(
            Param::SweepSteps,
            steps as f64,
            Valid::AtMostSteps(MAX_SWEEP_STEPS),
        ));
    }
    let mut solutions = Vec::with_capacity(steps);
    let mut angles: Vec<Vec<f64>> = Vec::with_capacity(steps);
    let info = sweep_each(k, steps, |_, s, a| -> Result<()> {
        solutions.push(s.clone());
        angles.push(a.to_vec());
        Ok(())
    })?;
    Ok(Sweep {
        solutions,
        angles,
        near_singular: info.near_singular,
        range: info.range,
    })
}

/// Like [`sweep`], but hands each position to `visit` (with the link angles
/// unwrapped along the sweep) instead of keeping it: memory stays flat for any count.
///
/// # Errors
/// Fewer than 2 steps, the solver's error, an input speed so high that a velocity or
/// acceleration overflows ([`LinkageError::SpeedOverflow`]), or the first error of
/// `visit`.
pub fn sweep_each<E: From<LinkageError>>(
    k: &mut Kinematics,
    steps: usize,
    visit: impl FnMut(&Mechanism, &Solution, &[f64]) -> std::result::Result<(), E>,
) -> std::result::Result<SweepInfo, E> {
    if steps < 2 {
        return Err(LinkageError::invalid(
            Param::SweepSteps,
            steps as f64,
            Valid::MustBeAtLeast(2),
        )
        .into());
    }
    let (range, full) = sweep_range(k)?;
    sweep_each_on(k, Grid::even(range, full, steps), visit)
}

/// Where a sweep solves: its inputs, in order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Grid {
    /// `steps` inputs evenly spread over `range` (rad): a full turn (`full`)
    /// excludes its end, which repeats the start; a rocking input's range includes
    /// both ends.
    Even {
        /// The range, rad.
        range: [f64; 2],
        /// Whether the range is a full turn.
        full: bool,
        /// How many inputs.
        steps: usize,
    },
    /// `count` whole multiples of `step` (rad) from `first` (rad), inside `range`.
    Multiples {
        /// The range the multiples lie in, rad.
        range: [f64; 2],
        /// The first input, rad.
        first: f64,
        /// The step, rad.
        step: f64,
        /// How many inputs.
        count: usize,
    },
}

impl Grid {
    /// `steps` inputs over `range`: a full turn (`full`) excludes its end, which
    /// repeats the start; a rocking input's range includes both ends.
    pub fn even(range: [f64; 2], full: bool, steps: usize) -> Self {
        Self::Even { range, full, steps }
    }

    /// The whole multiples of `step` (rad, positive) in `range`, as a table of the
    /// cycle lists them (0°, 1°, 2°, ... for a step of 1°). A full turn (`full`)
    /// runs from 0 to just under a turn, each angle once, whatever its start.
    pub fn multiples(range: [f64; 2], full: bool, step: f64) -> Self {
        let (range, first, last) = if full {
            let turn = std::f64::consts::TAU;
            ([0.0, turn], 0.0, turn - 1e-9 * step)
        } else {
            // A rocking input's range ends a hair inside its dead points: the
            // multiples stay inside it.
            let [a, b] = range;
            (range, (a / step).ceil() * step, b)
        };
        let count = if last < first {
            0
        } else {
            ((last - first) / step).floor() as usize + 1
        };
        Self::Multiples {
            range,
            first,
            step,
            count: count.min(MAX_SWEEP_STEPS),
        }
    }

    /// How many inputs.
    pub fn count(&self) -> usize {
        match *self {
            Self::Even { steps, .. } => steps,
            Self::Multiples { count, .. } => count,
        }
    }

    /// The range the inputs lie in, rad.
    pub fn range(&self) -> [f64; 2] {
        match *self {
            Self::Even { range, .. } | Self::Multiples { range, .. } => range,
        }
    }

    /// The `i`-th input, rad.
    pub fn input(&self, i: usize) -> f64 {
        match *self {
            Self::Even {
                range: [a, b],
                full,
                steps,
            } => {
                let divisions = if full { steps } else { steps - 1 }.max(1);
                a + (b - a) * i as f64 / divisions as f64
            }
            Self::Multiples { first, step, .. } => first + step * i as f64,
        }
    }
}

/// Like [`sweep_each`], on the inputs of `grid`.
///
/// # Errors
/// The solver's error, an input speed so high that a velocity or acceleration
/// overflows ([`LinkageError::SpeedOverflow`]), or the first error of `visit`.
pub fn sweep_each_on<E: From<LinkageError>>(
    k: &mut Kinematics,
    grid: Grid,
    mut visit: impl FnMut(&Mechanism, &Solution, &[f64]) -> std::result::Result<(), E>,
) -> std::result::Result<SweepInfo, E> {
    let speed = k.mechanism().driver.speed_rad_s;
    let [a, b] = grid.range();
    let count = grid.count();
    let mut near_singular = Vec::new();
    let mut lanes = k.empty_lane_solution();
    let mut s = k.empty_solution();
    let mut angles: Vec<f64> = Vec::new();
    // LANES inputs per call: the closed form solves them together in SIMD lanes.
    // The last call repeats its final input to fill the lanes.
    for first in (0..count).step_by(LANES) {
        let inputs = std::array::from_fn(|l| grid.input((first + l).min(count - 1)));
        solve_stepping_past_branch_points(k, inputs, speed, (b - a) * 1e-6, &mut lanes)?;
        for lane in 0..LANES.min(count - first) {
            lanes.lane_into(lane, &mut s);
            crate::overflow::check(k, &s)?;
            if s.conditioning < NEAR_SINGULAR {
                near_singular.push(s.input_rad);
            }
            if first == 0 && lane == 0 {
                angles.extend(s.links.iter().map(|l| l.angle_rad()));
            } else {
                for (prev, l) in angles.iter_mut().zip(&s.links) {
                    *prev = unwrap_near(l.angle_rad(), *prev);
                }
            }
            visit(k.mechanism(), &s, &angles)?;
        }
    }
    Ok(SweepInfo {
        near_singular,
        range: grid.range(),
    })
}

/// [`Kinematics::solve_lanes`], except that an input landing exactly on a singular
/// position inside the range (a change-point chain's branch point, where the solve
/// has no velocity to give) is solved `hair` past it instead: the sweep goes on, and
/// that row, whose conditioning is about zero, is reported as near singular.
fn solve_stepping_past_branch_points(
    k: &mut Kinematics,
    inputs: [f64; LANES],
    speed: f64,
    hair: f64,
    lanes: &mut crate::solve::LaneSolution,
) -> Result<()> {
    match k.solve_lanes(inputs, speed, lanes) {
        Err(LinkageError::Singular { .. }) => {}
        other => return other,
    }
    let mut one = k.empty_solution();
    for (lane, x) in inputs.into_iter().enumerate() {
        if let Err(LinkageError::Singular { .. }) = k.solve_into(x, speed, &mut one) {
            k.solve_into(x + hair, speed, &mut one)?;
        }
        lanes.set_lane(lane, &one);
    }
    Ok(())
}

/// The CSV header of `sweep` and `at`.
pub fn csv_header(m: &Mechanism) -> Vec<String> {
    let mut h = vec!["input_rad".to_string()];
    for p in &m.points {
        for suffix in ["x", "y", "vx", "vy", "ax", "ay"] {
            h.push(format!("{}_{suffix}", p.name));
        }
    }
    for l in m.moving_links() {
        for suffix in ["theta", "omega", "alpha"] {
            h.push(format!("{}_{suffix}", m.links[l].name));
        }
    }
    h
}

/// One CSV row matching [`csv_header`]; `angles` are the (unwrapped) link angles.
pub fn csv_row(m: &Mechanism, s: &Solution, angles: &[f64]) -> Vec<f64> {
    let mut row = vec![s.input_rad];
    for p in &s.points {
        row.extend([
            p.position.x,
            p.position.y,
            p.velocity.x,
            p.velocity.y,
            p.acceleration.x,
            p.acceleration.y,
        ]);
    }
    for l in m.moving_links() {
        row.extend([angles[l], s.links[l].omega_rad_s, s.links[l].alpha_rad_s2]);
    }
    row
}

#[cfg(test)]
mod tests {
    use super::Grid;

    fn degrees(g: &Grid) -> Vec<f64> {
        (0..g.count()).map(|i| g.input(i).to_degrees()).collect()
    }

    #[test]
    fn a_full_turn_on_whole_degrees_runs_from_zero_whatever_its_start() {
        let start = 117.658_f64.to_radians();
        let g = Grid::multiples(
            [start, start + std::f64::consts::TAU],
            true,
            1f64.to_radians(),
        );
        let d = degrees(&g);
        assert_eq!(d.len(), 360);
        assert!(
            d.iter()
                .enumerate()
                .all(|(i, x)| (x - i as f64).abs() < 1e-9)
        );
        // 7° does not divide the turn: 0, 7, ..., 357.
        let g = Grid::multiples([0.0, std::f64::consts::TAU], true, 7f64.to_radians());
        assert_eq!(g.count(), 52);
        assert!((degrees(&g)[51] - 357.0).abs() < 1e-9);
    }

    #[test]
    fn a_rocking_range_keeps_the_multiples_inside_it() {
        let range = [10.5f64.to_radians(), 40.0f64.to_radians() - 1e-9];
        let g = Grid::multiples(range, false, 10f64.to_radians());
        let d = degrees(&g);
        assert_eq!(d.len(), 2, "{d:?}");
        assert!((d[0] - 20.0).abs() < 1e-9 && (d[1] - 30.0).abs() < 1e-9);
        let even = Grid::even(range, false, 3);
        assert!(
            (degrees(&even)[2] - 40.0).abs() < 1e-6,
            "both ends included"
        );
    }
}
