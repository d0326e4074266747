//! The names of the forces and couples of a force polygon, as data: which link, which
//! element, which joint. Text is made where it is shown; [`ForceSymbol::parts`] gives
//! the letter and subscript in the textbook's numbering (the frame is 1, the moving
//! links 2, 3, … in the scene's order).

use serde::Serialize;

use crate::dynamics::LoadSource;
use crate::ids::{LinkId, PointId};
use crate::model::Mechanism;

/// A force of a polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ForceSymbol {
    /// The d'Alembert inertia force −m a_G of a link: `F_i3`.
    Inertia {
        /// The link.
        link: LinkId,
    },
    /// An applied load: a weight `G_3`, a spring `F_s3`, a damper `F_d3`, an external
    /// force `P_E` (named by its point).
    Load {
        /// The link it acts on.
        link: LinkId,
        /// Its element.
        source: LoadSource,
    },
    /// The reaction on `on` from `from` in their joint at `point`: `R_23` is the force
    /// of link 2 on link 3.
    Reaction {
        /// The link that pushes.
        from: LinkId,
        /// The link pushed.
        on: LinkId,
        /// The joint's point.
        point: PointId,
    },
}

/// A couple of a force polygon's stage (couples are not drawn in the polygon; they
/// enter the moment equations and its table).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CoupleSymbol {
    /// The inertia couple −I α of a link: `M_i3`.
    Inertia {
        /// The link.
        link: LinkId,
    },
    /// A torque element or a rotational damper on a link: `M_3`.
    Load {
        /// The link.
        link: LinkId,
        /// Its element.
        source: LoadSource,
    },
    /// The couple a guide puts on its slider (or back): `M_34`.
    Guide {
        /// The link that pushes.
        from: LinkId,
        /// The link pushed.
        on: LinkId,
    },
    /// The balancing (driving) torque on the crank: `M_b`.
    Balancing,
}

/// The letter and subscript of a symbol: `("R", "23")`.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct SymbolParts {
    /// The letter.
    pub letter: &'static str,
    /// The subscript.
    pub subscript: String,
}

impl SymbolParts {
    fn new(letter: &'static str, subscript: String) -> Self {
        Self { letter, subscript }
    }

    /// ASCII text: `R_23`.
    pub fn text(&self) -> String {
        format!("{}_{}", self.letter, self.subscript)
    }
}

/// A link's number in the textbook's way: the frame is 1, the moving links 2, 3, …
/// in the scene's order.
pub fn link_number(m: &Mechanism, link: LinkId) -> usize {
    if link == m.ground {
        return 1;
    }
    2 + m.link_ids().filter(|&l| l < link && l != m.ground).count()
}

impl ForceSymbol {
    /// Its letter and subscript for `m`.
    pub fn parts(&self, m: &Mechanism) -> SymbolParts {
        let n = |l: LinkId| link_number(m, l);
        match *self {
            Self::Inertia { link } => SymbolParts::new("F", format!("i{}", n(link))),
            Self::Load { link, source } => match source {
                LoadSource::Weight => SymbolParts::new("G", n(link).to_string()),
                LoadSource::Spring(_) => SymbolParts::new("F", format!("s{}", n(link))),
                LoadSource::Damper(_) => SymbolParts::new("F", format!("d{}", n(link))),
                LoadSource::PointForce { point, .. } => {
                    SymbolParts::new("P", m.points[point].name.clone())
                }
                LoadSource::Torque(_) => SymbolParts::new("M", n(link).to_string()),
            },
            Self::Reaction { from, on, .. } => {
                SymbolParts::new("R", format!("{}{}", n(from), n(on)))
            }
        }
    }
}

impl CoupleSymbol {
    /// Its letter and subscript for `m`.
    pub fn parts(&self, m: &Mechanism) -> SymbolParts {
        let n = |l: LinkId| link_number(m, l);
        match *self {
            Self::Inertia { link } => SymbolParts::new("M", format!("i{}", n(link))),
            Self::Load { link, .. } => SymbolParts::new("M", n(link).to_string()),
            Self::Guide { from, on } => SymbolParts::new("M", format!("{}{}", n(from), n(on))),
            Self::Balancing => SymbolParts::new("M", "b".to_string()),
        }
    }
}
