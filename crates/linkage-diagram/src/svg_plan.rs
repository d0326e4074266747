//! The plan of positions as a course draws it: every position in thin lines, the
//! start in the links' colour with its joints lettered and its links numbered (the
//! numbers the force tables use), and each position's number at the crank pin and at
//! the output, every label placed clear of the others ([`crate::placement`]).

use std::fmt::Write as _;

use linkage::{LinkId, Mechanism, Solution};

use crate::geometry::{Pt, Rect};
use crate::label::Label;
use crate::layout::{Fit, Sizes};
use crate::placement::{Obstacles, Placed, place_arrow_label, place_vertex_label};
use crate::pose_figure::{PoseFigure, link_number};
use crate::pose_layout::pivot_symbol_box;
use crate::svg_draw::{FONT, TITLE_H, frame, label_at, line, text_at};

const BLUE: &str = "#1e5aaa";
const GREY: &str = "#9a9a9a";
const NUMBER: &str = "#b0306a";

/// Every position's links, the start drawn strong, lettered and numbered.
pub(crate) fn plan(
    out: &mut String,
    m: &Mechanism,
    positions: &[Solution],
    pane: Rect,
    sizes: Sizes,
    title: &str,
) {
    frame(out, &pane);
    text_at(
        out,
        [pane.min[0] + 6.0, pane.min[1] + 15.0],
        title,
        12.0,
        "bold",
    );
    let all: Vec<Vec<Vec<Pt>>> = positions.iter().map(|s| outlines(m, s)).collect();
    let grounds = m.links[m.ground].points.iter().map(|(_, p)| [p.x, p.y]);
    let Some(units) = Rect::around(all.iter().flatten().flatten().copied().chain(grounds)) else {
        return;
    };
    let inner = Rect {
        min: [pane.min[0] + 4.0, pane.min[1] + TITLE_H],
        max: [pane.max[0] - 4.0, pane.max[1] - 4.0],
    };
    let fit = Fit::new(units, inner, sizes);
    let px_all: Vec<Vec<Vec<Pt>>> = all
        .iter()
        .map(|links| {
            links
                .iter()
                .map(|l| l.iter().map(|&p| fit.px(p)).collect())
                .collect()
        })
        .collect();
    for (i, links) in px_all.iter().enumerate().rev() {
        let (colour, width) = if i == 0 { (BLUE, 2.5) } else { (GREY, 0.8) };
        for l in links {
            outline(out, l, colour, width);
        }
    }
    let pivots: Vec<Pt> = m.links[m.ground]
        .points
        .iter()
        .map(|(_, p)| fit.px([p.x, p.y]))
        .collect();
    for &p in &pivots {
        pivot(out, p);
    }
    let start = PoseFigure::new(m, &positions[0], None);
    let joints: Vec<(String, Pt)> = start
        .joints
        .iter()
        .map(|(name, p)| (name.clone(), fit.px(*p)))
        .collect();
    let flat: Vec<Vec<Pt>> = px_all.iter().flatten().cloned().collect();
    let mut obstacles = Obstacles::for_points(
        inner,
        &flat,
        joints.iter().map(|j| &j.1),
        pivots.iter().map(|&p| pivot_symbol_box(p)),
    );
    let middle = fit.px(units.centre());
    for (name, at) in &joints {
        let away = [at[0] - middle[0], at[1] - middle[1]];
        let placed = place_vertex_label(*at, away, size(name), &mut obstacles);
        draw(out, name, &placed, "#000000");
    }
    link_numbers(out, m, &px_all[0], &mut obstacles);
    position_numbers(out, m, positions, &fit, &mut obstacles);
    let bar = fit.scale_bar(units.width().max(units.height()), inner, sizes);
    line(out, bar.from, bar.to, "#000000", 2.0, false);
    text_at(
        out,
        [bar.to[0] + 6.0, bar.to[1] + 4.0],
        &crate::numbers::si(bar.value, "m"),
        FONT,
        "normal",
    );
}

