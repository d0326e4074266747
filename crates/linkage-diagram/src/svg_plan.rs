//! The plan of positions as a course draws it: every position in thin lines, the
//! start in the links' colour with its joints lettered and its links numbered (the
//! numbers the force tables use), and each position's number at the crank pin and at
//! the output, every label placed clear of the others ([`crate::placement`]).

use std::fmt::Write as _;

use linkage::{LinkId, Mechanism, Solution};

use crate::geometry::{Pt, Rect, distance};
use crate::label::Label;
use crate::layout::{Fit, Sizes};
use crate::placement::{Anchor, Obstacles, Placed, place_all};
use crate::pose_figure::{PoseFigure, link_number};
use crate::pose_layout::pivot_symbol_box;
use crate::svg_draw::{FONT, TITLE_H, frame, label_at, line, text_at};

const BLUE: &str = "#1e5aaa";
const GREY: &str = "#9a9a9a";
const NUMBER: &str = "#b0306a";
const JOINT: &str = "#000000";

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
    let flat: Vec<Vec<Pt>> = px_all.iter().flatten().cloned().collect();
    let mut labels = joint_letters(m, &positions[0], &fit, fit.px(units.centre()));
    // The joints' dots, which no label may cover.
    let dots: Vec<Pt> = labels.iter().filter_map(PlanLabel::point).collect();
    labels.extend(link_numbers(m, &px_all[0]));
    labels.extend(position_numbers(m, positions, &fit));
    let obstacles = Obstacles::for_points(
        inner,
        &flat,
        dots.iter(),
        pivots.iter().map(|&p| pivot_symbol_box(p)),
    );
    let anchors: Vec<(Anchor, [f64; 2])> =
        labels.iter().map(|l| (l.anchor, size(&l.text))).collect();
    for (label, placed) in labels.iter().zip(place_all(&obstacles, &anchors)) {
        draw(out, &label.text, &placed, label.colour);
    }
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

/// A label of the plan: its text, colour and where it goes.
struct PlanLabel {
    text: String,
    colour: &'static str,
    anchor: Anchor,
}

impl PlanLabel {
    /// The point it names, if it names one.
    fn point(&self) -> Option<Pt> {
        match self.anchor {
            Anchor::Vertex { at, .. } => Some(at),
            Anchor::Arrow { .. } => None,
        }
    }
}

/// The start's joints by their letters, away from the figure's `middle` (pixels).
fn joint_letters(m: &Mechanism, start: &Solution, fit: &Fit, middle: Pt) -> Vec<PlanLabel> {
    PoseFigure::new(m, start, None)
        .joints
        .iter()
        .map(|(name, p)| {
            let at = fit.px(*p);
            PlanLabel {
                text: name.clone(),
                colour: JOINT,
                anchor: Anchor::Vertex {
                    at,
                    away: [at[0] - middle[0], at[1] - middle[1]],
                },
            }
        })
        .collect()
}

/// The start's links by their numbers, beside each link's first side.
fn link_numbers(m: &Mechanism, start: &[Vec<Pt>]) -> Vec<PlanLabel> {
    m.moving_links()
        .zip(start)
        .filter_map(|(link, l)| {
            let anchor = match l[..] {
                [from, to, ..] => Anchor::Arrow { from, to },
                [at] => Anchor::Vertex {
                    at,
                    away: [1.0, -1.0],
                },
                [] => return None,
            };
            Some(PlanLabel {
                text: link_number(m, link).to_string(),
                colour: BLUE,
                anchor,
            })
        })
        .collect()
}

/// Each position's number at the crank pin (away from the crank's pivot) and at the
/// output's point; positions whose points fall within [`SAME_SPOT_PX`] of each other
/// share one label ("0–3, 11"), as a slider with a short stroke on a large drawing
/// puts all its positions on a few pixels.
fn position_numbers(m: &Mechanism, positions: &[Solution], fit: &Fit) -> Vec<PlanLabel> {
    let mut labels = Vec::new();
    for link in [m.driver.link, m.output] {
        if link == m.output && m.output == m.driver.link {
            continue;
        }
        let centre = ground_point(m, link).map(|p| fit.px(p));
        let points: Vec<(usize, Pt)> = positions
            .iter()
            .enumerate()
            .filter_map(|(i, s)| Some((i, fit.px(far_point(m, s, link)?))))
            .collect();
        for (numbers, at) in same_spots(&points) {
            let away = centre.map_or([0.0, -1.0], |c| [at[0] - c[0], at[1] - c[1]]);
            labels.push(PlanLabel {
                text: number_list(&numbers),
                colour: NUMBER,
                anchor: Anchor::Vertex { at, away },
            });
        }
    }
    labels
}

/// Points closer than this share one label, pixels: about a number's height.
const SAME_SPOT_PX: f64 = 10.0;

/// The positions grouped by spot: each group's numbers and its first point, every
/// point within [`SAME_SPOT_PX`] of its group's first.
fn same_spots(points: &[(usize, Pt)]) -> Vec<(Vec<usize>, Pt)> {
    let mut groups: Vec<(Vec<usize>, Pt)> = Vec::new();
    for &(i, p) in points {
        let near = |g: &&mut (Vec<usize>, Pt)| distance(g.1, p) < SAME_SPOT_PX;
        match groups.iter_mut().find(|g| near(g)) {
            Some(g) => g.0.push(i),
            None => groups.push((vec![i], p)),
        }
    }
    groups
}

/// Numbers in rising order as a short list, three or more in a row as a range:
/// [0, 1, 2, 3, 11] reads "0–3, 11".
fn number_list(numbers: &[usize]) -> String {
    let mut runs: Vec<(usize, usize)> = Vec::new();
    for &n in numbers {
        match runs.last_mut() {
            Some((_, last)) if *last + 1 == n => *last = n,
            _ => runs.push((n, n)),
        }
    }
    let run = |&(a, b): &(usize, usize)| match b - a {
        0 => a.to_string(),
        1 => format!("{a}, {b}"),
        _ => format!("{a}–{b}"),
    };
    runs.iter().map(run).collect::<Vec<_>>().join(", ")
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_in_a_row_read_as_a_range() {
        assert_eq!(number_list(&[0, 1, 2, 3, 11]), "0–3, 11");
        assert_eq!(number_list(&[4, 5, 9]), "4, 5, 9");
        assert_eq!(number_list(&[7]), "7");
    }

    #[test]
    fn positions_on_one_spot_share_a_label() {
        let points = [
            (0, [0.0, 0.0]),
            (1, [30.0, 0.0]),
            (2, [3.0, 4.0]),
            (3, [31.0, 2.0]),
            (4, [60.0, 0.0]),
        ];
        let groups: Vec<Vec<usize>> = same_spots(&points).into_iter().map(|g| g.0).collect();
        assert_eq!(groups, [vec![0, 2], vec![1, 3], vec![4]]);
    }
}
