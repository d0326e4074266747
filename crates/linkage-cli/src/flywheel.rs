//! `linkage flywheel`: the flywheel the energy method sizes for a speed fluctuation δ,
//! with the cycle it is sized on.

use linkage::machine::{FlywheelSizing, size_flywheel};
use serde_json::json;

use crate::args::{SceneArgs, SummaryFormat};
use crate::error::Result;
use crate::io::{describe, json_text, load, to_csv};

/// Sizes the flywheel and formats it.
pub fn run(args: &SceneArgs, delta: f64, format: SummaryFormat) -> Result<String> {
    let mut k = load(args)?;
    let sized = size_flywheel(&mut k, delta).map_err(|e| describe(args, e))?;
    let name = &k.mechanism().name;
    match format {
        SummaryFormat::Text => Ok(summary(name, &sized)),
        SummaryFormat::Csv => cycle_csv(&sized),
        SummaryFormat::Json => json_text(&json!({"scene": name, "flywheel": sized})),
    }
}

/// The key figures, one a line, with their units.
fn summary(name: &str, s: &FlywheelSizing) -> String {
    let rpm = s.speed_rad_s * 60.0 / std::f64::consts::TAU;
    let j = &s.reduced_inertia_kg_m2;
    format!(
        "{name}: flywheel by the energy method at {rpm:.4} rpm ({:.6} rad/s), delta = {}\n\
         mean torque        {:.6e} N·m\n\
         mean power         {:.6e} W\n\
         peak torque        {:.6e} N·m at {:.4} deg\n\
         work surplus range {:.6e} J (largest at {:.4} deg, smallest at {:.4} deg)\n\
         flywheel on crank  {:.6e} kg·m²\n\
         mechanism's reduced inertia {:.6e} to {:.6e} kg·m² (mean {:.6e})\n{}",
        s.speed_rad_s,
        s.delta,
        s.mean_torque_n_m,
        s.mean_power_w,
        s.peak_torque_n_m,
        s.peak_torque_at_rad.to_degrees().rem_euclid(360.0),
        s.work_range_j,
        s.angle_of_max_rad.to_degrees(),
        s.angle_of_min_rad.to_degrees(),
        s.flywheel_kg_m2,
        j.min,
        j.max,
        j.mean,
        drive_lines(s),
    )
}

/// With a drive: its rotor's and train's inertia at the crank, and the flywheel
/// still to fit beside them, on the crank and on the motor shaft.
fn drive_lines(s: &FlywheelSizing) -> String {
    let Some(on_motor) = s.flywheel_to_add_on_motor_kg_m2 else {
        return String::new();
    };
    format!(
        "drive's rotor and train at crank {:.6e} kg·m²\n\
         flywheel to add    {:.6e} kg·m² on the crank, {:.6e} kg·m² on the motor shaft\n",
        s.drive_inertia_kg_m2, s.flywheel_to_add_kg_m2, on_motor,
    )
}

/// The cycle: angle, torque, surplus and reduced inertia per row.
fn cycle_csv(s: &FlywheelSizing) -> Result<String> {
    let header = [
        "angle_rad",
        "torque_n_m",
        "surplus_j",
        "reduced_inertia_kg_m2",
    ]
    .map(String::from);
    let rows: Vec<Vec<f64>> = s
        .cycle
        .iter()
        .map(|c| {
            vec![
                c.angle_rad,
                c.torque_n_m,
                c.surplus_j,
                c.reduced_inertia_kg_m2,
            ]
        })
        .collect();
    to_csv(&header, &rows)
}
