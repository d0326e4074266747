//! `linkage synth`: the crank-rocker here, the other syntheses in their own files
//! (`synth_function`, `synth_motion`, `synth_path`, `synth_die_cutter`).

use linkage::synthesis::{DieCutterSpec, crank_rocker};

use crate::args::SynthCommand;
use crate::error::{CliError, Result};
use crate::io::json_text;

/// `synth WHAT`.
pub(crate) fn synth(what: SynthCommand) -> Result<String> {
    match what {
        SynthCommand::CrankRocker {
            rocker,
            swing_deg,
            k,
            rocker_start_deg,
            arc_deg,
            side,
            scene_out,
        } => {
            let choice = arc_deg.map(|a| (a.to_radians(), if side >= 0 { 1 } else { -1 }));
            let d = crank_rocker(
                rocker,
                swing_deg.to_radians(),
                k,
                rocker_start_deg.to_radians(),
                choice,
            )?;
            if let Some(path) = scene_out {
                let scene = linkage::synthesis::four_bar_scene(&d, k);
                let text = scene.to_ron()?;
                std::fs::write(&path, text).map_err(|source| CliError::Write { path, source })?;
            }
            json_text(&serde_json::to_value(&d)?)
        }
        SynthCommand::Function {
            points,
            ground,
            scene_out,
        } => crate::synth_function::run(&points, ground, scene_out.as_deref()),
        SynthCommand::Path(args) => crate::synth_path::run(&args),
        SynthCommand::Motion {
            poses,
            moving,
            fixed_near,
            pair,
            scene_out,
        } => crate::synth_motion::run(
            &poses,
            &crate::synth_motion::Choice {
                moving,
                fixed_near,
                pair,
            },
            scene_out.as_deref(),
        ),
        SynthCommand::DieCutter {
            stroke_mm,
            k,
            link_mm,
            rpm,
            as_printed,
        } => {
            let spec = DieCutterSpec {
                stroke_m: stroke_mm * 1e-3,
                k,
                link_m: link_mm * 1e-3,
                crank_rpm: rpm,
            };
            let printed = match as_printed.as_deref() {
                Some(&[ab, bc]) => Some([ab, bc]),
                _ => None,
            };
            crate::synth_die_cutter::run(&spec, printed)
        }
    }
}
