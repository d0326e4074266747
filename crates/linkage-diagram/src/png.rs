//! The sheet as PNG: the SVG rendered by resvg (the reference Rust SVG renderer)
//! rather than drawn a second time, with only the font given loaded, so that the
//! picture is the same on every machine. Chinese text (names in a scene, a sheet in
//! Chinese) draws with Noto Sans CJK SC, cut to the common characters
//! (`scripts/cjk_font.py`; SIL OFL, `assets/fonts/OFL.txt`).

/// Noto Sans CJK SC cut to the common characters: the face Chinese text is drawn
/// with, here and in the desktop app.
pub const CJK_FONT: &[u8] = include_bytes!("../../../assets/fonts/NotoSansSC-Subset.otf");

/// `svg` rendered at `dpi` (the sheet's units are CSS pixels, 96 to the inch) with the
/// sans-serif face `font` (TrueType or OpenType data, family `family`), and
/// [`CJK_FONT`] for the characters it lacks where the sheet holds Chinese text, as
/// PNG bytes.
pub fn render(svg: &str, dpi: f32, font: &[u8], family: &str) -> Result<Vec<u8>, String> {
    let opt = options(font, family, has_cjk(svg));
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

/// Whether `text` holds a character of the Chinese face's ranges (CJK radicals to
/// the full-width forms).
pub(crate) fn has_cjk(text: &str) -> bool {
    text.chars().any(crate::label::is_cjk)
}

/// resvg's options with `font` as the sans-serif face, and [`CJK_FONT`] beside it
/// when `cjk`: usvg falls back, glyph by glyph, to a loaded face that has the
/// character.
pub(crate) fn options(font: &[u8], family: &str, cjk: bool) -> resvg::usvg::Options<'static> {
    let mut opt = resvg::usvg::Options::default();
    opt.fontdb_mut().load_font_data(font.to_vec());
    if cjk {
        opt.fontdb_mut().load_font_data(CJK_FONT.to_vec());
    }
    opt.fontdb_mut().set_sans_serif_family(family);
    opt.font_family = family.into();
    opt
}

/// The characters of `svg`'s text that [`render`] would draw as no glyph (the
/// faces' `.notdef`), in order: none on a sheet whose every word is drawn.
///
/// # Errors
/// An SVG that does not parse.
pub fn undrawn_characters(svg: &str, font: &[u8], family: &str) -> Result<Vec<String>, String> {
    undrawn_with(svg, &options(font, family, has_cjk(svg)))
}

fn undrawn_with(svg: &str, opt: &resvg::usvg::Options<'_>) -> Result<Vec<String>, String> {
    let tree = resvg::usvg::Tree::from_str(svg, opt)
        .map_err(|e| format!("the SVG does not parse: {e}"))?;
    let mut undrawn = Vec::new();
    collect_undrawn(tree.root(), &mut undrawn);
    Ok(undrawn)
}

fn collect_undrawn(group: &resvg::usvg::Group, out: &mut Vec<String>) {
    for node in group.children() {
        match node {
            resvg::usvg::Node::Group(g) => collect_undrawn(g, out),
            resvg::usvg::Node::Text(t) => {
                for span in t.layouted() {
                    out.extend(
                        span.positioned_glyphs
                            .iter()
                            .filter(|g| g.id.0 == 0 && !g.text.trim().is_empty())
                            .map(|g| g.text.clone()),
                    );
                }
            }
            _ => {}
        }
    }
}

/// A text of a sheet as drawn: its characters and the box its glyphs cover on the
/// page, px.
#[derive(Clone, Debug, PartialEq)]
pub struct TextBox {
    /// The text.
    pub text: String,
    /// The box of its glyphs' outlines, in the page's coordinates.
    pub rect: crate::geometry::Rect,
}

/// The faces sheets are drawn in (a Latin face and [`CJK_FONT`]), loaded once for
/// many pages: parsing the Chinese face is most of a page's cost.
pub struct Faces {
    options: resvg::usvg::Options<'static>,
}

impl Faces {
    /// The sans-serif face `font` (family `family`) with the Chinese face beside it.
    pub fn new(font: &[u8], family: &str) -> Self {
        Self {
            options: options(font, family, true),
        }
    }

    /// `svg` parsed and laid out with these faces.
    ///
    /// # Errors
    /// An SVG that does not parse.
    pub fn tree(&self, svg: &str) -> Result<resvg::usvg::Tree, String> {
        resvg::usvg::Tree::from_str(svg, &self.options)
            .map_err(|e| format!("the SVG does not parse: {e}"))
    }

    /// Every text of `svg` with the box it is drawn in: what a test of a sheet's
    /// legibility measures (no text over another, none past the page).
    ///
    /// # Errors
    /// An SVG that does not parse.
    pub fn text_boxes(&self, svg: &str) -> Result<Vec<TextBox>, String> {
        let mut boxes = Vec::new();
        collect_boxes(self.tree(svg)?.root(), &mut boxes);
        Ok(boxes)
    }
}

impl Faces {
    /// Every straight piece of every stroked line of `svg` (a curve by its
    /// chord), in the page's coordinates: what a test of a sheet's
    /// legibility checks the texts against (no line drawn through a text).
    ///
    /// # Errors
    /// An SVG that does not parse.
    pub fn stroked_segments(&self, svg: &str) -> Result<Vec<[crate::geometry::Pt; 2]>, String> {
        let mut segments = Vec::new();
        collect_segments(self.tree(svg)?.root(), None, &mut segments);
        Ok(segments)
    }
}

