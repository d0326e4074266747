//! A velocity or acceleration polygon as a figure: from the pole p (p' for
//! accelerations) each joint's absolute vector to its lowercase point (b, c / b',
//! c'), then every dyad's equation laid head to tail — relative vectors whole, their
//! normal, tangential, Coriolis and sliding components each drawn — in m/s or m/s².

use linkage::polygon::{Component, Quantity, Symbol, Term, VectorEquation};
use linkage::{Mechanism, Solution};

use crate::geometry::{Pt, Rect};
use crate::label::Label;
use crate::layout::Figure;

/// How an arrow is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ArrowStyle {
    /// A joint's absolute vector, from the pole.
    Absolute,
    /// A relative vector (`v_CB`).
    Relative,
    /// A normal component.
    Normal,
    /// A tangential component.
    Tangential,
    /// A Coriolis component.
    Coriolis,
    /// A sliding component.
    Sliding,
    /// A force known before its stage is solved (a load, an inertia force, the
    /// reaction of a stage solved before).
    Load,
    /// A reaction the stage solves for.
    Reaction,
    /// A group's inner reaction: the polygon's diagonal.
    Inner,
}

impl ArrowStyle {
    fn of(symbol: &Symbol) -> Self {
        match symbol.component {
            Component::Whole => Self::Relative,
            Component::Normal => Self::Normal,
            Component::Tangential => Self::Tangential,
            Component::Coriolis => Self::Coriolis,
            Component::Sliding => Self::Sliding,
        }
    }

    /// Its colour, sRGB: the same in the app and on the sheet.
    pub fn rgb(self) -> [u8; 3] {
        match self {
            Self::Absolute => [30, 90, 170],
            Self::Relative => [70, 70, 70],
            Self::Normal => [40, 140, 200],
            Self::Tangential => [220, 130, 20],
            Self::Coriolis => [210, 40, 40],
            Self::Sliding => [40, 150, 70],
            Self::Load => [30, 90, 170],
            Self::Reaction => [200, 50, 40],
            Self::Inner => [40, 150, 70],
        }
    }

    /// Whether it is drawn dashed (a component, not a whole vector; a force
    /// polygon's diagonal).
    pub fn dashed(self) -> bool {
        !matches!(
            self,
            Self::Absolute | Self::Relative | Self::Load | Self::Reaction
        )
    }
}

/// One arrow, in the polygon's units.
#[derive(Clone, Debug, PartialEq)]
pub struct Arrow {
    /// Tail.
    pub from: Pt,
    /// Head.
    pub to: Pt,
    /// Style.
    pub style: ArrowStyle,
    /// The term it draws (for an absolute vector `v_B`, which its end point's name
    /// labels in the figure).
    pub symbol: Symbol,
}

/// A named point of the polygon: the pole or the end of an absolute vector.
#[derive(Clone, Debug, PartialEq)]
pub struct Vertex {
    /// Where, in the polygon's units.
    pub at: Pt,
    /// Its name: `p`, `b`, `c'`.
    pub name: String,
}

/// A polygon ready to lay out.
#[derive(Clone, Debug, PartialEq)]
pub struct PolygonFigure {
    /// Velocity or acceleration.
    pub quantity: Quantity,
    /// Arrows: absolute vectors first.
    pub arrows: Vec<Arrow>,
    /// The pole first, then the joints' points.
    pub vertices: Vec<Vertex>,
}

