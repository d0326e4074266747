//! The course-design report's data (课程设计说明书): what a machine-theory course
//! design ends in, gathered from the same analyses the app and the command line
//! show — the task's data (the scene's name, notes, crank speed, link lengths), the
//! mechanism's structure (degrees of freedom by the formula, its Assur groups), the
//! positions table, the course sheet (plan, s–v–a diagrams, polygons, force
//! polygons), the flywheel where the scene has loads, the cams, and the results.
//! [`crate::svg_report`] lays it out on A4 pages.

use linkage::analysis::{Report, report};
use linkage::cam::CamPoint;
use linkage::dyad::GroupLabel;
use linkage::extremum::{locate_max, locate_min};
use linkage::machine::{FlywheelSizing, size_flywheel};
use linkage::model::CamJoint;
use linkage::polygon::{Quantity, polygons};
use linkage::{Kinematics, Result};

use crate::course::CourseSheet;

/// The coefficient of speed fluctuation the report's flywheel is sized for: 0.05,
/// the textbooks' value for general machinery (punches and presses allow 0.05 to
/// 0.15).
pub const REPORT_DELTA: f64 = 0.05;

/// One row of the positions table: the main output at a position.
#[derive(Clone, Debug, PartialEq)]
pub struct PositionRow {
    /// Its number on the plan.
    pub number: usize,
    /// The crank angle, degrees.
    pub crank_deg: f64,
    /// Displacement, velocity, acceleration (m, m/s, m/s², or rad, rad/s, rad/s²).
    pub s_v_a: [f64; 3],
}

/// A link of the task's data: its number, name and the distances between its
/// joints (m), as the scene gives them.
#[derive(Clone, Debug, PartialEq)]
pub struct LinkRow {
    /// Its number (the frame is 1).
    pub number: usize,
    /// Its name.
    pub name: String,
    /// Joint to joint, m: one for a binary link, three for a ternary one.
    pub lengths_m: Vec<(String, f64)>,
}

/// The degrees of freedom by the formula F = 3n − 2P_L − P_H.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mobility {
    /// Moving links, n.
    pub moving: usize,
    /// Lower pairs (revolute and prismatic), P_L.
    pub lower: usize,
    /// Higher pairs (cam contacts), P_H.
    pub higher: usize,
    /// F.
    pub dof: i64,
}

/// A cam's figures: its name, base circle, largest pressure angle with where and
/// its limit, and its profile's least radius of curvature.
#[derive(Clone, Debug, PartialEq)]
pub struct CamFigures {
    /// The cam joint's name.
    pub name: String,
    /// Base circle radius, m.
    pub base_radius_m: f64,
    /// Largest pressure angle, rad, and the cam angle where, rad.
    pub largest_pressure: [f64; 2],
    /// The allowed pressure angle, rad.
    pub limit_rad: f64,
    /// The profile's least radius of curvature, m.
    pub least_radius_m: f64,
}

/// Everything the report writes.
#[derive(Clone, Debug)]
pub struct CourseReport {
    /// The course sheet: positions, diagrams, chosen polygons, forces.
    pub course: CourseSheet,
    /// The cycle's analysis (Grashof, K, strokes, transmission angle, notes).
    pub analysis: Report,
    /// The main output's name and whether it turns (a rocker) or slides.
    pub output: Option<(String, bool)>,
    /// The positions table.
    pub positions: Vec<PositionRow>,
    /// The task's links.
    pub links: Vec<LinkRow>,
    /// The structure's count.
    pub mobility: Mobility,
    /// The Assur groups, in the order they are solved.
    pub groups: Vec<GroupLabel>,
    /// The flywheel for [`REPORT_DELTA`], where the scene has loads.
    pub flywheel: Option<FlywheelSizing>,
    /// Every cam's figures.
    pub cams: Vec<CamFigures>,
}

impl CourseReport {
    /// The report of `k`'s mechanism with `count` positions and polygons at
    /// `chosen`.
    ///
    /// # Errors
    /// What [`CourseSheet::compute`] and the cycle's analysis refuse.
    pub fn compute(k: &mut Kinematics, count: usize, chosen: &[usize]) -> Result<Self> {
        Self::compute_from(k, count, None, chosen)
    }

