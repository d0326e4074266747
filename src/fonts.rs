//! The app's fonts: egui's Ubuntu-Light for all text, proportional and monospace,
//! and egui's few icons.
//!
//! Why not egui's `default_fonts`: they add the Hack monospace face, which only
//! egui_plot's axis numbers would use here, and which is 0.15 MB of the web demo's
//! 2.4 MB download gzipped. The faces come from `epaint_default_fonts`, the crate
//! egui takes its own from, so the text looks as egui's does.

use std::sync::Arc;

use eframe::egui::{FontData, FontDefinitions, FontFamily, FontTweak};

/// Ubuntu-Light for both families, egui's icon face as fallback.
pub fn definitions() -> FontDefinitions {
    let mut fonts = FontDefinitions::empty();
    fonts.font_data.insert(
        "Ubuntu-Light".to_owned(),
        Arc::new(FontData::from_static(epaint_default_fonts::UBUNTU_LIGHT)),
    );
    fonts.font_data.insert(
        "egui-icons".to_owned(),
        // The scale egui gives the same face: its icons sit with the text.
        Arc::new(
            FontData::from_static(epaint_default_fonts::EGUI_ICONS).tweak(FontTweak {
                scale: 0.90,
                ..Default::default()
            }),
        ),
    );
    let family = vec!["Ubuntu-Light".to_owned(), "egui-icons".to_owned()];
    fonts
        .families
        .insert(FontFamily::Proportional, family.clone());
    fonts.families.insert(FontFamily::Monospace, family);
    fonts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_family_has_a_face_for_text_and_symbols() {
        let ctx = eframe::egui::Context::default();
        ctx.set_fonts(definitions());
        // A frame loads the fonts; its texture upload is not needed here.
        ctx.run_ui(Default::default(), |_| {})
            .textures_delta
            .clear();
        for family in [FontFamily::Proportional, FontFamily::Monospace] {
            let font = eframe::egui::FontId::new(14.0, family.clone());
            // Every non-ASCII character in a string literal of the app or the solver
            // (their messages are shown); egui's own fonts lack '→' too, so none uses it.
            for c in "°±²µ·×Δλμφω–—…−≤".chars() {
                assert!(
                    ctx.fonts_mut(|f| f.has_glyph(&font, c)),
                    "{family:?} lacks {c:?}"
                );
            }
        }
    }
}
