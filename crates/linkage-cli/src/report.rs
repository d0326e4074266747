//! `linkage report`: the analyses of one scene, as JSON in SI for programs or as text
//! in the scene's unit and degrees.

use crate::args::{ReportFormat, SceneArgs};
use crate::error::Result;
use crate::io::{describe, json_text, length_unit, load};

/// `report SCENE [--format text]`.
pub(crate) fn report(args: &SceneArgs, format: ReportFormat) -> Result<String> {
    let mut k = load(args)?;
    let r = linkage::analysis::report(&mut k)?;
    let peaks = linkage::analysis::output_peaks(&mut k).map_err(|e| describe(args, e))?;
    match format {
        ReportFormat::Json => {
            let mut value = serde_json::to_value(&r)?;
            value["output_peaks"] = serde_json::to_value(&peaks)?;
            json_text(&value)
        }
        ReportFormat::Text => Ok(crate::report_text::text(&r, &peaks, length_unit(args)?)),
    }
}
