//! Everything `linkage report` prints, gathered in one pass.

use serde::Serialize;

use crate::error::{AssemblyFailure, LinkageError, Result};
use crate::solve::{Kinematics, PathKind};

use super::grashof::{Grashof, grashof};
use super::limits::LimitPosition;
use super::limits::{FoundLimit, align_flat_limits, found_limits, span};
use super::outputs::{Output, outputs};
use super::time_ratio::{TimeRatioNote, time_ratio};
use super::toggles::Toggle;
use super::toggles::toggles;
use super::transmission::{TransmissionAngle, transmission_angle};
use crate::assembly::AssemblyRanges;
use crate::ranges::assembly_ranges_of;

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
