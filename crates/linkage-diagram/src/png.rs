//! The sheet as PNG: the SVG rendered by resvg (the reference Rust SVG renderer)
//! rather than drawn a second time, with only the font given loaded, so that the
//! picture is the same on every machine.

/// `svg` rendered at `dpi` (the sheet's units are CSS pixels, 96 to the inch) with the
/// sans-serif face `font` (TrueType or OpenType data, family `family`), as PNG bytes.
pub fn render(svg: &str, dpi: f32, font: &[u8], family: &str) -> Result<Vec<u8>, String> {
    let mut opt = resvg::usvg::Options::default();
    opt.fontdb_mut().load_font_data(font.to_vec());
    opt.fontdb_mut().set_sans_serif_family(family);
    opt.font_family = family.into();
    let tree = resvg::usvg::Tree::from_str(svg, &opt)
        .map_err(|e| format!("the SVG does not parse: {e}"))?;
    let zoom = dpi / 96.0;
    let size = tree
        .size()
        .to_int_size()
        .scale_by(zoom)
        .ok_or("the sheet has no size")?;
    let mut pixmap = resvg::tiny_skia::Pixmap::new(size.width(), size.height())
        .ok_or_else(|| format!("cannot make a {}x{} picture", size.width(), size.height()))?;
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::from_scale(zoom, zoom),
        &mut pixmap.as_mut(),
    );
    pixmap
        .encode_png()
        .map_err(|e| format!("cannot encode the PNG: {e}"))
}
