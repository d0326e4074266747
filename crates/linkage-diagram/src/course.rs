//! The course sheet's data: what a machine-theory course asks a student to draw for a
//! mechanism — its plan of positions (N positions over the crank's range, 12 by
//! default, numbered from the start), the displacement, velocity and acceleration
//! diagrams of its output against the crank angle with the positions marked, the
//! velocity and acceleration polygons at chosen positions, and the force polygons at
//! the first chosen one (where the scene has masses or forces).
//! [`crate::svg_course`] draws it.

use linkage::analysis::{Output, outputs};
use linkage::error::{Param, Valid};
use linkage::force_polygon::{ForcePolygons, force_polygons};
use linkage::kinetostatics::Kinetostatics;
use linkage::polygon::{VectorEquation, polygons};
use linkage::sweep::{Grid, sweep, sweep_each_on, sweep_range};
use linkage::{Kinematics, LinkageError, Mechanism, Result, Solution};

/// Positions on the sheet unless asked.
pub const DEFAULT_POSITIONS: usize = 12;

/// Steps of the diagrams over the range.
const DIAGRAM_STEPS: usize = 361;

/// The main output's motion against the crank angle (deg on x).
#[derive(Clone, Debug, PartialEq)]
pub struct OutputSeries {
    /// The output link's name.
    pub name: String,
    /// A rocker (deg, deg/s, deg/s²) or a slider (m, m/s, m/s²).
    pub is_angle: bool,
    /// Displacement.
    pub s: Vec<[f64; 2]>,
    /// Velocity.
    pub v: Vec<[f64; 2]>,
    /// Acceleration.
    pub a: Vec<[f64; 2]>,
}

impl OutputSeries {
    /// The units of s, v and a.
    pub fn units(&self) -> [&'static str; 3] {
        if self.is_angle {
            ["deg", "deg/s", "deg/s²"]
        } else {
            ["m", "m/s", "m/s²"]
        }
    }
}

/// One position drawn with its polygons.
#[derive(Clone, Debug, PartialEq)]
pub struct ChosenPosition {
    /// Its number on the plan (0 the start).
    pub number: usize,
    /// Its velocity and acceleration polygon equations.
    pub equations: Vec<VectorEquation>,
}

/// Everything the course sheet draws.
#[derive(Clone, Debug)]
pub struct CourseSheet {
    /// The mechanism.
    pub mechanism: Mechanism,
    /// The positions, numbered from 0 at the range's start.
    pub positions: Vec<Solution>,
    /// The positions drawn with their polygons.
    pub chosen: Vec<ChosenPosition>,
    /// The main output's diagrams.
    pub output: Option<OutputSeries>,
    /// The force polygons at the first chosen position, where the scene has force
    /// data.
    pub forces: Option<ForcePolygons>,
}

impl CourseSheet {
    /// The sheet of `k`'s mechanism with `count` positions and polygons at the
    /// positions numbered `chosen`.
    ///
    /// # Errors
    /// Fewer than 2 positions, a chosen number past the last position, or a position
    /// that does not solve.
    pub fn compute(k: &mut Kinematics, count: usize, chosen: &[usize]) -> Result<Self> {
        Self::compute_from(k, count, None, chosen)
    }

