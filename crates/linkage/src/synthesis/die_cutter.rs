//! The toggle six-bar of the die-cutter paper as geometry: a crank-rocker ABCD whose
//! rocker swings up to 90°, where C lies on DE (the toggle), and CE = CD driving the
//! die E on a vertical guide through D. From the requirements (stroke H, K and
//! CD = CE = L), or from the paper's printed AB and BC. The scene it gives carries
//! links, joints, guide, driver and branches only: the paper's loads, names and
//! notes are data in `assets/scenes/die_cutter*.ron` and words at each edge (the
//! command line's `synth die-cutter`, the app's synthesis tab).

use serde::Serialize;

use super::{CrankRocker, crank_rocker, plain_link, points};
use crate::error::{LinkageError, Result};
use crate::error::{Param, Valid};
use crate::scene::{
    Branch, DriverSpec, ForcesSpec, LengthUnit, LinkSpec, Models, SceneFile, SliderSpec,
    SolverSpec, Speed,
};

/// The die-cutter requirements of the second paper.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DieCutterSpec {
    /// Stroke H, m.
    pub stroke_m: f64,
    /// Time ratio K.
    pub k: f64,
    /// CD = CE = L, m.
    pub link_m: f64,
    /// Crank speed, rpm.
    pub crank_rpm: f64,
}

/// A synthesized toggle six-bar.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ToggleSixBar {
    /// The crank-rocker ABCD (D at the origin).
    pub design: CrankRocker,
    /// The rocker's angle at its far limit, rad (φ30 of the paper); the toggle is
    /// at 90°.
    pub far_rad: f64,
    /// CD = CE = L, m.
    pub link_m: f64,
}

impl ToggleSixBar {
    /// The rocker's swing from its far limit to the toggle, rad.
    pub fn swing_rad(&self) -> f64 {
        std::f64::consts::FRAC_PI_2 - self.far_rad
    }
}

/// Rocker angle at the far limit: S = H = 2L(1 − sin φ30).
pub fn die_cutter_far_angle(spec: &DieCutterSpec) -> Result<f64> {
    let s = 1.0 - spec.stroke_m / (2.0 * spec.link_m);
    if !(spec.stroke_m > 0.0 && spec.link_m > 0.0 && s > 0.0) {
        return Err(LinkageError::invalid(
            Param::Stroke,
            spec.stroke_m,
            Valid::StrokeBelow {
                two_l_m: 2.0 * spec.link_m,
            },
        ));
    }
    Ok(s.asin())
}

/// The written scene must load again: a crank speed that is not a finite number
/// would give a scene file that no reader accepts.
fn check_crank_speed(spec: &DieCutterSpec) -> Result<()> {
    if spec.crank_rpm.is_finite() {
        Ok(())
    } else {
        Err(LinkageError::invalid(
            Param::CrankRpm,
            spec.crank_rpm,
            Valid::Finite,
        ))
    }
}

/// Synthesizes the toggle six-bar: rocker CD swings from φ30 to 90° (C on DE at the
/// top, the toggle), crank-rocker ABCD from the swing and K, CE = CD, slider E on a
/// vertical guide through D.
pub fn die_cutter(spec: &DieCutterSpec) -> Result<ToggleSixBar> {
    check_crank_speed(spec)?;
    let phi30 = die_cutter_far_angle(spec)?;
    let design = crank_rocker(
        spec.link_m,
        std::f64::consts::FRAC_PI_2 - phi30,
        spec.k,
        phi30,
        None,
    )?;
    Ok(ToggleSixBar {
        design,
        far_rad: phi30,
        link_m: spec.link_m,
    })
}

