//! `linkage timing`: the timing diagram of a scene, every output (links pinned to
//! ground, sliders) against the main shaft's angle as a share of its stroke, with its
//! dwells: CSV or JSON to standard output, the sheet as SVG or PNG where asked.

use linkage::analysis::{TimingDiagram, timing};
use linkage_diagram::svg_timing::timing_sheet;
use serde_json::json;

use crate::args::{Format, SceneArgs, SheetOut};
use crate::diagram::{check_dpi, write_sheet};
use crate::error::{CliError, Result};
use crate::io::{check_finite, describe, json_text, load, to_csv};

/// Runs the command.
pub fn run(scene: &SceneArgs, samples: usize, format: Format, out: &SheetOut) -> Result<String> {
    if !(4..=100_000).contains(&samples) {
        return Err(CliError::refused(format!(
            "--samples {samples} is out of range: 4 to 100000"
        )));
    }
    check_dpi(out)?;
    let mut k = load(scene)?;
    let d = timing(&mut k, samples).map_err(|e| describe(scene, e))?;
    for lane in &d.lanes {
        check_finite(&lane.share, &lane.name)?;
    }
    if out.svg.is_some() || out.png.is_some() {
        write_sheet(timing_sheet(&k.mechanism().name, &d, out.lang), out)?;
    }
    match format {
        Format::Csv => rows_csv(&d),
        Format::Json => json_text(&json!(d)),
    }
}

/// `shaft_deg`, then per output its value (deg or m) and its share of the stroke.
fn rows_csv(d: &TimingDiagram) -> Result<String> {
    let mut header = vec!["shaft_deg".to_string()];
    for lane in &d.lanes {
        let unit = if lane.is_angle { "deg" } else { "m" };
        header.push(format!("{}_{unit}", lane.name));
        header.push(format!("{}_share", lane.name));
    }
    let rows: Vec<Vec<f64>> = d
        .shaft_rad
        .iter()
        .enumerate()
        .map(|(i, x)| {
            let mut row = vec![x.to_degrees()];
            for lane in &d.lanes {
                let [lo, hi] = lane.range;
                let value = lo + lane.share[i] * (hi - lo);
                row.push(if lane.is_angle {
                    value.to_degrees()
                } else {
                    value
                });
                row.push(lane.share[i]);
            }
            row
        })
        .collect();
    to_csv(&header, &rows)
}
