//! Typeset labels in egui: a [`Label`]'s runs as one text layout, sub- and
//! superscripts smaller and aligned low or high, as the textbooks set v_CB and a_C^n.

use std::sync::Arc;

use eframe::egui::{self, Align, Color32, FontId, Galley, text::LayoutJob};
use linkage_diagram::label::{Label, SCRIPT_SCALE, Script};

/// The layout of `label` at `size` points in `colour`.
pub fn job(label: &Label, size: f32, colour: Color32) -> LayoutJob {
    let mut job = LayoutJob::default();
    for run in &label.runs {
        let (font, valign) = match run.script {
            Script::Base => (size, Align::Center),
            Script::Sub => (size * SCRIPT_SCALE as f32, Align::BOTTOM),
            Script::Super => (size * SCRIPT_SCALE as f32, Align::TOP),
        };
        job.append(
            &run.text,
            0.0,
            egui::TextFormat {
                font_id: FontId::proportional(font),
                color: colour,
                valign,
                ..Default::default()
            },
        );
    }
    job
}

/// The laid-out label, ready to paint or measure.
pub fn galley(painter: &egui::Painter, label: &Label, size: f32, colour: Color32) -> Arc<Galley> {
    painter.layout_job(job(label, size, colour))
}
