//! Every sheet is print-ready: every page is A4 (210 × 297 mm), and on every page no
//! text is drawn over another text or past the page's margins, and no line through
//! the middle of a text. The texts' boxes are
//! measured as resvg lays them out with the sheets' own faces (the app's Latin face
//! and the Chinese one), not by the approximate measure the layout used; checked on
//! every shipped scene and example (the Chinese-named one among them), at inputs
//! over its range (position sheets with every part, instant centres and force
//! polygons) and its course sheet, in English and in Chinese.
#![cfg(feature = "png")]

use crate::common;

use linkage::Kinematics;
use linkage_diagram::Rect;
use linkage_diagram::course::CourseSheet;
use linkage_diagram::pages::Sheet;
use linkage_diagram::png::{Faces, TextBox};
use linkage_diagram::svg_course::course_sheet;
use linkage_diagram::words::Lang;

const FONT: &[u8] = epaint_default_fonts::UBUNTU_LIGHT;
/// A4 in the sheets' units (CSS px, 96 to the inch).
const PAGE: [f64; 2] = [793.7, 1122.5];
/// The margin no text may enter but the foot, px (the sheets keep 40).
const EDGE: f64 = 15.0;
/// Overlap allowed between two boxes, px: glyph outlines of neighbouring lines may
/// touch by antialiasing's width.
const SLACK: f64 = 0.5;

/// The problems on one page: texts past the edge and texts over texts; then the
/// lines drawn through texts.
fn problems(page: &str) -> Vec<String> {
    let (mut found, lines) = problems_and_lines(page);
    found.extend(lines);
    found
}

/// The problems on one page apart (texts past the edge or over texts), and the
/// lines drawn through texts.
fn problems_and_lines(page: &str) -> (Vec<String>, Vec<String>) {
    thread_local! {
        static FACES: Faces = Faces::new(FONT, "Ubuntu");
    }
    let boxes = FACES.with(|f| f.text_boxes(page)).expect("the page parses");
    let segments = FACES
        .with(|f| f.stroked_segments(page))
        .expect("the page parses");
    let inside = Rect {
        min: [EDGE, EDGE],
        max: [PAGE[0] - EDGE, PAGE[1] - EDGE],
    };
    let mut found: Vec<String> = boxes
        .iter()
        .filter(|b| !inside.contains_rect(&b.rect))
        .map(|b| format!("{:?} runs past the page's margin at {:?}", b.text, b.rect))
        .collect();
    for (i, a) in boxes.iter().enumerate() {
        for b in &boxes[i + 1..] {
            if overlap(a, b) {
                found.push(format!(
                    "{:?} at {:?} overlaps {:?} at {:?}",
                    a.text, a.rect, b.text, b.rect
                ));
            }
        }
    }
    let lines = boxes
        .iter()
        .filter_map(|b| {
            let [p, q] = segments
                .iter()
                .find(|[p, q]| core(&b.rect).crosses_segment(*p, *q))?;
            Some(format!(
                "a line from {p:.1?} to {q:.1?} runs through {:?} at {:?}",
                b.text, b.rect
            ))
        })
        .collect();
    (found, lines)
}

/// The middle of a text's box: its glyphs' cores, which a line the text names may
/// pass beside (a label sits by its line) but not through. The box less 15 % of its
/// width either side and 22 % of its height above and below: a line through a
/// term's subscript ("a_B^n" with its arrow along the B) strikes it out as surely
/// as one through the letter (with 30 %, as first measured, that one passed).
fn core(r: &Rect) -> Rect {
    let [w, h] = [r.max[0] - r.min[0], r.max[1] - r.min[1]];
    let (dx, dy) = (0.15 * w, 0.22 * h);
    Rect {
        min: [r.min[0] + dx, r.min[1] + dy],
        max: [r.max[0] - dx, r.max[1] - dy],
    }
}

fn overlap(a: &TextBox, b: &TextBox) -> bool {
    let w = a.rect.max[0].min(b.rect.max[0]) - a.rect.min[0].max(b.rect.min[0]);
    let h = a.rect.max[1].min(b.rect.max[1]) - a.rect.min[1].max(b.rect.min[1]);
    w > SLACK && h > SLACK
}

/// Every page is A4 and clean; adds the problems to `out` and the lines through
/// texts to `lines`, each named by `what`.
fn check(sheet: &Sheet, what: &str, out: &mut Vec<String>, lines: &mut Vec<String>) {
    for (i, page) in sheet.pages.iter().enumerate() {
        let a4 = page.contains("width=\"210.0mm\" height=\"297.0mm\"");
        if !a4 {
            out.push(format!("{what}, page {}: not A4", i + 1));
        }
        let (found, through) = problems_and_lines(page);
        let named = |p: String| format!("{what}, page {}: {p}", i + 1);
        out.extend(found.into_iter().map(named));
        lines.extend(through.into_iter().map(named));
    }
}

