//! The SVG sheets' drawing primitives: page sizes and fonts, text and typeset labels,
//! lines, circles, frames, scale bars, and a laid-out polygon (velocity,
//! acceleration or force) with its labels. Shared by the position sheet
//! ([`crate::svg`]), its force section and the course sheet.

use std::fmt::Write as _;

use crate::geometry::{Pt, Rect};
use crate::label::{Label, SCRIPT_SCALE, Script};
use crate::layout::{LaidPolygon, ScaleBar};
use crate::words::Lang;

/// A4 width in CSS pixels (210 mm at 96 per inch).
pub(crate) const PAGE_W: f64 = 793.7;
/// A4 height in CSS pixels (297 mm).
pub(crate) const PAGE_H: f64 = 1122.5;
pub(crate) const MARGIN: f64 = 40.0;
pub(crate) const FONT: f64 = 12.0;

/// Label sizes on the sheet: the approximate measure, as no font engine is at hand.
pub(crate) fn measure(label: &Label) -> [f64; 2] {
    label.approximate_size(FONT)
}

/// `text` cut with an ellipsis where it would run past `width` px at `size` px (the
/// approximate measure).
pub(crate) fn fit_text(text: &str, width: f64, size: f64) -> String {
    let wide = |t: &str| Label::plain(t).approximate_size(size)[0] > width;
    if !wide(text) {
        return text.to_owned();
    }
    let mut kept = String::new();
    for c in text.chars() {
        if wide(&format!("{kept}{c}…")) {
            break;
        }
        kept.push(c);
    }
    kept + "…"
}

/// A whole SVG document `height` px tall (A4 wide, sized in millimetres) around
/// `body`, titled `title`.
pub(crate) fn document(title: &str, body: &str, height: f64) -> String {
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
         <svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" \
         width=\"{:.1}mm\" height=\"{:.1}mm\" viewBox=\"0 0 {PAGE_W} {height:.1}\" \
         font-family=\"Ubuntu, Liberation Sans, Arial, Helvetica, Noto Sans CJK SC, Noto Sans SC, Microsoft YaHei, PingFang SC, sans-serif\">\n\
         <title>{}</title>\n\
         <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n{body}</svg>\n",
        PAGE_W * 25.4 / 96.0,
        height * 25.4 / 96.0,
        escape(title)
    )
}

/// A framed pane with `title` (bold, `title_px`) at its top left; returns the part
/// below the title, where its figure goes.
pub(crate) fn titled_pane(out: &mut String, pane: &Rect, title: &str, title_px: f64) -> Rect {
    frame(out, pane);
    text_at(
        out,
        [pane.min[0] + 6.0, pane.min[1] + 15.0],
        title,
        title_px,
        "bold",
    );
    Rect {
        min: [pane.min[0], pane.min[1] + TITLE_H],
        max: pane.max,
    }
}

/// `#rrggbb`.
pub(crate) fn hex([r, g, b]: [u8; 3]) -> String {
    format!("#{r:02x}{g:02x}{b:02x}")
}

/// The face of a text that holds Chinese: the Chinese face for all of it, Latin
/// letters too, as a textbook sets a Chinese line. (resvg shapes a run in the first
/// face and takes the characters it lacks from the next; where the Latin face joins
/// letters into a ligature, as "fi", the run loses its Chinese.) Nothing for a text
/// without Chinese, which takes the sheet's face.
pub(crate) fn family(t: &str) -> &'static str {
    if t.chars().any(crate::label::is_cjk) {
        " font-family=\"Noto Sans CJK SC, Noto Sans SC, Microsoft YaHei, PingFang SC, sans-serif\""
    } else {
        ""
    }
}