    /// [`Self::compute`] with position 0 at the crank angle `first_deg` where given
    /// ([`CourseSheet::compute_from`]).
    ///
    /// # Errors
    /// As [`CourseSheet::compute_from`] and the cycle's analysis.
    pub fn compute_from(
        k: &mut Kinematics,
        count: usize,
        first_deg: Option<f64>,
        chosen: &[usize],
    ) -> Result<Self> {
        let course = CourseSheet::compute_from(k, count, first_deg, chosen)?;
        let analysis = report(k)?;
        let main = crate::course::main_output(k);
        let positions = course
            .positions
            .iter()
            .enumerate()
            .map(|(number, s)| PositionRow {
                number,
                crank_deg: s.input_rad.to_degrees(),
                s_v_a: main
                    .as_ref()
                    .map_or([0.0; 3], |o| [o.value(s), o.rate(s), o.acceleration(s)]),
            })
            .collect();
        let groups = course.positions.first().map_or_else(Vec::new, |s| {
            polygons(k, s)
                .into_iter()
                .filter(|e| e.kind == Quantity::Velocity)
                .map(|e| e.group)
                .collect()
        });
        // Only where the scene gives masses or loads: a kinematics scene has no torque
        // to even out (its sizing would be a flywheel of 0).
        let loaded = linkage::kinetostatics::Kinetostatics::new(k).is_ok();
        let flywheel = if loaded {
            size_flywheel(k, REPORT_DELTA).ok()
        } else {
            None
        };
        let m = k.mechanism();
        Ok(Self {
            output: main.map(|o| (o.name().to_string(), o.is_angle())),
            positions,
            links: course
                .positions
                .first()
                .map_or_else(Vec::new, |s| links(m, s)),
            mobility: mobility(m),
            groups,
            cams: m.cams.iter().map(cam_figures).collect(),
            flywheel,
            analysis,
            course,
        })
    }
}

/// Each moving link with the distances between its joints (by the joints' letters),
/// measured at the first position: the lengths the scene gives it.
fn links(m: &linkage::Mechanism, s: &linkage::Solution) -> Vec<LinkRow> {
    m.moving_links()
        .map(|l| {
            let joints = crate::pose_figure::link_joints(m, l);
            let mut lengths = Vec::new();
            for (i, &a) in joints.iter().enumerate() {
                for &b in &joints[i + 1..] {
                    let d = (s.points[a].position - s.points[b].position).norm();
                    let name = format!("{}{}", m.points[a].name, m.points[b].name);
                    lengths.push((name, d));
                }
            }
            LinkRow {
                number: crate::pose_figure::link_number(m, l),
                name: m.links[l].name.clone(),
                lengths_m: lengths,
            }
        })
        .collect()
}

fn mobility(m: &linkage::Mechanism) -> Mobility {
    let moving = m.links.len() - 1;
    let lower = m.revolutes.len() + m.sliders.len();
    let higher = m.cams.len();
    Mobility {
        moving,
        lower,
        higher,
        dof: 3 * moving as i64 - 2 * lower as i64 - higher as i64,
    }
}

/// A cam's figures: each extreme bracketed by the profile sampled every degree and
/// located on the cam itself (as the app's cam panel locates them).
fn cam_figures(c: &CamJoint) -> CamFigures {
    let turn = Some(std::f64::consts::TAU);
    let points: Vec<CamPoint> = (0..360)
        .map(|i| c.point_at(f64::from(i).to_radians()))
        .collect();
    let series = |f: &dyn Fn(&CamPoint) -> f64| -> Vec<[f64; 2]> {
        points.iter().map(|p| [p.angle_rad, f(p)]).collect()
    };
    let centre = |p: &CamPoint| p.profile_m[0].hypot(p.profile_m[1]);
    let pressure = |p: &CamPoint| p.pressure_angle_rad.abs();
    let radius = |p: &CamPoint| p.profile_radius_m;
    let base = locate_min(&series(&centre), turn, |x| Some(centre(&c.point_at(x))));
    let largest = locate_max(&series(&pressure), turn, |x| Some(pressure(&c.point_at(x))));
    let least = locate_min(&series(&radius), turn, |x| Some(radius(&c.point_at(x))));
    CamFigures {
        name: c.name.clone(),
        base_radius_m: base.map_or(0.0, |e| e.value),
        largest_pressure: largest.map_or([0.0; 2], |e| [e.value, e.angle_rad]),
        limit_rad: c.pressure_limit_rad(),
        least_radius_m: least.map_or(0.0, |e| e.value),
    }
}