/// The die cutter with the printed AB, BC and CD = CE, keeping the printed K and the
/// toggle at the top: the rocker swing these force, and A where they put it.
pub fn die_cutter_as_printed(
    crank_m: f64,
    coupler_m: f64,
    spec: &DieCutterSpec,
) -> Result<ToggleSixBar> {
    check_crank_speed(spec)?;
    let theta = std::f64::consts::PI * (spec.k - 1.0) / (spec.k + 1.0);
    let (near, far) = (coupler_m - crank_m, coupler_m + crank_m);
    let chord = (near * near + far * far - 2.0 * near * far * theta.cos()).sqrt();
    let swing = 2.0 * (chord / (2.0 * spec.link_m)).min(1.0).asin();
    let start = std::f64::consts::FRAC_PI_2 - swing;
    // A on the circle where the crank is the printed length: a root of crank(t) - AB.
    let best = crank_rocker(spec.link_m, swing, spec.k, start, None)?;
    let f = |t: f64| {
        crank_rocker(spec.link_m, swing, spec.k, start, Some((t, best.side)))
            .map_or(f64::NAN, |d| d.crank_m - crank_m)
    };
    let mut found = None;
    let n = 3600;
    let mut prev = (best.arc_rad, f(best.arc_rad));
    for i in 1..=n {
        let t = best.arc_rad + std::f64::consts::PI * i as f64 / n as f64;
        let v = f(t);
        if prev.1.is_finite() && v.is_finite() && prev.1.signum() != v.signum() {
            found = crate::roots_util::refine(prev.0, t, f);
            break;
        }
        prev = (t, v);
    }
    let t = found
        .ok_or_else(|| LinkageError::invalid(Param::CrankAb, crank_m, Valid::CrankPlaceable))?;
    let design = crank_rocker(spec.link_m, swing, spec.k, start, Some((t, best.side)))?;
    Ok(ToggleSixBar {
        design,
        far_rad: start,
        link_m: spec.link_m,
    })
}

/// The toggle six-bar as a scene in millimetres, the crank driven at `crank_rpm`:
/// geometry only (no name, loads or notes; callers add them).
pub fn toggle_six_bar_scene(t: &ToggleSixBar, crank_rpm: f64) -> SceneFile {
    let d = &t.design;
    let branch = if d.c_left_of_bd {
        Branch::Left("B".into(), "D".into())
    } else {
        Branch::Right("B".into(), "D".into())
    };
    SceneFile {
        name: String::new(),
        description: String::new(),
        notes: Vec::new(),
        models: Models::Kinematics,
        length_unit: LengthUnit::Millimetre,
        angle_unit: crate::scene::AngleUnit::Degree,
        links: links(d, t.link_m),
        sliders: vec![SliderSpec {
            slider: "die".into(),
            point: "E".into(),
            guide: "ground".into(),
            through: "D".into(),
            angle: 90.0,
            relative_angle: 0.0,
        }],
        driver: DriverSpec {
            link: "crank".into(),
            speed: Speed::Rpm(crank_rpm),
            start: 0.0,
        },
        branches: [("C".to_string(), branch), ("E".to_string(), Branch::Along)]
            .into_iter()
            .collect(),
        output: Some("die".into()),
        guess: Default::default(),
        forces: ForcesSpec::default(),
        solver: SolverSpec::default(),
        drive: None,
        cams: Vec::new(),
    }
}

/// The links in millimetres, at full precision (rounding would move the rocker's
/// limit off the toggle): ground AD, crank AB, coupler BC, rocker DC, CE of length
/// `link_m`, and the die at E.
fn links(d: &CrankRocker, link_m: f64) -> Vec<LinkSpec> {
    let mm = |v: f64| v * 1e3;
    let l = mm(link_m);
    let [ax, ay] = d.pivot_a.map(mm);
    vec![
        plain_link("ground", true, points(&[("A", ax, ay), ("D", 0.0, 0.0)])),
        plain_link(
            "crank",
            false,
            points(&[("A", 0.0, 0.0), ("B", mm(d.crank_m), 0.0)]),
        ),
        plain_link(
            "coupler",
            false,
            points(&[("B", 0.0, 0.0), ("C", mm(d.coupler_m), 0.0)]),
        ),
        plain_link("rocker", false, points(&[("D", 0.0, 0.0), ("C", l, 0.0)])),
        plain_link("link_ce", false, points(&[("C", 0.0, 0.0), ("E", l, 0.0)])),
        plain_link("die", false, points(&[("E", 0.0, 0.0)])),
    ]
}
