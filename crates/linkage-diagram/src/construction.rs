//! The graphical construction of one vector equation, step by step as the textbook
//! draws it: the known terms of each side head to tail from the pole, then through
//! each side's end the line of its unknown term's known direction, then the point
//! where the two lines cross, which fixes both unknown magnitudes.
//!
//! It is built from the equation's terms alone (which are known, their directions
//! and the known vectors), so its crossing point is a second, geometric solution of
//! the equation; the tests hold it to the solver's.

use linkage::polygon::{Term, VectorEquation};

use crate::geometry::Pt;
use crate::label::{Label, Run, Script};
use crate::numbers::si;
use crate::polygon_figure::{Arrow, ArrowStyle, PolygonFigure, Vertex};

/// A line of known direction through a known point, for an unknown term.
#[derive(Clone, Debug, PartialEq)]
pub struct DirectionLine {
    /// A point it passes through (the end of its side's known terms).
    pub through: Pt,
    /// Its unit direction.
    pub direction: Pt,
    /// The unknown term it carries.
    pub label: Label,
}

/// One step: what is drawn so far and what the step fixes.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// Arrows and named points drawn so far.
    pub figure: PolygonFigure,
    /// Direction lines drawn so far.
    pub lines: Vec<DirectionLine>,
    /// What this step does, in words with typeset symbols.
    pub says: Label,
}

/// Why an equation has no two-line construction.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NoConstruction {
    /// It does not have exactly two unknown magnitudes of known direction.
    NotTwoUnknownMagnitudes,
    /// The two direction lines are parallel: a dead point of the group.
    ParallelLines,
    /// An unknown term is zero here, so its line has no direction to draw.
    ZeroUnknown(String),
}

impl std::fmt::Display for NoConstruction {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::NotTwoUnknownMagnitudes => {
                write!(
                    f,
                    "no two-line construction: the equation does not have two unknown magnitudes of known direction"
                )
            }
            Self::ParallelLines => write!(
                f,
                "the two direction lines are parallel: a dead point, where the construction has no crossing"
            ),
            Self::ZeroUnknown(s) => {
                write!(f, "{s} is zero here: its line has no direction to draw")
            }
        }
    }
}

/// The construction of `eq` (named points: the pole `pole`, the crossing `crossing`).
pub fn construct(
    eq: &VectorEquation,
    pole: &str,
    crossing: &str,
) -> Result<Vec<Step>, NoConstruction> {
    let unknown = |t: &Term| !(t.magnitude_known && t.direction_known);
    let lhs_unknown: Vec<&Term> = eq.lhs.iter().filter(|t| unknown(t)).collect();
    let rhs_unknown: Vec<&Term> = eq.rhs.iter().filter(|t| unknown(t)).collect();
    let all: Vec<&Term> = lhs_unknown.iter().chain(&rhs_unknown).copied().collect();
    if all.len() != 2 || all.iter().any(|t| !t.direction_known) {
        return Err(NoConstruction::NotTwoUnknownMagnitudes);
    }
    let scale = eq.largest_term();
    for t in &all {
        if t.magnitude <= 1e-12 * scale.max(f64::MIN_POSITIVE) {
            return Err(NoConstruction::ZeroUnknown(t.symbol.to_string()));
        }
    }
    // Both unknowns on one side: the other side's known sum is where they must reach.
    let (first, second) = (all[0], all[1]);
    let mut steps = Vec::new();
    let mut arrows = Vec::new();
    let pole_vertex = Vertex {
        at: [0.0, 0.0],
        name: pole.to_string(),
    };
    let figure = |arrows: &[Arrow], extra: Option<Vertex>| PolygonFigure {
        quantity: eq.kind,
        arrows: arrows.to_vec(),
        vertices: std::iter::once(pole_vertex.clone()).chain(extra).collect(),
    };
    let rhs_end = chain_known(&eq.rhs, &mut arrows);
    steps.push(Step {
        figure: figure(&arrows, None),
        lines: vec![],
        says: words(&[
            Piece::Text(format!(
                "right side: the known terms head to tail from {pole}: "
            )),
            Piece::Terms(known_terms(&eq.rhs)),
        ]),
    });
    let lhs_end = chain_known(&eq.lhs, &mut arrows);
    if eq.lhs.iter().any(|t| !unknown(t)) {
        steps.push(Step {
            figure: figure(&arrows, None),
            lines: vec![],
            says: words(&[
                Piece::Text(format!("left side: its known terms from {pole} too: ")),
                Piece::Terms(known_terms(&eq.lhs)),
            ]),
        });
    }
    // Each unknown's line passes through the end of its own side's known terms; when
    // both unknowns sit on one side, the second's passes through the other side's
    // end instead (that sum is where the two must reach).
    let on_rhs = |t: &Term| eq.rhs.iter().any(|r| std::ptr::eq(r, t));
    let end_of = |rhs: bool| if rhs { rhs_end } else { lhs_end };
    let p1 = end_of(on_rhs(first));
    let p2 = if on_rhs(first) == on_rhs(second) {
        end_of(!on_rhs(first))
    } else {
        end_of(on_rhs(second))
    };
    let line = |t: &Term, through: Pt| DirectionLine {
        through,
        direction: unit(t.vector),
        label: Label::of_symbol(&t.symbol),
    };
    let lines = vec![line(first, p1), line(second, p2)];
    steps.push(Step {
        figure: figure(&arrows, None),
        lines: lines.clone(),
        says: words(&[
            Piece::Text("unknown magnitudes: the line of ".into()),
            Piece::Terms(vec![first]),
            Piece::Text(format!(" ({}) and the line of ", first.direction)),
            Piece::Terms(vec![second]),
            Piece::Text(format!(" ({})", second.direction)),
        ]),
    });
    let x = crossing_point(&lines[0], &lines[1]).ok_or(NoConstruction::ParallelLines)?;
    let unit = crate::polygon_figure::unit(eq.kind);
    for (t, from) in [(first, p1), (second, p2)] {
        // Each unknown runs from its line's point to the crossing, or back from it.
        let toward = [x[0] - from[0], x[1] - from[1]];
        let along = toward[0] * t.vector[0] + toward[1] * t.vector[1] >= 0.0;
        let (a, b) = if along { (from, x) } else { (x, from) };
        arrows.push(Arrow {
            from: a,
            to: b,
            style: style_of(t),
            symbol: t.symbol.clone(),
        });
    }
    let named = Vertex {
        at: x,
        name: crossing.to_string(),
    };
    steps.push(Step {
        figure: figure(&arrows, Some(named)),
        lines,
        says: words(&[
            Piece::Text(format!("the lines cross at {crossing}: |")),
            Piece::Terms(vec![first]),
            Piece::Text(format!("| = {}, |", si(distance_between(p1, x), unit))),
            Piece::Terms(vec![second]),
            Piece::Text(format!("| = {}", si(distance_between(p2, x), unit))),
        ]),
    });
    Ok(steps)
}

