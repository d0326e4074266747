//! The designs the synthesis window makes, free of any GUI type: the inputs of each
//! kind, in the units a designer types (mm, deg), and the design as a table of words
//! and a scene. The solver does the synthesis (`linkage::synthesis`).

pub mod design;
pub mod function;
pub mod motion;
pub mod path_inputs;
pub mod path_job;

use linkage::synthesis::{
    CrankRocker, DieCutterSpec, ToggleSixBar, crank_rocker, die_cutter, four_bar_scene,
    toggle_six_bar_scene,
};

pub use crate::synthesis::design::{Design, Figure, SynthError};
use crate::synthesis::design::{deg, mm, row};

/// Which design.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SynthKind {
    /// A crank-rocker from swing and K.
    CrankRocker,
    /// The die cutter's six-bar from H, K and L.
    DieCutter,
    /// A function generator through precision points.
    Function,
    /// A four-bar through three, four or five positions of a body.
    Motion,
    /// A four-bar whose coupler point passes through targets (a search).
    Path,
}

impl SynthKind {
    /// Every kind, in the window's order.
    pub const ALL: [SynthKind; 5] = [
        SynthKind::CrankRocker,
        SynthKind::DieCutter,
        SynthKind::Function,
        SynthKind::Motion,
        SynthKind::Path,
    ];

    /// Its tab's label.
    pub fn label(self) -> &'static str {
        match self {
            SynthKind::CrankRocker => "crank-rocker",
            SynthKind::DieCutter => "die cutter",
            SynthKind::Function => "function",
            SynthKind::Motion => "positions",
            SynthKind::Path => "path",
        }
    }
}

/// The inputs of every kind (each kept while another is shown).
#[derive(Clone, Debug, PartialEq)]
pub struct SynthInputs {
    /// Which design.
    pub kind: SynthKind,
    /// Crank-rocker: rocker CD (mm), swing (deg), K.
    pub rocker: [f64; 3],
    /// Die cutter: stroke H (mm), K, L (mm), crank speed (rpm).
    pub die: [f64; 4],
    /// Function: precision points, `input_deg, output_deg` per line.
    pub function_points: String,
    /// Function: ground AD, mm.
    pub function_ground_mm: f64,
    /// Function: the function to generate (else the typed points).
    pub function_spec: Option<crate::synthesis::function::FunctionSpec>,
    /// Motion: the body's three to five positions, `x_mm, y_mm, angle_deg` per line.
    pub poses: String,
    /// Motion: what fixes the four-bar (moving pivots, fixed pivots, Burmester pair).
    pub motion: crate::synthesis::motion::MotionChoice,
    /// Path: the targets and constraints of the search.
    pub path: crate::synthesis::path_inputs::PathInputs,
}

impl Default for SynthInputs {
    fn default() -> Self {
        Self {
            kind: SynthKind::CrankRocker,
            rocker: [600.0, 16.6, 1.3],
            die: [50.0, 1.3, 600.0, 50.0],
            // y = log10(x) on [1, 2] at its three Chebyshev points: θ over 60° from
            // 30°, φ over 90° from 240°.
            function_points: "34.0192, 248.4189\n60.0, 292.6466\n85.9808, 325.5766\n".into(),
            function_ground_mm: 100.0,
            function_spec: None,
            poses: "0, 0, 0\n200, 100, 20\n350, 300, 45\n".into(),
            motion: crate::synthesis::motion::MotionChoice::default(),
            path: crate::synthesis::path_inputs::PathInputs::default(),
        }
    }
}

/// The design of `inputs`, or why there is none (in words: it is shown at once).
///
/// # Errors
/// Inputs outside their valid range, rows that are not numbers, or requirements no
/// linkage of the kind meets; each names its cause.
pub fn design(inputs: &SynthInputs) -> Result<Design, SynthError> {
    match inputs.kind {
        SynthKind::CrankRocker => rocker(inputs.rocker),
        SynthKind::DieCutter => die(inputs.die),
        SynthKind::Function => match &inputs.function_spec {
            Some(spec) => crate::synthesis::function::from_spec(spec, inputs.function_ground_mm),
            None => crate::synthesis::function::from_points(
                &inputs.function_points,
                inputs.function_ground_mm,
            ),
        },
        SynthKind::Motion => crate::synthesis::motion::motion(&inputs.poses, &inputs.motion),
        // Not closed form: the window runs its search (`crate::synthesis::path_job`).
        SynthKind::Path => Err(SynthError::PathIsSearched),
    }
}

fn rocker([cd_mm, swing_deg, k]: [f64; 3]) -> Result<Design, SynthError> {
    let d = crank_rocker(
        cd_mm * 1e-3,
        swing_deg.to_radians(),
        k,
        45f64.to_radians(),
        None,
    )?;
    Ok(Design {
        table: crank_rocker_rows(&d, "rocker CD", "least transmission angle"),
        scene: four_bar_scene(&d, k),
        figure: Figure::None,
    })
}

/// The table of a crank-rocker design, its rocker and transmission rows named by
/// the caller (the die cutter's rocker is also CE, and its angle is ABCD's only).
fn crank_rocker_rows(d: &CrankRocker, rocker: &str, transmission: &str) -> Vec<(String, String)> {
    vec![
        row("crank AB", mm(d.crank_m)),
        row("coupler BC", mm(d.coupler_m)),
        row(rocker, mm(d.rocker_m)),
        row("ground AD", mm(d.ground_m)),
        row("crank angle between the limits", deg(d.theta_rad)),
        row(transmission, deg(d.min_transmission_rad)),
    ]
}

fn die([h_mm, k, l_mm, rpm]: [f64; 4]) -> Result<Design, SynthError> {
    let spec = DieCutterSpec {
        stroke_m: h_mm * 1e-3,
        k,
        link_m: l_mm * 1e-3,
        crank_rpm: rpm,
    };
    let t = die_cutter(&spec)?;
    Ok(Design {
        table: crank_rocker_rows(
            &t.design,
            "rocker CD = CE",
            "least transmission angle (ABCD)",
        ),
        scene: die_cutter_scene(&t, [h_mm, k, l_mm, rpm]),
        figure: Figure::None,
    })
}

/// The synthesized toggle six-bar with the paper's loads (its pressing force and
/// die, from the shipped scene), named and described from the inputs typed.
fn die_cutter_scene(t: &ToggleSixBar, [h_mm, k, l_mm, rpm]: [f64; 4]) -> linkage::scene::SceneFile {
    let mut scene = toggle_six_bar_scene(t, rpm);
    if let Some(paper) = crate::catalog::builtin("die_cutter")
        .and_then(|b| linkage::scene::SceneFile::parse(b.text).ok())
    {
        scene = scene.with_loads_of(&paper);
    }
    let d = &t.design;
    scene.name = format!("Die cutter (H = {h_mm} mm, K = {k}, L = {l_mm} mm)");
    scene.description = format!(
        "Toggle six-bar synthesized from stroke H = {h_mm} mm, time ratio K = {k} and CD = CE = L = {l_mm} mm: AB = {}, BC = {}, AD = {}; the rocker swings from {} to 90°, where C lies on DE (the toggle). The pressing force and the die's mass are the paper's.",
        mm(d.crank_m),
        mm(d.coupler_m),
        mm(d.ground_m),
        deg(t.far_rad)
    );
    scene.notes = vec![format!(
        "φ30 = asin(1 − H/(2L)) = {}; the crank pivot A is where the least transmission angle is largest ({}).",
        deg(t.far_rad),
        deg(d.min_transmission_rad)
    )];
    scene
}