    /// [`Self::compute`] with position 0 at the crank angle `first_deg` where given:
    /// on a crank that turns, any angle (the positions go round a turn from it); on
    /// one that rocks, an angle of its range (the positions span it from there to
    /// the range's end).
    ///
    /// # Errors
    /// As [`Self::compute`], and a first angle outside a rocking crank's range (the
    /// error names the range).
    pub fn compute_from(
        k: &mut Kinematics,
        count: usize,
        first_deg: Option<f64>,
        chosen: &[usize],
    ) -> Result<Self> {
        if count < 2 {
            return Err(invalid(Param::CoursePositions, count, Valid::AtLeast(2)));
        }
        if let Some(&bad) = chosen.iter().find(|&&c| c >= count) {
            return Err(invalid(
                Param::ChosenPosition,
                bad,
                Valid::Count {
                    lo: 0,
                    hi: count - 1,
                },
            ));
        }
        // The sweep's own positions: evenly over the range, a full turn without its
        // repeated end, branch points stepped past.
        let positions = match first_deg {
            None => sweep(k, count)?.solutions,
            Some(first) => positions_from(k, count, first)?,
        };
        let chosen: Vec<ChosenPosition> = chosen
            .iter()
            .map(|&number| ChosenPosition {
                number,
                equations: polygons(k, &positions[number]),
            })
            .collect();
        let forces = chosen.first().and_then(|c| {
            let input = positions[c.number].input_rad;
            let mut ks = Kinetostatics::new(k).ok()?;
            force_polygons(k, &mut ks, input).ok()
        });
        Ok(Self {
            output: output_series(k)?,
            mechanism: k.mechanism().clone(),
            positions,
            chosen,
            forces,
        })
    }
}

/// `count` positions from the crank angle `first_deg`: round a turn, or to the end
/// of a rocking crank's range.
fn positions_from(k: &mut Kinematics, count: usize, first_deg: f64) -> Result<Vec<Solution>> {
    let ([a, b], full) = sweep_range(k)?;
    let first = first_deg.to_radians();
    let inside = first_deg.is_finite() && (full || (a..=b).contains(&first));
    if !inside {
        let valid = if full {
            Valid::Between(-360.0, 360.0)
        } else {
            Valid::Between(a.to_degrees(), b.to_degrees())
        };
        return Err(LinkageError::invalid(
            Param::FirstPosition,
            first_deg,
            valid,
        ));
    }
    let end = if full {
        first + std::f64::consts::TAU
    } else {
        b
    };
    let mut solutions = Vec::with_capacity(count);
    let grid = Grid::even([first, end], full, count);
    sweep_each_on::<LinkageError>(k, grid, |_, s, _| {
        solutions.push(s.clone());
        Ok(())
    })?;
    Ok(solutions)
}

fn invalid(param: Param, value: usize, valid: Valid) -> LinkageError {
    LinkageError::invalid(param, value as f64, valid)
}

/// The main output: the scene's output link (a rocker or a slider), or the first
/// output where that is neither.
pub(crate) fn main_output(k: &Kinematics) -> Option<Output> {
    let m = k.mechanism();
    let all = outputs(k);
    let is_main = |o: &&Output| match o {
        Output::Rocker { link, .. } => *link == m.output,
        Output::Slide { slider, .. } => m.sliders[*slider].slider == m.output,
    };
    all.iter().find(is_main).or_else(|| all.first()).cloned()
}

/// The main output's s, v and a over the range (rocker angles unwrapped).
fn output_series(k: &mut Kinematics) -> Result<Option<OutputSeries>> {
    let Some(out) = main_output(k) else {
        return Ok(None);
    };
    let sw = sweep(k, DIAGRAM_STEPS)?;
    let unit = |x: f64| if out.is_angle() { x.to_degrees() } else { x };
    let series = |f: &dyn Fn(&Solution, &[f64]) -> f64| -> Vec<[f64; 2]> {
        sw.solutions
            .iter()
            .zip(&sw.angles)
            .map(|(s, row)| [s.input_rad.to_degrees(), f(s, row)])
            .filter(|p| p[1].is_finite())
            .collect()
    };
    let s = match &out {
        Output::Rocker { link, .. } => {
            let link = link.index();
            series(&|_, row| row[link].to_degrees())
        }
        Output::Slide { .. } => series(&|s, _| out.value(s)),
    };
    Ok(Some(OutputSeries {
        name: out.name().to_string(),
        is_angle: out.is_angle(),
        s,
        v: series(&|s, _| unit(out.rate(s))),
        a: series(&|s, _| unit(out.acceleration(s))),
    }))
}