fn style_of(t: &Term) -> ArrowStyle {
    use linkage::polygon::Component;
    match t.symbol.component {
        Component::Whole if t.symbol.relative_to.is_none() => ArrowStyle::Absolute,
        Component::Whole => ArrowStyle::Relative,
        Component::Normal => ArrowStyle::Normal,
        Component::Tangential => ArrowStyle::Tangential,
        Component::Coriolis => ArrowStyle::Coriolis,
        Component::Sliding => ArrowStyle::Sliding,
    }
}

/// Lays the known terms of `side` head to tail from the pole; returns the end.
fn chain_known(side: &[Term], arrows: &mut Vec<Arrow>) -> Pt {
    let mut at = [0.0, 0.0];
    for t in side
        .iter()
        .filter(|t| t.magnitude_known && t.direction_known)
    {
        let next = [at[0] + t.vector[0], at[1] + t.vector[1]];
        if t.magnitude > 0.0 {
            arrows.push(Arrow {
                from: at,
                to: next,
                style: style_of(t),
                symbol: t.symbol.clone(),
            });
        }
        at = next;
    }
    at
}

/// A piece of a step's words.
enum Piece<'a> {
    Text(String),
    /// Terms joined by " + " (none: "none").
    Terms(Vec<&'a Term>),
}

fn words(pieces: &[Piece<'_>]) -> Label {
    let mut runs = Vec::new();
    let text = |t: &str| Run {
        text: t.to_string(),
        script: Script::Base,
    };
    for p in pieces {
        match p {
            Piece::Text(t) => runs.push(text(t)),
            Piece::Terms(terms) if terms.is_empty() => runs.push(text("none")),
            Piece::Terms(terms) => {
                for (i, t) in terms.iter().enumerate() {
                    if i > 0 {
                        runs.push(text(" + "));
                    }
                    runs.extend(Label::of_symbol(&t.symbol).runs);
                }
            }
        }
    }
    Label { runs }
}

fn known_terms(side: &[Term]) -> Vec<&Term> {
    side.iter()
        .filter(|t| t.magnitude_known && t.direction_known)
        .collect()
}

fn unit(v: Pt) -> Pt {
    let n = v[0].hypot(v[1]);
    [v[0] / n, v[1] / n]
}

fn distance_between(a: Pt, b: Pt) -> f64 {
    (b[0] - a[0]).hypot(b[1] - a[1])
}

/// Where two lines cross; none if they are parallel (to 1e-9 rad).
pub fn crossing_point(a: &DirectionLine, b: &DirectionLine) -> Option<Pt> {
    let (d1, d2) = (a.direction, b.direction);
    let det = d1[0] * (-d2[1]) - d1[1] * (-d2[0]);
    if det.abs() < 1e-9 {
        return None;
    }
    let r = [b.through[0] - a.through[0], b.through[1] - a.through[1]];
    let s = (r[0] * (-d2[1]) - r[1] * (-d2[0])) / det;
    Some([a.through[0] + s * d1[0], a.through[1] + s * d1[1]])
}
