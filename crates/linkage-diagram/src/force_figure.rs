//! A force polygon as a figure: one stage of the graphical kinetostatics (an Assur
//! group or the crank) with its forces laid head to tail from the start, the known
//! ones first, the solved reactions closing it, and a group's inner reaction as the
//! diagonal — in newtons, laid out by the same code as the velocity polygons.

use linkage::Mechanism;
use linkage::force_polygon::{CoupleTerm, ForcePolygons, ForceVector, StagePolygon, SymbolParts};

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

/// The numbers of a stage's links as the drawing numbers them: "3, 4", or "2".
pub fn stage_numbers(stage: &StagePolygon, m: &Mechanism) -> String {
    let numbers: Vec<String> = stage
        .links
        .iter()
        .map(|&l| linkage::force_polygon::link_number(m, l).to_string())
        .collect();
    numbers.join(", ")
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
    /// How the stage treats it: known, solved, or its direction known.
    pub status: RowStatus,
    /// A couple, not a force.
    pub couple: bool,
}

/// How a stage treats a force or couple of its table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RowStatus {
    /// Given (a load, or found by an earlier stage).
    Known,
    /// Its line of action known, its magnitude found here.
    DirectionKnown,
    /// Found here, magnitude and direction.
    Solved,
}

impl RowStatus {
    /// The sheet's English words.
    pub fn words(self) -> &'static str {
        match self {
            Self::Known => "known",
            Self::DirectionKnown => "direction known",
            Self::Solved => "solved",
        }
    }
}

/// A couple's sense of turning.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sense {
    /// A zero couple.
    None,
    /// Counter-clockwise (positive).
    CounterClockwise,
    /// Clockwise (negative).
    Clockwise,
}

impl Sense {
    /// The sheet's English words.
    pub fn words(self) -> &'static str {
        match self {
            Self::None => "none",
            Self::CounterClockwise => "counter-clockwise",
            Self::Clockwise => "clockwise",
        }
    }
}

/// A couple row's sense of turning (`None` for a force row; [`Sense::None`] for a
/// couple that is the round-off of `scale`).
pub fn sense(r: &ForceRow, scale: RowScale) -> Option<Sense> {
    let sense = if r.magnitude <= scale.couple_n_m * crate::numbers::ROUND_OFF {
        Sense::None
    } else if r.direction_deg > 0.0 {
        Sense::CounterClockwise
    } else {
        Sense::Clockwise
    };
    r.couple.then_some(sense)
}

fn force_row(f: &ForceVector, m: &Mechanism) -> ForceRow {
    let status = match (f.magnitude_known, f.direction_known) {
        (true, _) => RowStatus::Known,
        (false, true) => RowStatus::DirectionKnown,
        (false, false) => RowStatus::Solved,
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
    let status = if c.known {
        RowStatus::Known
    } else {
        RowStatus::Solved
    };
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

/// The sizes a table's values are the round-off of: its largest force, and its
/// largest force times the mechanism's longest link (or the balancing torque, if
/// larger) for the couples.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RowScale {
    /// N.
    pub force_n: f64,
    /// N·m.
    pub couple_n_m: f64,
}

/// The scale of `fp`'s tables.
pub fn row_scale(m: &Mechanism, fp: &ForcePolygons) -> RowScale {
    let force_n = fp
        .stages
        .iter()
        .flat_map(|s| s.polygon.iter().chain(&s.inner))
        .map(|f| f.force.norm())
        .fold(0.0, f64::max);
    let longest = m
        .links
        .iter()
        .flat_map(|l| {
            l.points
                .iter()
                .flat_map(move |(_, a)| l.points.iter().map(move |(_, b)| (a - b).norm()))
        })
        .fold(0.0, f64::max);
    RowScale {
        force_n,
        couple_n_m: (force_n * longest).max(fp.balancing_torque.abs()),
    }
}

/// A row's magnitude and direction as shown: `12.5 N`, `99.5°` (0° to 360° from
/// +x), a round-off of `scale` as 0; a couple's sense in words.
pub fn row_cells(r: &ForceRow, scale: RowScale) -> (String, String) {
    use crate::numbers::{ROUND_OFF, si, si_beside};
    if let Some(sense) = sense(r, scale) {
        (
            si_beside(r.magnitude, scale.couple_n_m, "N·m"),
            sense.words().into(),
        )
    } else if r.magnitude <= scale.force_n * ROUND_OFF {
        (si(0.0, "N"), String::new())
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
