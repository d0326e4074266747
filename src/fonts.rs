//! The app's fonts: egui's Ubuntu-Light for all text, proportional and monospace,
//! egui's few icons, and Noto Sans CJK SC for Chinese (cut to the common characters
//! by `scripts/cjk_font.py`; SIL OFL, `assets/fonts/OFL.txt`). The desktop app
//! embeds the Chinese face; the web demo fetches it only once Chinese text is to
//! be shown (`web_font.rs`), so that an English user's first download does not grow
//! by its 1.5 MB.
//!
//! Why not egui's `default_fonts`: they add the Hack monospace face, which only
//! egui_plot's axis numbers would use here, and which is 0.15 MB of the web demo's
//! 2.4 MB download gzipped. The faces come from `epaint_default_fonts`, the crate
//! egui takes its own from, so the text looks as egui's does.

use std::sync::Arc;

use eframe::egui::epaint::text::{FontInsert, FontPriority, InsertFontFamily};
use eframe::egui::{FontData, FontDefinitions, FontFamily, FontTweak};

/// The Chinese face's name among the fonts.
pub const CJK_FACE: &str = "NotoSansSC";

/// Where the web demo fetches the Chinese face, beside its page.
pub const CJK_FONT_URL: &str = "fonts/NotoSansSC-Subset.otf";

/// The Chinese face, embedded in the desktop app (the sheets' PNG draws with the
/// same bytes).
#[cfg(not(target_arch = "wasm32"))]
const CJK_FONT: &[u8] = linkage_diagram::png::CJK_FONT;

/// Whether `text` holds a character that only the Chinese face draws (CJK
/// ideographs and radicals, CJK punctuation, full-width forms).
pub fn has_cjk(text: &str) -> bool {
    text.chars().any(|c| {
        matches!(c, '\u{2E80}'..='\u{9FFF}' | '\u{F900}'..='\u{FAFF}' | '\u{FF00}'..='\u{FFEF}')
    })
}

/// The Chinese face (an `.otf`'s bytes) as the last fallback of both families:
/// Latin text keeps Ubuntu-Light.
pub fn cjk_insert(data: FontData) -> FontInsert {
    let last = |family| InsertFontFamily {
        family,
        priority: FontPriority::Lowest,
    };
    FontInsert::new(
        CJK_FACE,
        data,
        vec![last(FontFamily::Proportional), last(FontFamily::Monospace)],
    )
}

/// Ubuntu-Light for both families, egui's icon face as fallback, and on the desktop
/// the Chinese face after it.
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
    #[allow(unused_mut)] // the web demo adds the Chinese face when it is needed
    let mut family = vec!["Ubuntu-Light".to_owned(), "egui-icons".to_owned()];
    #[cfg(not(target_arch = "wasm32"))]
    {
        fonts.font_data.insert(
            CJK_FACE.to_owned(),
            Arc::new(FontData::from_static(CJK_FONT)),
        );
        family.push(CJK_FACE.to_owned());
    }
    fonts
        .families
        .insert(FontFamily::Proportional, family.clone());
    fonts.families.insert(FontFamily::Monospace, family);
    fonts
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every non-ASCII character between quotes on a line of code (not a comment) in
    /// the app and the crates whose text it shows: read from the sources, so that a
    /// new symbol in a label is checked without being listed here.
    fn non_ascii_in_string_literals() -> std::collections::BTreeSet<char> {
        let mut found = std::collections::BTreeSet::new();
        let dirs = ["src", "crates/linkage/src", "crates/linkage-diagram/src"];
        for (_, text) in crate::test_sources::rust_sources(&dirs) {
            for line in text.lines().filter(|l| !l.trim_start().starts_with("//")) {
                if let (Some(a), Some(b)) = (line.find('"'), line.rfind('"')) {
                    found.extend(line[a..b].chars().filter(|c| !c.is_ascii()));
                }
            }
        }
        found
    }

    #[test]
    fn every_family_has_a_face_for_text_and_symbols() {
        let ctx = eframe::egui::Context::default();
        ctx.set_fonts(definitions());
        // A frame loads the fonts; its texture upload is not needed here.
        ctx.run_ui(Default::default(), |_| {})
            .textures_delta
            .clear();
        let mut shown = non_ascii_in_string_literals();
        // And every word of the catalogue, in both languages.
        let catalogue = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("locales/app.yml"),
        )
        .expect("the catalogue");
        shown.extend(
            catalogue
                .lines()
                .filter(|l| !l.trim_start().starts_with('#'))
                .flat_map(str::chars)
                .filter(|c| !c.is_ascii()),
        );
        assert!(shown.contains(&'°'), "{shown:?}");
        for family in [FontFamily::Proportional, FontFamily::Monospace] {
            let font = eframe::egui::FontId::new(14.0, family.clone());
            // egui panics on a glyph no face has (egui's own fonts lack '→' too).
            for &c in &shown {
                assert!(
                    ctx.fonts_mut(|f| f.has_glyph(&font, c)),
                    "{family:?} lacks {c:?}, used in a string the app shows"
                );
            }
        }
    }
}
