//! `linkage kinetostatics`: input torque (Newton–Euler and virtual work), every joint
//! reaction and the force amplification over one input cycle.

use linkage::kinetostatics::{JointKind, Kinetostatics};
use serde_json::{Value, json};

use crate::args::{Format, SceneArgs};
use crate::error::{CliError, Result};
use crate::io::{describe, json_text, load, records_to_csv};

/// The columns: the input, the torque both ways, each joint's reaction (and a
/// slider's couple, a cam contact's push), the amplification.
fn header(joints: &[linkage::kinetostatics::JointReaction]) -> Vec<String> {
    let mut header: Vec<String> = ["input_rad", "torque_n_m", "torque_virtual_work_n_m"]
        .map(String::from)
        .to_vec();
    for j in joints {
        header.push(format!("{}_fx", j.name));
        header.push(format!("{}_fy", j.name));
        match j.kind {
            JointKind::Prismatic => header.push(format!("{}_couple", j.name)),
            JointKind::CamContact => header.push(format!("{}_push", j.name)),
            JointKind::Revolute => {}
        }
    }
    header.push("amplification".into());
    header
}

/// One row, in [`header`]'s order; `None` where a figure is undefined (a singular
/// amplification, a push with no cam contact).
fn row(input: f64, s: &linkage::kinetostatics::KinetostaticState) -> Vec<Option<f64>> {
    let mut row = vec![
        Some(input),
        Some(s.torque_newton_euler),
        Some(s.torque_virtual_work),
    ];
    for j in &s.joints {
        row.extend([Some(j.force.0), Some(j.force.1)]);
        match j.kind {
            JointKind::Prismatic => row.push(Some(j.couple)),
            JointKind::CamContact => row.push(j.push),
            JointKind::Revolute => {}
        }
    }
    row.push(s.amplification);
    row
}

/// Runs the cycle and formats it; a singular amplification is an empty CSV field
/// (JSON null), never infinity.
pub fn run(args: &SceneArgs, steps: usize, format: Format) -> Result<String> {
    if steps == 0 {
        return Err(CliError::refused("--steps must be at least 1"));
    }
    let mut k = load(args)?;
    let mut ks = Kinetostatics::new(&mut k)?;
    let start = k.mechanism().driver.start_rad;
    let mut header = Vec::new();
    let mut rows: Vec<Vec<Option<f64>>> = Vec::with_capacity(steps);
    let mut worst = 0.0_f64;
    let mut sampled = Vec::with_capacity(steps);
    for i in 0..steps {
        let input = start + std::f64::consts::TAU * i as f64 / steps as f64;
        let s = ks.at(&mut k, input).map_err(|e| describe(args, e))?;
        if i == 0 {
            header = self::header(&s.joints);
        }
        let row = row(input, &s);
        if row.iter().flatten().any(|v| !v.is_finite()) {
            return Err(CliError::refused(format!(
                "non-finite kinetostatics at input {input} rad"
            )));
        }
        worst = worst.max((s.torque_newton_euler - s.torque_virtual_work).abs());
        sampled.push([input, s.torque_newton_euler.abs()]);
        rows.push(row);
    }
    // The largest torque located between the rows, not read off them.
    let turn = std::f64::consts::TAU;
    let peak = linkage::extremum::locate_max(&sampled, Some(turn), |x| {
        ks.at(&mut k, x).ok().map(|s| s.torque_newton_euler.abs())
    })
    .unwrap_or(linkage::extremum::Extreme {
        angle_rad: start,
        value: 0.0,
    });
    match format {
        Format::Csv => {
            let text: Vec<Vec<String>> = rows
                .iter()
                .map(|r| {
                    r.iter()
                        .map(|v| v.map_or(String::new(), |v| format!("{v:e}")))
                        .collect()
                })
                .collect();
            records_to_csv(&header, &text)
        }
        Format::Json => json_text(&json!({
            "scene": k.mechanism().name,
            "columns": header,
            "rows": rows.iter().map(|r| r.iter().map(|v| v.map_or(Value::Null, |v| json!(v))).collect::<Vec<_>>()).collect::<Vec<_>>(),
            "max_torque_n_m": peak.value,
            "max_torque_at_rad": peak.angle_rad,
            "torque_agreement_relative": if peak.value > 0.0 { worst / peak.value } else { 0.0 },
        })),
    }
}