/// Each moving link's outline (its points in order), metres.
fn outlines(m: &Mechanism, s: &Solution) -> Vec<Vec<Pt>> {
    m.moving_links()
        .map(|l| {
            m.links[l]
                .points
                .iter()
                .map(|(_, local)| {
                    let p = s.links[l].point(local).position;
                    [p.x, p.y]
                })
                .collect()
        })
        .collect()
}

/// The start's links by their numbers, beside each link's first side.
fn link_numbers(out: &mut String, m: &Mechanism, start: &[Vec<Pt>], o: &mut Obstacles) {
    for (link, l) in m.moving_links().zip(start) {
        let text = link_number(m, link).to_string();
        let placed = match l[..] {
            [a, b, ..] => place_arrow_label(a, b, size(&text), o),
            [a] => place_vertex_label(a, [1.0, -1.0], size(&text), o),
            [] => continue,
        };
        draw(out, &text, &placed, BLUE);
    }
}

/// Each position's number at the crank pin (away from the crank's pivot) and at the
/// output's point.
fn position_numbers(
    out: &mut String,
    m: &Mechanism,
    positions: &[Solution],
    fit: &Fit,
    o: &mut Obstacles,
) {
    let pivot = ground_point(m, m.driver.link).map(|p| fit.px(p));
    let output_pivot = ground_point(m, m.output).map(|p| fit.px(p));
    for (i, s) in positions.iter().enumerate() {
        let text = i.to_string();
        for (link, centre) in [(m.driver.link, pivot), (m.output, output_pivot)] {
            if i > 0 && link == m.driver.link && m.output == m.driver.link {
                continue;
            }
            let Some(at) = far_point(m, s, link).map(|p| fit.px(p)) else {
                continue;
            };
            let away = centre.map_or([0.0, -1.0], |c| [at[0] - c[0], at[1] - c[1]]);
            let placed = place_vertex_label(at, away, size(&text), o);
            draw(out, &text, &placed, NUMBER);
        }
    }
}

/// Where `link` is pinned to the frame, metres (its pivot's ground point).
fn ground_point(m: &Mechanism, link: LinkId) -> Option<Pt> {
    let rv = m
        .revolutes
        .iter()
        .find(|rv| (rv.a == link && rv.b == m.ground) || (rv.b == link && rv.a == m.ground))?;
    let p = if rv.a == m.ground {
        rv.a_local
    } else {
        rv.b_local
    };
    Some([p.x, p.y])
}

/// The point of `link` farthest from its ground pivot (a crank's pin, a rocker's
/// tip), or its first point where it has no pivot (a slider's pin), metres.
fn far_point(m: &Mechanism, s: &Solution, link: LinkId) -> Option<Pt> {
    let frame = &s.links[link];
    let world = |local| {
        let p = frame.point(local).position;
        [p.x, p.y]
    };
    let points = m.links[link].points.iter().map(|(_, local)| world(local));
    match ground_point(m, link) {
        Some(c) => points.max_by(|a, b| {
            let d = |p: &Pt| (p[0] - c[0]).hypot(p[1] - c[1]);
            d(a).total_cmp(&d(b))
        }),
        None => points.into_iter().next(),
    }
}

/// A small label's box: a joint's letter or a number.
fn size(text: &str) -> [f64; 2] {
    Label::plain(text).approximate_size(FONT)
}

fn draw(out: &mut String, text: &str, placed: &Placed, colour: &str) {
    if let Some([a, b]) = placed.leader {
        line(out, a, b, "#999999", 0.6, false);
    }
    label_at(out, &Label::plain(text), placed.rect.min, colour);
}

fn outline(out: &mut String, l: &[Pt], colour: &str, width: f64) {
    for pair in l.windows(2) {
        line(out, pair[0], pair[1], colour, width, false);
    }
    if l.len() > 2 {
        line(out, l[l.len() - 1], l[0], colour, width, false);
    }
}

fn pivot(out: &mut String, p: Pt) {
    let _ = writeln!(
        out,
        "<polygon points=\"{:.1},{:.1} {:.1},{:.1} {:.1},{:.1}\" fill=\"#cccccc\" stroke=\"#333333\"/>",
        p[0],
        p[1],
        p[0] - 6.0,
        p[1] + 10.0,
        p[0] + 6.0,
        p[1] + 10.0
    );
}
