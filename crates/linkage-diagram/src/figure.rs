//! What a polygon pane draws, whatever the polygon: arrows in a style, named
//! vertices, and the [`Figure`] interface that [`crate::layout`] lays out — the
//! velocity and acceleration polygons and the force polygons alike.

use crate::geometry::{Pt, Rect};
use crate::label::Label;

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

/// A named point of the polygon: the pole or the end of an absolute vector.
#[derive(Clone, Debug, PartialEq)]
pub struct Vertex {
    /// Where, in the polygon's units.
    pub at: Pt,
    /// Its name: `p`, `b`, `c'`.
    pub name: String,
}

/// What a polygon pane lays out: arrows with styles and labels, and named vertices.
/// The velocity and acceleration polygons ([`crate::PolygonFigure`]) and the force
/// polygons ([`crate::force_figure::ForceFigure`]) are laid out by the same code.
pub trait Figure {
    /// Each arrow's tail, head and style, in the figure's units.
    fn arrow_ends(&self) -> Vec<(Pt, Pt, ArrowStyle)>;
    /// The label of arrow `index`, if it carries one.
    fn arrow_label(&self, index: usize) -> Option<Label>;
    /// The named vertices, the pole (if any) first.
    fn vertices(&self) -> &[Vertex];
    /// The box of its arrows and vertices, in its units (a point at the origin when
    /// it has none).
    fn extent(&self) -> Rect {
        let ends = self
            .arrow_ends()
            .into_iter()
            .flat_map(|(from, to, _)| [from, to]);
        Rect::around(ends.chain(self.vertices().iter().map(|v| v.at))).unwrap_or(Rect {
            min: [0.0; 2],
            max: [0.0; 2],
        })
    }
}
