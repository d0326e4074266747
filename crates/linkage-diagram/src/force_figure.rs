//! A force polygon as a figure: one stage of the graphical kinetostatics (an Assur
//! group or the crank) with its forces laid head to tail from the start, the known
//! ones first, the solved reactions closing it, and a group's inner reaction as the
//! diagonal — in newtons, laid out by the same code as the velocity polygons.

use linkage::Mechanism;
use linkage::dyad::{DyadKind, DyadLabel};
use linkage::force_polygon::{CoupleTerm, ForceVector, Stage, StagePolygon, SymbolParts};

use crate::figure::{ArrowStyle, Figure, Vertex};
use crate::geometry::Pt;
use crate::label::{Label, Run, Script};

/// The unit of a force polygon.
pub const FORCE_UNIT: &str = "N";

/// One arrow of a force polygon, in newtons.
#[derive(Clone, Debug, PartialEq)]
pub struct ForceArrow {
    /// Tail.
    pub from: Pt,
    /// Head.
    pub to: Pt,
    /// Known force, solved reaction or the diagonal.
    pub style: ArrowStyle,
    /// Its symbol typeset (`R` with subscript `23`).
    pub label: Label,
}

/// A stage's force polygon ready to lay out.
#[derive(Clone, Debug, PartialEq)]
pub struct ForceFigure {
    /// The arrows head to tail, then the diagonal.
    pub arrows: Vec<ForceArrow>,
    /// The polygon's start, named o.
    pub vertices: Vec<Vertex>,
}

/// A symbol's letter and subscript as a label.
pub fn parts_label(parts: &SymbolParts) -> Label {
    Label {
        runs: vec![
            Run {
                text: parts.letter.to_string(),
                script: Script::Base,
            },
            Run {
                text: parts.subscript.clone(),
                script: Script::Sub,
            },
        ],
    }
}

fn finite(v: &Pt) -> bool {
    v[0].is_finite() && v[1].is_finite()
}

impl ForceFigure {
    /// The figure of `stage` of `m`; non-finite and zero forces are left out.
    pub fn new(stage: &StagePolygon, m: &Mechanism) -> Self {
        let mut arrows = Vec::new();
        let mut at: Pt = [0.0, 0.0];
        for f in &stage.polygon {
            let next = [at[0] + f.force.x, at[1] + f.force.y];
            if !finite(&next) {
                break;
            }
            if f.force.norm() > 0.0 {
                let style = if f.magnitude_known {
                    ArrowStyle::Load
                } else {
                    ArrowStyle::Reaction
                };
                arrows.push(ForceArrow {
                    from: at,
                    to: next,
                    style,
                    label: parts_label(&f.symbol.parts(m)),
                });
            }
            at = next;
        }
        if let Some(inner) = &stage.inner {
            let to = [inner.force.x, inner.force.y];
            if finite(&to) && inner.force.norm() > 0.0 {
                arrows.push(ForceArrow {
                    from: [0.0, 0.0],
                    to,
                    style: ArrowStyle::Inner,
                    label: parts_label(&inner.symbol.parts(m)),
                });
            }
        }
        let vertices = vec![Vertex {
            at: [0.0, 0.0],
            name: "o".into(),
        }];
        Self { arrows, vertices }
    }
}

impl Figure for ForceFigure {
    // The same lines as polygon_figure.rs's: the two figures' arrows are of two types (a
    // force's label is its own, a polygon term's is made from its symbol), and a
    // shared arrow type for three fields would cost more than these lines.
    fn arrow_ends(&self) -> Vec<(Pt, Pt, ArrowStyle)> {
        self.arrows
            .iter()
            .map(|a| (a.from, a.to, a.style))
            .collect()
    }

    fn arrow_label(&self, index: usize) -> Option<Label> {
        Some(self.arrows[index].label.clone())
    }

    fn vertices(&self) -> &[Vertex] {
        &self.vertices
    }
}

/// The stage's title in the words of the drawing: "coupler and rocker, joined at C
/// (links 3, 4)", "crank (link 2)"; the group's kind (RRR, RRP) is the solver's.
pub fn stage_title(stage: &StagePolygon, m: &Mechanism) -> String {
    let numbers = stage_numbers(stage, m);
    match &stage.stage {
        Stage::Group { dyad, .. } => {
            let noun = if dyad.kind == DyadKind::CamFollower {
                "link"
            } else {
                "links"
            };
            format!("{} ({noun} {numbers})", dyad_words(dyad))
        }
        Stage::Crank { link } => format!("{} (link {numbers})", m.links[*link].name),
    }
}

