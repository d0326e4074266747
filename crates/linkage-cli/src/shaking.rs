//! `linkage shaking`: the shaking force and moment on the frame over a cycle, before
//! and after the counterweights that balance it best (least squares or least peak, on
//! the crank or the links named), and what they do to the driving torque and the
//! flywheel.

use linkage::machine::{
    BalanceAim, Counterweight, FlywheelSizing, Shaking, counterweights, shaking, size_flywheel,
    with_counterweights,
};
use linkage::{Kinematics, LinkId, Mechanism};
use serde_json::json;

use crate::args::{AimArg, SceneArgs, SummaryFormat};
use crate::error::{CliError, Result};
use crate::io::{describe, json_text, load, to_csv};

/// The δ the flywheel figures are given for.
const DELTA: f64 = 0.05;

/// One side of the comparison: the shaking cycle and the flywheel sizing.
struct Side {
    shaking: Shaking,
    flywheel: FlywheelSizing,
}

fn side(k: &mut Kinematics, about: [f64; 2]) -> linkage::Result<Side> {
    Ok(Side {
        shaking: shaking(k, about)?,
        flywheel: size_flywheel(k, DELTA)?,
    })
}

/// The links named by `on` (default: the crank).
fn links(m: &Mechanism, on: &[String]) -> Result<Vec<LinkId>> {
    if on.is_empty() {
        return Ok(vec![m.driver.link]);
    }
    on.iter()
        .map(|name| {
            m.link_index(name).ok_or_else(|| {
                let names: Vec<&str> = m.links.iter().map(|l| l.name.as_str()).collect();
                CliError::refused(format!(
                    "--on {name}: no such link; the links are {}",
                    names.join(", ")
                ))
            })
        })
        .collect()
}

/// Runs both sides and formats them.
pub fn run(
    args: &SceneArgs,
    about: [f64; 2],
    on: &[String],
    aim: AimArg,
    format: SummaryFormat,
) -> Result<String> {
    let mut k = load(args)?;
    let links = links(k.mechanism(), on)?;
    let aim = match aim {
        AimArg::Rms => BalanceAim::Rms,
        AimArg::Peak => BalanceAim::Peak,
    };
    let before = side(&mut k, about).map_err(|e| describe(args, e))?;
    let weights =
        counterweights(&mut k, &before.shaking, &links, aim).map_err(|e| describe(args, e))?;
    let mut balanced = Kinematics::new(with_counterweights(k.mechanism(), &weights))?;
    let after = side(&mut balanced, about).map_err(|e| describe(args, e))?;
    let m = k.mechanism();
    match format {
        SummaryFormat::Text => Ok(summary(m, aim, &weights, &before, &after)),
        SummaryFormat::Csv => cycles_csv(&before.shaking, &after.shaking),
        SummaryFormat::Json => {
            let named: Vec<serde_json::Value> = weights
                .iter()
                .map(|c| json!({"link_name": m.links[c.link].name, "counterweight": c}))
                .collect();
            json_text(&json!({
                "scene": m.name,
                "aim": aim,
                "counterweights": named,
                "before": {"shaking": before.shaking, "flywheel": summary_of(&before.flywheel)},
                "after": {"shaking": after.shaking, "flywheel": summary_of(&after.flywheel)},
            }))
        }
    }
}

/// The flywheel's key figures (its cycle is `linkage flywheel`'s).
fn summary_of(f: &FlywheelSizing) -> serde_json::Value {
    json!({
        "delta": f.delta,
        "mean_torque_n_m": f.mean_torque_n_m,
        "peak_torque_n_m": f.peak_torque_n_m,
        "work_range_j": f.work_range_j,
        "flywheel_kg_m2": f.flywheel_kg_m2,
    })
}

fn summary(
    m: &Mechanism,
    aim: BalanceAim,
    weights: &[Counterweight],
    before: &Side,
    after: &Side,
) -> String {
    let row =
        |what: &str, a: f64, b: f64, unit: &str| format!("{what:<28}{a:>14.6e}{b:>14.6e} {unit}\n");
    let (s0, s1, f0, f1) = (
        &before.shaking,
        &after.shaking,
        &before.flywheel,
        &after.flywheel,
    );
    let aim_words = match aim {
        BalanceAim::Rms => "least squares",
        BalanceAim::Peak => "least peak",
    };
    let mut out = format!(
        "{}: shaking on the frame (moments about ({}, {}) m)\n",
        m.name, s0.about_m[0], s0.about_m[1]
    );
    for c in weights {
        out += &format!(
            "{} counterweight ({aim_words}): {:.6e} kg·m at {:.4} deg from the {}, \
             {:.6e} kg at ({:.6}, {:.6}) m on it\n",
            m.links[c.link].name,
            c.mass_radius_kg_m,
            c.angle_rad.to_degrees(),
            m.links[c.link].name,
            c.mass_kg,
            c.at_m[0],
            c.at_m[1],
        );
    }
    out += &format!("{:<28}{:>14}{:>14}\n", "", "without", "with");
    out += &row("peak shaking force", s0.peak_force_n, s1.peak_force_n, "N");
    out += &row("rms shaking force", s0.rms_force_n, s1.rms_force_n, "N");
    out += &row(
        "peak shaking moment",
        s0.peak_moment_n_m,
        s1.peak_moment_n_m,
        "N·m",
    );
    out += &row(
        "peak driving torque",
        f0.peak_torque_n_m,
        f1.peak_torque_n_m,
        "N·m",
    );
    out += &row("work surplus range", f0.work_range_j, f1.work_range_j, "J");
    out += &row(
        &format!("flywheel for delta {DELTA}"),
        f0.flywheel_kg_m2,
        f1.flywheel_kg_m2,
        "kg·m²",
    );
    out
}

/// Both cycles side by side, a row per crank angle.
fn cycles_csv(before: &Shaking, after: &Shaking) -> Result<String> {
    let header = [
        "angle_rad",
        "force_x_n",
        "force_y_n",
        "moment_n_m",
        "balanced_force_x_n",
        "balanced_force_y_n",
        "balanced_moment_n_m",
    ]
    .map(String::from);
    let rows: Vec<Vec<f64>> = before
        .cycle
        .iter()
        .zip(&after.cycle)
        .map(|(a, b)| {
            vec![
                a.angle_rad,
                a.force_n[0],
                a.force_n[1],
                a.moment_n_m,
                b.force_n[0],
                b.force_n[1],
                b.moment_n_m,
            ]
        })
        .collect();
    to_csv(&header, &rows)
}