pub(crate) fn escape(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// `t` escaped, with each `_{…}` of a symbol the catalogue writes (M_{b}, J_{F},
/// ΔW_{max}) set as a subscript of the text's `size`: what a textbook prints, not
/// an underscore. A name the user typed with an underscore (`bell_crank`) has no
/// brace after it and stays as typed.
pub(crate) fn typeset(t: &str, size: f64) -> String {
    let mut out = String::new();
    for run in Label::marked(t).runs {
        match run.script {
            Script::Sub => {
                let _ = write!(
                    out,
                    "<tspan font-size=\"{:.1}\" baseline-shift=\"sub\">{}</tspan>",
                    size * SCRIPT_SCALE,
                    escape(&run.text)
                );
            }
            _ => out.push_str(&escape(&run.text)),
        }
    }
    out
}

pub(crate) fn text_at(out: &mut String, at: Pt, t: &str, size: f64, weight: &str) {
    let _ = writeln!(
        out,
        "<text x=\"{:.1}\" y=\"{:.1}\" font-size=\"{size}\" font-weight=\"{weight}\"{}>{}</text>",
        at[0],
        at[1],
        family(t),
        typeset(t, size)
    );
}

/// `t` in `size` px ending at `at` (right-aligned), in grey: a pane's note.
pub(crate) fn text_at_end(out: &mut String, at: Pt, t: &str, size: f64) {
    let _ = writeln!(
        out,
        "<text x=\"{:.1}\" y=\"{:.1}\" font-size=\"{size}\" fill=\"#555555\" text-anchor=\"end\"{}>{}</text>",
        at[0],
        at[1],
        family(t),
        typeset(t, size)
    );
}

/// A typeset label with its box's left top at `min`.
pub(crate) fn label_at(out: &mut String, label: &Label, min: Pt, colour: &str) {
    let scripted = label.runs.iter().any(|r| r.script != Script::Base);
    let baseline = min[1] + FONT * if scripted { 1.05 } else { 0.92 };
    let _ = write!(
        out,
        "<text x=\"{:.1}\" y=\"{baseline:.1}\" font-size=\"{FONT}\" fill=\"{colour}\"{}>",
        min[0],
        family(&label.text())
    );
    for r in &label.runs {
        let t = escape(&r.text);
        let small = FONT * SCRIPT_SCALE;
        match r.script {
            Script::Base => {
                let _ = write!(out, "<tspan>{t}</tspan>");
            }
            Script::Sub => {
                let _ = write!(
                    out,
                    "<tspan font-size=\"{small:.1}\" baseline-shift=\"sub\">{t}</tspan>"
                );
            }
            Script::Super => {
                let _ = write!(
                    out,
                    "<tspan font-size=\"{small:.1}\" baseline-shift=\"super\">{t}</tspan>"
                );
            }
        }
    }
    out.push_str("</text>\n");
}

pub(crate) fn line(out: &mut String, a: Pt, b: Pt, colour: &str, width: f64, dashed: bool) {
    let dash = if dashed {
        " stroke-dasharray=\"5 3\""
    } else {
        ""
    };
    let _ = writeln!(
        out,
        "<line x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" stroke=\"{colour}\" stroke-width=\"{width}\"{dash}/>",
        a[0], a[1], b[0], b[1]
    );
}

pub(crate) fn circle(out: &mut String, at: Pt, r: f64, fill: &str, stroke: &str) {
    let _ = writeln!(
        out,
        "<circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"{r}\" fill=\"{fill}\" stroke=\"{stroke}\"/>",
        at[0], at[1]
    );
}

pub(crate) fn polygon_shape(out: &mut String, pts: &[Pt], fill: &str, stroke: &str) {
    let list: Vec<String> = pts
        .iter()
        .map(|p| format!("{:.2},{:.2}", p[0], p[1]))
        .collect();
    let _ = writeln!(
        out,
        "<polygon points=\"{}\" fill=\"{fill}\" stroke=\"{stroke}\"/>",
        list.join(" ")
    );
}

pub(crate) fn frame(out: &mut String, pane: &Rect) {
    let _ = writeln!(
        out,
        "<rect x=\"{:.1}\" y=\"{:.1}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"none\" stroke=\"#bbbbbb\"/>",
        pane.min[0],
        pane.min[1],
        pane.width(),
        pane.height()
    );
}

pub(crate) fn scale_bar(out: &mut String, bar: &ScaleBar, unit: &str) {
    line(out, bar.from, bar.to, "#000000", 2.0, false);
    for end in [bar.from, bar.to] {
        line(
            out,
            [end[0], end[1] - 3.0],
            [end[0], end[1] + 3.0],
            "#000000",
            1.0,
            false,
        );
    }
    text_at(
        out,
        [bar.to[0] + 6.0, bar.to[1] + 4.0],
        &crate::numbers::si(bar.value, unit),
        FONT,
        "normal",
    );
}

pub(crate) fn leaders_and_label(
    out: &mut String,
    label: &Label,
    rect: &Rect,
    leader: Option<[Pt; 2]>,
    colour: &str,
) {
    if let Some([a, b]) = leader {
        line(out, a, b, "#999999", 0.7, false);
    }
    label_at(out, label, rect.min, colour);
}

/// Height of a pane's title line.
pub(crate) const TITLE_H: f64 = 20.0;

/// A laid-out polygon (velocity, acceleration or force) with its scale bar in
/// `unit`.
pub(crate) fn polygon(out: &mut String, unit: &str, laid: &LaidPolygon, lang: Lang) {
    if laid.px_per_unit <= 0.0 {
        let at = [laid.pane.min[0] + 6.0, laid.pane.centre()[1]];
        let note = crate::words::sw!(lang, "sheet.at_rest");
        text_at(out, at, &note, FONT, "normal");
        return;
    }
    for a in &laid.arrows {
        let c = hex(a.style.rgb());
        let width = if a.style.dashed() { 1.3 } else { 1.8 };
        line(out, a.from, a.to, &c, width, a.style.dashed());
        if let Some(h) = a.head {
            polygon_shape(out, &h, &c, "none");
        }
    }
    for &v in &laid.vertices {
        circle(out, v, 2.5, "#000000", "none");
    }
    for l in &laid.labels {
        let colour = match l.owner {
            crate::layout::LabelOwner::Arrow(i) => laid
                .arrows
                .iter()
                .find(|a| a.index == i)
                .map_or_else(|| "#000000".into(), |a| hex(a.style.rgb())),
            crate::layout::LabelOwner::Vertices(_) => "#000000".into(),
        };
        leaders_and_label(out, &l.label, &l.rect, l.leader, &colour);
    }
    if let Some(bar) = &laid.scale_bar {
        scale_bar(out, bar, unit);
    }
}
