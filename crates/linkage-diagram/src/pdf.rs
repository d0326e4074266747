//! A sheet as PDF: each SVG page parsed by usvg (as for PNG, with the same faces) and
//! drawn by krilla-svg onto an A4 page of one krilla document. Text stays text,
//! selectable and searchable, in the fonts it was set in, embedded and cut to the
//! glyphs used; the document is titled with the sheet's title.

use krilla::Document;
use krilla::geom::Size;
use krilla::metadata::Metadata;
use krilla::page::PageSettings;
use krilla_svg::{SurfaceExt, SvgSettings};

use crate::pages::Sheet;
use crate::png::Faces;

/// A4 in PDF points (72 to the inch): 210 × 297 mm.
const A4_PT: [f32; 2] = [595.276, 841.89];

/// `sheet`'s pages as one PDF, its Latin text in the face `font` (family `family`)
/// and its Chinese text in [`crate::png::CJK_FONT`]; the document's language is
/// `language` (a BCP 47 tag: "en", "zh-CN").
///
/// # Errors
/// A page whose SVG does not parse, or a document krilla cannot write.
pub fn document(
    sheet: &Sheet,
    font: &[u8],
    family: &str,
    language: &str,
) -> Result<Vec<u8>, String> {
    let mut doc = Document::new();
    doc.set_metadata(
        Metadata::new()
            .title(sheet.title.clone())
            .language(language.to_owned())
            .creator("Linkage Lab".to_owned()),
    );
    let size = Size::from_wh(A4_PT[0], A4_PT[1]).ok_or("the page has no size")?;
    let faces = Faces::new(font, family);
    for (i, svg) in sheet.pages.iter().enumerate() {
        let tree = faces
            .tree(svg)
            .map_err(|e| format!("page {}: {e}", i + 1))?;
        let mut page = doc.start_page_with(PageSettings::new(size));
        let mut surface = page.surface();
        surface
            .draw_svg(&tree, size, SvgSettings::default())
            .ok_or_else(|| format!("page {} cannot be drawn", i + 1))?;
        surface.finish();
        page.finish();
    }
    doc.finish()
        .map_err(|e| format!("the PDF cannot be written: {e:?}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two pages of Latin and Chinese text make a two-page PDF that embeds both
    /// faces.
    #[test]
    fn pages_become_pages_with_their_fonts() {
        let page = |t: &str| {
            format!(
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"210mm\" height=\"297mm\" \
                 viewBox=\"0 0 793.7 1122.5\"><text x=\"40\" y=\"60\" font-size=\"14\">{t}</text></svg>"
            )
        };
        let sheet = Sheet {
            title: "t".into(),
            pages: vec![page("crank AB"), page("曲柄 AB")],
        };
        let pdf = document(
            &sheet,
            epaint_default_fonts::UBUNTU_LIGHT,
            "Ubuntu",
            "zh-CN",
        )
        .expect("writes");
        let text = String::from_utf8_lossy(&pdf);
        assert!(pdf.starts_with(b"%PDF-"));
        assert!(text.contains("/Count 2"), "two pages");
        assert!(text.contains("Ubuntu"), "the Latin face is embedded");
        assert!(text.contains("NotoSans"), "the Chinese face is embedded");
    }
}