impl PolygonFigure {
    /// The unit of its vectors.
    pub fn unit(&self) -> &'static str {
        unit(self.quantity)
    }

    /// The figure of `quantity` from a position's equations and the joints' absolute
    /// vectors (name, vector); non-finite vectors are left out.
    pub fn new(quantity: Quantity, equations: &[VectorEquation], joints: &[(String, Pt)]) -> Self {
        let prime = if quantity == Quantity::Acceleration {
            "'"
        } else {
            ""
        };
        let finite = |v: &Pt| v[0].is_finite() && v[1].is_finite();
        let joints: Vec<&(String, Pt)> = joints.iter().filter(|(_, v)| finite(v)).collect();
        let mut vertices = vec![Vertex {
            at: [0.0, 0.0],
            name: format!("p{prime}"),
        }];
        let mut arrows = Vec::new();
        for (name, v) in &joints {
            vertices.push(Vertex {
                at: *v,
                name: format!("{}{prime}", name.to_lowercase()),
            });
            arrows.push(Arrow {
                from: [0.0, 0.0],
                to: *v,
                style: ArrowStyle::Absolute,
                symbol: Symbol {
                    quantity,
                    point: name.clone(),
                    relative_to: None,
                    component: Component::Whole,
                },
            });
        }
        for eq in equations.iter().filter(|e| e.kind == quantity) {
            for side in [&eq.rhs, &eq.lhs] {
                chain(side, &joints, &mut arrows);
            }
        }
        Self {
            quantity,
            arrows,
            vertices,
        }
    }

    /// The polygon of `quantity` of `m` at `s`, from the position's equations.
    pub fn of_position(
        quantity: Quantity,
        m: &Mechanism,
        s: &Solution,
        equations: &[VectorEquation],
    ) -> Self {
        let joints: Vec<(String, Pt)> = m
            .joint_points()
            .into_iter()
            .map(|p| {
                let motion = &s.points[p];
                let v = match quantity {
                    Quantity::Velocity => motion.velocity,
                    Quantity::Acceleration => motion.acceleration,
                };
                (m.points[p].name.clone(), [v.x, v.y])
            })
            .collect();
        Self::new(quantity, equations, &joints)
    }

    /// The box of its arrows and vertices, in its units.
    pub fn extent(&self) -> Rect {
        extent_of(
            self.arrows.iter().flat_map(|a| [a.from, a.to]),
            &self.vertices,
        )
    }

    /// The label of an arrow: its symbol typeset, or for an absolute vector none
    /// (its end point's name labels it).
    pub fn arrow_label(arrow: &Arrow) -> Option<Label> {
        (arrow.style != ArrowStyle::Absolute).then(|| Label::of_symbol(&arrow.symbol))
    }
}

impl Figure for PolygonFigure {
    fn arrow_ends(&self) -> Vec<(Pt, Pt, ArrowStyle)> {
        self.arrows
            .iter()
            .map(|a| (a.from, a.to, a.style))
            .collect()
    }

    fn arrow_label(&self, index: usize) -> Option<Label> {
        Self::arrow_label(&self.arrows[index])
    }

    fn vertices(&self) -> &[Vertex] {
        &self.vertices
    }

    fn extent(&self) -> Rect {
        Self::extent(self)
    }
}

/// The box of `ends` and `vertices`; a point at the origin when there are none.
pub(crate) fn extent_of(ends: impl Iterator<Item = Pt>, vertices: &[Vertex]) -> Rect {
    Rect::around(ends.chain(vertices.iter().map(|v| v.at))).unwrap_or(Rect {
        min: [0.0; 2],
        max: [0.0; 2],
    })
}

/// The unit of a quantity.
pub fn unit(quantity: Quantity) -> &'static str {
    match quantity {
        Quantity::Velocity => "m/s",
        Quantity::Acceleration => "m/s²",
    }
}

/// An absolute term (`v_B`, `a_C`: a joint's whole motion relative to the frame) is
/// drawn from the pole with the joints' vectors, not again in a chain.
fn is_absolute(symbol: &Symbol, joints: &[&(String, Pt)]) -> bool {
    symbol.relative_to.is_none()
        && symbol.component == Component::Whole
        && joints.iter().any(|(name, _)| *name == symbol.point)
}

/// Lays `terms` head to tail from the pole; absolute terms are already drawn.
fn chain(terms: &[Term], joints: &[&(String, Pt)], out: &mut Vec<Arrow>) {
    let mut at = [0.0, 0.0];
    for t in terms {
        let next = [at[0] + t.vector[0], at[1] + t.vector[1]];
        if !(next[0].is_finite() && next[1].is_finite()) {
            return;
        }
        if !is_absolute(&t.symbol, joints) && t.magnitude > 0.0 {
            out.push(Arrow {
                from: at,
                to: next,
                style: ArrowStyle::of(&t.symbol),
                symbol: t.symbol.clone(),
            });
        }
        at = next;
    }
}
