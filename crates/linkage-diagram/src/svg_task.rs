//! A student's task sheet for an exercise (A4, the language of its words): the
//! exercise's title and the student's number, the mechanism drawn at its start, the
//! student's data, and the questions, each with a line for the answer and its unit.
//! Every word comes worded (by the model's exercise words): the sheet lays out.

pub use crate::svg_cam::CamFigure;
use linkage::{Mechanism, Solution};

use crate::geometry::Rect;
use crate::layout::Sizes;
use crate::pages::{Pages, Sheet, heading, wrap};
use crate::pose_figure::PoseFigure;
use crate::pose_layout::layout_pose;
use crate::svg_draw::{FONT, MARGIN, PAGE_W, fit_text, line, measure, text_at};
use crate::words::Lang;

/// A task sheet's content, worded.
pub struct TaskSheet<'a> {
    /// The exercise's title.
    pub title: String,
    /// The student's line (`Student number: 2026001`).
    pub student: String,
    /// The data's heading and rows (name, value).
    pub data: (String, Vec<(String, String)>),
    /// The questions' heading and rows (question, unit).
    pub questions: (String, Vec<(String, String)>),
    /// The mechanism and its pose to draw (none for a cam).
    pub pose: Option<(&'a Mechanism, &'a Solution)>,
    /// A cam to draw with its follower (none for a mechanism).
    pub cam: Option<CamFigure<'a>>,
}

/// The pose pane's height, px.
const POSE_H: f64 = 330.0;
/// A row's height, px.
const ROW_H: f64 = 19.0;
/// The width between the margins, px.
const WIDTH: f64 = PAGE_W - 2.0 * MARGIN;

/// The task sheet on as many A4 pages as it needs.
pub fn task_sheet(task: &TaskSheet<'_>, lang: Lang) -> Sheet {
    let mut pages = Pages::new(&task.title);
    heading(&mut pages, &task.title, 16.0);
    let top = pages.place(ROW_H + 6.0);
    text_at(
        pages.out(),
        [MARGIN, top + FONT + 2.0],
        &task.student,
        FONT + 1.0,
        "bold",
    );
    if let Some((m, s)) = task.pose {
        let fig = PoseFigure::new(m, s, None);
        let top = pages.place(POSE_H + 10.0);
        let pane = Rect::from_min_size([MARGIN, top], WIDTH, POSE_H);
        let sizes = Sizes {
            font_px: FONT,
            ..Sizes::default()
        };
        crate::svg::pose(&mut pages, &layout_pose(&fig, pane, sizes, &measure), lang);
    }
    if let Some(cam) = &task.cam {
        let top = pages.place(POSE_H + 10.0);
        let pane = Rect::from_min_size([MARGIN, top], WIDTH, POSE_H);
        crate::svg_draw::frame(pages.out(), &pane);
        crate::svg_cam::cam_in_pane(pages.out(), cam, &pane);
    }
    data(&mut pages, &task.data);
    questions(&mut pages, &task.questions);
    pages.finish()
}

/// The data as a table of two columns, the values wrapped to their column.
fn data(pages: &mut Pages, (title, rows): &(String, Vec<(String, String)>)) {
    pages.keep(2.0 * ROW_H + 20.0);
    heading(pages, title, 13.0);
    let name_w = 0.38 * WIDTH;
    for (name, value) in rows {
        let lines = wrap(value, WIDTH - name_w - 10.0, FONT);
        let top = pages.place(ROW_H * lines.len() as f64);
        let name = fit_text(name, name_w - 8.0, FONT);
        text_at(
            pages.out(),
            [MARGIN, top + FONT + 2.0],
            &name,
            FONT,
            "normal",
        );
        for (i, l) in lines.iter().enumerate() {
            let y = top + FONT + 2.0 + ROW_H * i as f64;
            text_at(pages.out(), [MARGIN + name_w, y], l, FONT, "normal");
        }
    }
}

/// The questions, numbered, each with a line to write the answer on and its unit.
fn questions(pages: &mut Pages, (title, rows): &(String, Vec<(String, String)>)) {
    pages.keep(3.0 * ROW_H + 20.0);
    heading(pages, title, 13.0);
    for (i, (question, unit)) in rows.iter().enumerate() {
        let lines = wrap(&format!("{}. {question}", i + 1), WIDTH, FONT);
        let top = pages.place(ROW_H * (lines.len() as f64 + 1.6));
        for (k, l) in lines.iter().enumerate() {
            text_at(
                pages.out(),
                [MARGIN, top + FONT + 2.0 + ROW_H * k as f64],
                l,
                FONT,
                "normal",
            );
        }
        let y = top + ROW_H * (lines.len() as f64 + 1.0);
        let x = MARGIN + 24.0;
        line(pages.out(), [x, y], [x + 200.0, y], "#555555", 0.8, false);
        text_at(pages.out(), [x + 206.0, y - 2.0], unit, FONT, "normal");
    }
}