/// The numbers of a stage's links as the drawing numbers them: "3, 4", or "2".
pub fn stage_numbers(stage: &StagePolygon, m: &Mechanism) -> String {
    let numbers: Vec<String> = stage
        .links
        .iter()
        .map(|&l| linkage::force_polygon::link_number(m, l).to_string())
        .collect();
    numbers.join(", ")
}

/// A dyad by its links and joint, as the user knows it: "coupler and rocker, joined
/// at C", or a cam's follower "follower, on the cam at F"; never the solver's kind.
pub fn dyad_words(dyad: &DyadLabel) -> String {
    let [a, b] = &dyad.links;
    if dyad.kind == DyadKind::CamFollower {
        format!("{a}, on the cam at {}", dyad.inner_point)
    } else {
        format!("{a} and {b}, joined at {}", dyad.inner_point)
    }
}

/// One row of a stage's force table.
#[derive(Clone, Debug, PartialEq)]
pub struct ForceRow {
    /// The symbol typeset.
    pub label: Label,
    /// |F|, N (or |M|, N·m, for a couple).
    pub magnitude: f64,
    /// Its direction, degrees from +x (a couple: its sign, +1 counter-clockwise).
    pub direction_deg: f64,
    /// "known", "solved", "direction known" — how the stage treats it.
    pub status: &'static str,
    /// A couple, not a force.
    pub couple: bool,
}

fn force_row(f: &ForceVector, m: &Mechanism) -> ForceRow {
    let status = match (f.magnitude_known, f.direction_known) {
        (true, _) => "known",
        (false, true) => "direction known",
        (false, false) => "solved",
    };
    ForceRow {
        label: parts_label(&f.symbol.parts(m)),
        magnitude: f.force.norm(),
        direction_deg: f.force.y.atan2(f.force.x).to_degrees(),
        status,
        couple: false,
    }
}

fn couple_row(c: &CoupleTerm, m: &Mechanism) -> ForceRow {
    let status = if c.known { "known" } else { "solved" };
    ForceRow {
        label: parts_label(&c.symbol.parts(m)),
        magnitude: c.moment.abs(),
        direction_deg: c.moment.signum(),
        status,
        couple: true,
    }
}

/// The rows of a stage's table: the polygon's forces in order, the diagonal, then
/// the couples.
pub fn force_rows(stage: &StagePolygon, m: &Mechanism) -> Vec<ForceRow> {
    stage
        .polygon
        .iter()
        .chain(stage.inner.iter())
        .map(|f| force_row(f, m))
        .chain(stage.couples.iter().map(|c| couple_row(c, m)))
        .collect()
}

/// A row's magnitude and direction as shown: `12.5000 N`, `99.50°` (0° to 360°
/// from +x); a couple's sense in words.
pub fn row_cells(r: &ForceRow) -> (String, String) {
    if r.couple {
        let sense = if r.magnitude == 0.0 {
            "none"
        } else if r.direction_deg > 0.0 {
            "counter-clockwise"
        } else {
            "clockwise"
        };
        (crate::numbers::si(r.magnitude, "N·m"), sense.to_string())
    } else {
        // Rounded first, so that −0.01° reads 0°, not 360°.
        let deg = (r.direction_deg * 10.0).round() / 10.0;
        (
            crate::numbers::si(r.magnitude, "N"),
            crate::numbers::degrees(deg.rem_euclid(360.0) + 0.0),
        )
    }
}

/// The stage's vector equation typeset: `R_23 + P_S + R_14 = 0`, its polygon's
/// forces in order.
pub fn stage_equation(stage: &StagePolygon, m: &Mechanism) -> Label {
    let mut runs = Vec::new();
    for (i, f) in stage.polygon.iter().enumerate() {
        if i > 0 {
            runs.push(Run {
                text: " + ".into(),
                script: Script::Base,
            });
        }
        runs.extend(parts_label(&f.symbol.parts(m)).runs);
    }
    runs.push(Run {
        text: " = 0".into(),
        script: Script::Base,
    });
    Label { runs }
}