/// No problem found and no line through a text, or each listed.
fn assert_clean(found: &[String], lines: &[String]) {
    assert!(
        found.is_empty(),
        "{} problems:\n{}",
        found.len(),
        found.join("\n")
    );
    assert!(
        lines.is_empty(),
        "{} lines through texts:\n{}",
        lines.len(),
        lines.join("\n")
    );
}

#[test]
fn every_page_of_every_sheet_is_a4_with_no_text_over_text() {
    let (mut found, mut lines) = (Vec::new(), Vec::new());
    for (file, m) in common::scenes_and_examples() {
        let mut k = Kinematics::new(m).expect("kinematics");
        for lang in Lang::ALL {
            for x in common::inputs(&k, 3) {
                if let Some(sheet) = common::full_sheet(&mut k, x, lang) {
                    let what = format!("{file} at {:.1}° ({})", x.to_degrees(), lang.code());
                    check(&sheet, &what, &mut found, &mut lines);
                }
            }
            let course = CourseSheet::compute(&mut k, 12, &[1, 7]).expect("course sheet");
            let what = format!("{file}: course sheet ({})", lang.code());
            check(&course_sheet(&course, lang), &what, &mut found, &mut lines);
        }
    }
    assert_clean(&found, &lines);
}

/// The check finds what it is for: two texts drawn on one spot, a text past the
/// page's edge, and a line through a text (not one beside it).
#[test]
fn the_check_sees_an_overlap_and_a_text_off_the_page() {
    let page = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"210.0mm\" height=\"297.0mm\" \
                viewBox=\"0 0 793.7 1122.5\">\
                <text x=\"100\" y=\"100\" font-size=\"12\">counter-clockwise</text>\
                <text x=\"150\" y=\"102\" font-size=\"12\">solved</text>\
                <text x=\"760\" y=\"300\" font-size=\"12\">cut at the edge</text>\
                <text x=\"100\" y=\"500\" font-size=\"12\">struck through</text>\
                <line x1=\"90\" y1=\"496\" x2=\"220\" y2=\"496\" stroke=\"black\"/>\
                <text x=\"100\" y=\"600\" font-size=\"12\">underlined</text>\
                <line x1=\"90\" y1=\"603\" x2=\"220\" y2=\"603\" stroke=\"black\"/></svg>";
    let found = problems(page);
    assert_eq!(found.len(), 3, "{found:#?}");
    assert!(
        found
            .iter()
            .any(|p| p.contains("runs through \"struck through\""))
    );
    assert!(found.iter().any(|p| p.contains("overlaps")));
    assert!(found.iter().any(|p| p.contains("past the page")));
}

/// A student's task sheet, as an exercise words it: every shipped scene drawn at its
/// start with data and questions long enough to wrap, in English and Chinese.
#[test]
fn every_task_sheet_is_a4_with_no_text_over_text() {
    use linkage_diagram::svg_task::{TaskSheet, task_sheet};
    let (mut found, mut lines) = (Vec::new(), Vec::new());
    for (file, m) in common::scenes_and_examples() {
        let mut k = Kinematics::new(m).expect("kinematics");
        let s = k
            .solve(k.mechanism().driver.start_rad)
            .expect("assembles at its start");
        for lang in Lang::ALL {
            let (q, v) = match lang {
                Lang::English => (
                    "Angular velocity ω of rocker at φ = 30° (counter-clockwise +)",
                    "through D, at 90° to x",
                ),
                Lang::Chinese => (
                    "φ = 30° 时构件 rocker 的角速度 ω（逆时针为正）",
                    "过 D 点，与 x 轴成 90°",
                ),
            };
            let task = TaskSheet {
                title: format!(
                    "{file}: an exercise with a long title that wraps onto a second line of the page"
                ),
                student: "Student number: 2026001".into(),
                data: (
                    "Your data".into(),
                    (0..12)
                        .map(|i| (format!("Frame pivot P{i} (x, y)"), format!("{v}; {v}; {v}")))
                        .collect(),
                ),
                questions: (
                    "Find".into(),
                    (0..14)
                        .map(|i| (format!("{q} {i}"), "rad/s²".to_string()))
                        .collect(),
                ),
                pose: Some((k.mechanism(), &s)),
                cam: None,
            };
            let what = format!("{file}: task sheet ({})", lang.code());
            check(&task_sheet(&task, lang), &what, &mut found, &mut lines);
        }
    }
    assert_clean(&found, &lines);
}