/// The part of the segment `[p, q]` inside `clip` (Liang–Barsky), if any.
fn clipped(
    [p, q]: [crate::geometry::Pt; 2],
    clip: Option<&crate::geometry::Rect>,
) -> Option<[crate::geometry::Pt; 2]> {
    let Some(r) = clip else {
        return Some([p, q]);
    };
    let d = [q[0] - p[0], q[1] - p[1]];
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (k, lo, hi) in [(0, r.min[0], r.max[0]), (1, r.min[1], r.max[1])] {
        if d[k] == 0.0 {
            if p[k] < lo || p[k] > hi {
                return None;
            }
            continue;
        }
        let (a, b) = ((lo - p[k]) / d[k], (hi - p[k]) / d[k]);
        t0 = t0.max(a.min(b));
        t1 = t1.min(a.max(b));
    }
    let at = |t: f64| [p[0] + t * d[0], p[1] + t * d[1]];
    (t0 < t1).then(|| [at(t0), at(t1)])
}

/// The stroked segments under `group`, cut to the clip paths around them (a plot's
/// curve runs past its frame and is clipped there).
fn collect_segments(
    group: &resvg::usvg::Group,
    clip: Option<crate::geometry::Rect>,
    out: &mut Vec<[crate::geometry::Pt; 2]>,
) {
    use resvg::tiny_skia::PathSegment;
    for node in group.children() {
        match node {
            resvg::usvg::Node::Group(g) => {
                let own = g.clip_path().map(|c| {
                    let b = c.root().abs_bounding_box();
                    crate::geometry::Rect {
                        min: [f64::from(b.left()), f64::from(b.top())],
                        max: [f64::from(b.right()), f64::from(b.bottom())],
                    }
                });
                collect_segments(g, own.or(clip), out);
            }
            resvg::usvg::Node::Path(p) if p.stroke().is_some() => {
                let t = p.abs_transform();
                let at = |q: resvg::tiny_skia::Point| {
                    let mut q = q;
                    t.map_point(&mut q);
                    [f64::from(q.x), f64::from(q.y)]
                };
                let (mut start, mut last) = ([0.0; 2], [0.0; 2]);
                for segment in p.data().segments() {
                    let to = match segment {
                        PathSegment::MoveTo(q) => {
                            start = at(q);
                            last = start;
                            continue;
                        }
                        PathSegment::LineTo(q) => at(q),
                        PathSegment::QuadTo(_, q) | PathSegment::CubicTo(_, _, q) => at(q),
                        PathSegment::Close => start,
                    };
                    out.extend(clipped([last, to], clip.as_ref()));
                    last = to;
                }
            }
            _ => {}
        }
    }
}

fn collect_boxes(group: &resvg::usvg::Group, out: &mut Vec<TextBox>) {
    for node in group.children() {
        match node {
            resvg::usvg::Node::Group(g) => collect_boxes(g, out),
            resvg::usvg::Node::Text(t) => {
                let b = t.abs_bounding_box();
                let text: String = t.chunks().iter().map(|c| c.text()).collect();
                out.push(TextBox {
                    text,
                    rect: crate::geometry::Rect {
                        min: [f64::from(b.left()), f64::from(b.top())],
                        max: [f64::from(b.right()), f64::from(b.bottom())],
                    },
                });
            }
            _ => {}
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const UBUNTU: &[u8] = epaint_default_fonts::UBUNTU_LIGHT;

    /// Chinese names draw with the Chinese face; without it, the same words are
    /// glyphs the sheet's Latin face lacks (so the check can fail).
    #[test]
    fn chinese_text_is_drawn_with_the_chinese_face() {
        let svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"40\">\
                   <text x=\"5\" y=\"30\" font-size=\"20\">曲柄 AB 连杆，滑块</text></svg>";
        assert_eq!(undrawn_characters(svg, UBUNTU, "Ubuntu"), Ok(Vec::new()));
        let latin_only = undrawn_with(svg, &options(UBUNTU, "Ubuntu", false)).expect("parses");
        assert_eq!(latin_only.concat(), "曲柄连杆，滑块");
    }

    /// A unit's dot in a line set in the Chinese face comes from the Latin face:
    /// the Chinese face's is full-width, and "kN·m" read "kN · m" in a Chinese
    /// report (the subset leaves it out, scripts/cjk_font.py).
    #[test]
    fn a_chinese_lines_unit_dot_is_the_latin_one() {
        let svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"300\" height=\"40\">\
                   <text x=\"5\" y=\"30\" font-size=\"20\" font-family=\"Noto Sans CJK SC\">\
                   平衡力矩 50.31 kN·m</text></svg>";
        let tree = Faces::new(UBUNTU, "Ubuntu").tree(svg).expect("parses");
        let mut dots = Vec::new();
        collect_glyph_faces(tree.root(), tree.fontdb(), &mut dots);
        let faces: Vec<&String> = dots
            .iter()
            .filter(|(t, _)| t == "·")
            .map(|(_, f)| f)
            .collect();
        assert_eq!(faces, ["Ubuntu"], "{dots:?}");
    }

    /// Each drawn character with the family of the face that draws it.
    fn collect_glyph_faces(
        group: &resvg::usvg::Group,
        db: &resvg::usvg::fontdb::Database,
        out: &mut Vec<(String, String)>,
    ) {
        for node in group.children() {
            match node {
                resvg::usvg::Node::Group(g) => collect_glyph_faces(g, db, out),
                resvg::usvg::Node::Text(t) => {
                    for span in t.layouted() {
                        for g in &span.positioned_glyphs {
                            let family = db
                                .face(g.font)
                                .and_then(|f| f.families.first().map(|(n, _)| n.clone()))
                                .unwrap_or_default();
                            out.push((g.text.clone(), family));
                        }
                    }
                }
                _ => {}
            }
        }
    }
}
