//! A velocity or acceleration polygon as a figure: from the pole p (p' for
//! accelerations) each joint's absolute vector to its lowercase point (b, c / b',
//! c'), then every dyad's equation laid head to tail — relative vectors whole, their
//! normal, tangential, Coriolis and sliding components each drawn — in m/s or m/s².

use linkage::polygon::{Component, Quantity, Symbol, Term, VectorEquation};
use linkage::{Mechanism, Solution};

use crate::figure::Figure;
pub use crate::figure::{ArrowStyle, Vertex};
use crate::geometry::{Pt, Rect};
use crate::label::Label;

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

/// The pole's name in a polygon of `quantity` whose joints are `joints`: p (p' for
/// accelerations) as the textbooks write it, or π (π') where a joint is named P and
/// its point in the polygon is p (the quick-return shaper's pin: two points named p
/// in one figure), as Artobolevsky's textbooks write the pole.
pub fn pole_name<'a>(quantity: Quantity, mut joints: impl Iterator<Item = &'a str>) -> String {
    let prime = if quantity == Quantity::Acceleration {
        "'"
    } else {
        ""
    };
    let letter = if joints.any(|n| n.eq_ignore_ascii_case("p")) {
        "π"
    } else {
        "p"
    };
    format!("{letter}{prime}")
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
            name: pole_name(quantity, joints.iter().map(|(n, _)| n.as_str())),
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
        Figure::extent(self)
    }

    /// The label of an arrow: its symbol typeset, or for an absolute vector none
    /// (its end point's name labels it).
    pub fn arrow_label(arrow: &Arrow) -> Option<Label> {
        (arrow.style != ArrowStyle::Absolute).then(|| Label::of_symbol(&arrow.symbol))
    }
}

impl Figure for PolygonFigure {
    // The same lines as force_figure.rs's: the two figures' arrows are of two types (a
    // force's label is its own, a polygon term's is made from its symbol), and a
    // shared arrow type for three fields would cost more than these lines.
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
}

/// The style a term's component is drawn in.
fn style_of(symbol: &Symbol) -> ArrowStyle {
    match symbol.component {
        Component::Whole => ArrowStyle::Relative,
        Component::Normal => ArrowStyle::Normal,
        Component::Tangential => ArrowStyle::Tangential,
        Component::Coriolis => ArrowStyle::Coriolis,
        Component::Sliding => ArrowStyle::Sliding,
    }
}

/// The title of a quantity's polygon: "Velocity polygon".
pub fn title(quantity: Quantity) -> &'static str {
    match quantity {
        Quantity::Velocity => "Velocity polygon",
        Quantity::Acceleration => "Acceleration polygon",
    }
}

/// The unit of a quantity.
pub fn unit(quantity: Quantity) -> &'static str {
    match quantity {
        Quantity::Velocity => "m/s",
        Quantity::Acceleration => "m/s²",
    }
}

/// The largest magnitude among `eq`'s terms: a term below its round-off
/// ([`crate::numbers::si_beside`]) is a zero.
pub fn largest_term(eq: &VectorEquation) -> f64 {
    eq.lhs
        .iter()
        .chain(&eq.rhs)
        .map(|t| t.magnitude.abs())
        .fold(0.0, f64::max)
}

/// The largest term of the position's equations of kind `quantity`: the size its
/// tables' values are the round-off of. Not one equation's own largest term: in a
/// dwell every term of the follower's equation is round-off.
pub fn largest_of_kind(equations: &[VectorEquation], quantity: Quantity) -> f64 {
    equations
        .iter()
        .filter(|e| e.kind == quantity)
        .map(largest_term)
        .fold(0.0, f64::max)
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
                style: style_of(&t.symbol),
                symbol: t.symbol.clone(),
            });
        }
        at = next;
    }
}
