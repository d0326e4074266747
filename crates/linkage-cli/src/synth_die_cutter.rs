//! `linkage synth die-cutter`: the toggle six-bar from the solver's geometry, with the
//! paper's loads from its scene files (`assets/scenes/die_cutter*.ron`, built in)
//! and this command's words: how to make it again, and what the paper got wrong.

use linkage::scene::SceneFile;
use linkage::synthesis::{
    DieCutterSpec, ToggleSixBar, die_cutter, die_cutter_as_printed, toggle_six_bar_scene,
};

use crate::error::{CliError, Result};

/// The paper's die cutter as shipped: its loads and name.
const SYNTHESIZED: &str = include_str!("../../../assets/scenes/die_cutter.ron");
/// The paper's printed dimensions as shipped.
const AS_PRINTED: &str = include_str!("../../../assets/scenes/die_cutter_as_printed.ron");

/// The shipped scene `text`, which the build embeds (it parses: the tests open
/// every shipped scene).
fn paper(text: &str) -> Result<SceneFile> {
    SceneFile::parse(text).map_err(|e| CliError::refused(format!("the built-in paper scene: {e}")))
}

/// The scene file text of the die cutter: from the requirements, or with the printed
/// AB and BC (mm) where `as_printed` gives them.
pub(crate) fn run(spec: &DieCutterSpec, as_printed: Option<[f64; 2]>) -> Result<String> {
    let scene = match as_printed {
        Some([ab, bc]) => {
            let t = die_cutter_as_printed(ab * 1e-3, bc * 1e-3, spec)?;
            printed(&t, spec, ab * 1e-3, bc * 1e-3, &paper(AS_PRINTED)?)
        }
        None => synthesized(&die_cutter(spec)?, spec, &paper(SYNTHESIZED)?),
    };
    Ok(scene.to_ron()? + "\n")
}

/// The die cutter from the requirements, described with the command that makes it.
fn synthesized(t: &ToggleSixBar, spec: &DieCutterSpec, paper: &SceneFile) -> SceneFile {
    let d = &t.design;
    let mut scene = toggle_six_bar_scene(t, spec.crank_rpm).with_loads_of(paper);
    scene.name = paper.name.clone();
    scene.description = format!(
        "Toggle six-bar force amplifier of the flat-press die cutter (paper 2), synthesized by `linkage synth die-cutter --stroke-mm {} --k {} --link-mm {}` from H, K and CD = CE = L; AB = {:.3} mm, BC = {:.3} mm, AD = {:.3} mm; rocker swings {:.3} deg to {:.0} deg where C lies on DE (toggle).",
        spec.stroke_m * 1e3,
        spec.k,
        spec.link_m * 1e3,
        d.crank_m * 1e3,
        d.coupler_m * 1e3,
        d.ground_m * 1e3,
        t.far_rad.to_degrees(),
        90.0
    );
    scene.notes = vec![
        format!(
            "phi30 = asin(1 - H/(2L)) = {:.4} deg: the paper's bound 'L <= 600 gives phi30 <= 73.4 deg'.",
            t.far_rad.to_degrees()
        ),
        "The crank turns at 50 rpm = 5.236 rad/s; the paper's v_B = 44.93 m/s uses the motor's 151.8 rad/s.".into(),
        "Pressing force 2e6 N acts on the die only on the upward working stroke; die + slider 120 kg.".into(),
        format!(
            "Crank pivot A chosen on the synthesis circle for the best minimum transmission angle ({:.2} deg).",
            d.min_transmission_rad.to_degrees()
        ),
    ];
    scene
}

/// The die cutter with the printed AB and BC (m), and the contradiction they show.
fn printed(
    t: &ToggleSixBar,
    spec: &DieCutterSpec,
    crank_m: f64,
    coupler_m: f64,
    paper: &SceneFile,
) -> SceneFile {
    let mut scene = toggle_six_bar_scene(t, spec.crank_rpm).with_loads_of(paper);
    scene.name = paper.name.clone();
    scene.description = format!(
        "The paper's printed dimensions AB = {:.0} mm, BC = {:.0} mm, CD = CE = {:.0} mm, keeping its K = {} and the toggle at the top (C on DE). These lengths force a rocker swing of {:.2} deg (not the 30 deg of phi30 = 60 deg), so the stroke is far from 50 mm: see `linkage report`.",
        crank_m * 1e3,
        coupler_m * 1e3,
        spec.link_m * 1e3,
        spec.k,
        t.swing_rad().to_degrees()
    );
    scene.notes = vec![
        "Contradiction shown, not hidden: AB = 295.42, BC = 891.96 with K = 1.3 need a rocker swing of about 69 deg, which no 50 mm stroke allows.".into(),
        "The paper's v_B = 44.93 m/s is omega x AB with omega = 151.8 rad/s, the MOTOR speed (1450 rpm); the crank turns at 50 rpm = 5.236 rad/s. Reproduce with `linkage at ... --speed-rad-s 151.8`.".into(),
        "Paper's graphical results for its position 1: v_C = 50.436 m/s, v_E = 49.772 m/s (from its inconsistent geometry).".into(),
        "Ground pivot A is not printed; it is placed where the printed AB, BC, CD and K are consistent.".into(),
    ];
    scene
}
