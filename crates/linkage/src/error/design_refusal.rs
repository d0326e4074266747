//! Why a closed-form synthesis gives no linkage, as data
//! ([`crate::LinkageError::NoDesign`]): which pivot, which coefficients.

use thiserror::Error;

/// The requirements are met by no four-bar, or by one that is no mechanism.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum DesignRefusal {
    /// Motion generation: the two moving pivots chosen coincide.
    #[error("the two moving pivots are at one place")]
    MovingPivotsCoincide,
    /// Motion generation: a moving pivot's three places are in a line.
    #[error(
        "moving pivot {number} ({:.6}, {:.6}) passes its three places in a line: its centre point is at infinity",
        at[0],
        at[1]
    )]
    CentreAtInfinity {
        /// Which pivot, from 1.
        number: usize,
        /// Where it is on the body, m.
        at: [f64; 2],
    },
    /// Motion generation: a moving pivot that stays put is the pole.
    #[error("moving pivot {number} stays at one place: it is the pole, not a crank")]
    MovingPivotIsPole {
        /// Which pivot, from 1.
        number: usize,
    },
    /// Burmester: the two cranks chosen share a moving pivot.
    #[error("the two cranks share a moving pivot")]
    CranksShareMovingPivot,
    /// Burmester: no centre-point curve near the fixed pivot asked for.
    #[error(
        "no point of the centre-point curve found near fixed pivot {number} ({:.6}, {:.6})",
        near[0],
        near[1]
    )]
    NoCentrePointNear {
        /// Which pivot, from 1.
        number: usize,
        /// Where it was asked for, m.
        near: [f64; 2],
    },
    /// Burmester: the fixed pivot is a pole, with no circle point.
    #[error("fixed pivot {number} is at a pole: no crank")]
    FixedPivotIsPole {
        /// Which pivot, from 1.
        number: usize,
    },
    /// Function generation: Freudenstein's K1 or K2 vanishes.
    #[error("K1 = {k1:.6e}, K2 = {k2:.6e}: the crank or rocker would be infinitely long")]
    InfiniteLink {
        /// Freudenstein's K1.
        k1: f64,
        /// Freudenstein's K2.
        k2: f64,
    },
    /// Function generation: the coupler's length squared is not positive.
    #[error(
        "K1 = {:.6}, K2 = {:.6}, K3 = {:.6} give a coupler length squared of {coupler_squared:.6e}: no four-bar meets these points",
        k[0],
        k[1],
        k[2]
    )]
    NoCoupler {
        /// Freudenstein's K1, K2, K3.
        k: [f64; 3],
        /// The coupler's length squared that came out, m².
        coupler_squared: f64,
    },
    /// A designed drawing lacks a part the check needs (the coupler, its point P).
    #[error("the {part} is missing")]
    PartMissing {
        /// The part, in words.
        part: &'static str,
    },
    /// The designed drawing is not a whole mechanism (a design's drawing always has
    /// its links, driver and ground pivots, so this names a fault in the design).
    #[error(
        "the designed drawing is not a mechanism: a link, the driver or its ground pivot is missing, or the count of joints is wrong"
    )]
    DrawingIncomplete,
}
