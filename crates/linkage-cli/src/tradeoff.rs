//! `linkage tradeoff`: the work–precision table (CSV on stdout) and its plot (PNG).

use linkage::dynamics::tradeoff::{default_plan, measure, plan_settings, reference_run};
use linkage::dynamics::{Method, Settings};

use crate::args::{SceneArgs, TradeoffArgs};
use crate::error::{CliError, Result};
use crate::io::{load, records_to_csv};
use crate::plot::{Series, work_precision_png};

/// Runs every method of the default plan against the DOP853 rtol-1e-13 reference.
pub fn run(scene: &SceneArgs, args: &TradeoffArgs) -> Result<String> {
    let k = load(scene)?;
    let mut base = Settings::new(Method::Dop853);
    base.t_end = args.t_end;
    base.use_stops = !args.no_stops;
    base.validate()?;
    let reference = reference_run(&k, &base, args.grid)?;
    let header: Vec<String> = [
        "method",
        "setting",
        "cpu_seconds",
        "rhs_evaluations",
        "steps",
        "max_q_error_rad",
        "event_time_error_s",
    ]
    .map(String::from)
    .to_vec();
    let mut rows = Vec::new();
    let mut series = Vec::new();
    for (method, settings) in default_plan() {
        let mut points = Vec::new();
        for setting in settings {
            let s = plan_settings(&base, method, setting);
            let row = measure(&k, &s, args.grid, &reference).map_err(|e| {
                CliError::refused(format!("{} at {setting:e}: {e}", method.label()))
            })?;
            points.push((row.cpu_seconds, row.max_q_error));
            rows.push(vec![
                method.label().to_string(),
                format!("{setting:e}"),
                format!("{:e}", row.cpu_seconds),
                row.rhs_evaluations.to_string(),
                row.steps.to_string(),
                format!("{:e}", row.max_q_error),
                format!("{:e}", row.event_time_error),
            ]);
        }
        series.push(Series {
            label: method.label().to_string(),
            points,
        });
    }
    if let Some(path) = &args.png {
        let name = &k.mechanism().name;
        work_precision_png(
            path,
            &format!("{name}: error against CPU time"),
            "CPU seconds per run (best of several)",
            "max |phi1 - phi1_ref|, rad",
            &series,
        )?;
    }
    records_to_csv(&header, &rows)
}
