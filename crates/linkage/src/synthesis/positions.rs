//! Motion generation through three, four or five positions, as one choice: the
//! number of positions picks the method (three: moving pivots given; four: fixed
//! pivots on the centre-point curve near given points; five: two Burmester points).
//! The CLI and the app both design through here.

use thiserror::Error;

use super::burmester::{Crank, burmester_points, four_bar_of, four_positions};
use super::motion::{BodyPose, MotionFourBar, three_positions};
use crate::error::LinkageError;

/// What fixes the four-bar, per number of positions, m.
#[derive(Clone, Debug, PartialEq)]
pub struct PositionsChoice {
    /// Three positions: the moving pivots in the body's frame.
    pub moving: Option<[[f64; 2]; 2]>,
    /// Four positions: points near the fixed pivots.
    pub fixed_near: Option<[[f64; 2]; 2]>,
    /// Five positions: which two Burmester points, from 1.
    pub burmester_pair: [usize; 2],
}

/// A four-bar through the positions, with the Burmester points where five fixed it.
#[derive(Clone, Debug)]
pub struct PositionsDesign {
    /// The four-bar.
    pub four_bar: MotionFourBar,
    /// Five positions: every Burmester point (the design uses two of them).
    pub burmester: Option<Vec<Crank>>,
}

/// Why no four-bar was designed.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum PositionsError {
    /// Not three, four or five positions.
    #[error("{0} positions: three, four or five are needed")]
    Count(usize),
    /// Three positions without moving pivots.
    #[error("three positions need the moving pivots in the body's frame")]
    NoMovingPivots,
    /// Four positions without points near the fixed pivots.
    #[error("four positions need points near the fixed pivots")]
    NoFixedNear,
    /// A Burmester point asked for that does not exist.
    #[error("Burmester point {asked}: there are {count} (1 to {count})")]
    NoSuchBurmesterPoint {
        /// The point asked for, from 1.
        asked: usize,
        /// How many there are.
        count: usize,
    },
    /// The method's own refusal.
    #[error(transparent)]
    Method(#[from] LinkageError),
}

/// The four-bar that carries a body through `poses` as `choice` says.
///
/// # Errors
/// A count other than three to five, a choice missing or out of range, or why no
/// four-bar meets the positions so.
pub fn through_positions(
    poses: &[BodyPose],
    choice: &PositionsChoice,
) -> Result<PositionsDesign, PositionsError> {
    let four_bar = match poses.len() {
        3 => {
            let moving = choice.moving.ok_or(PositionsError::NoMovingPivots)?;
            three_positions([poses[0], poses[1], poses[2]], moving)?
        }
        4 => four_positions(poses, choice.fixed_near.ok_or(PositionsError::NoFixedNear)?)?,
        5 => {
            let points = burmester_points(poses)?;
            let pick = |asked: usize| {
                points.get(asked.wrapping_sub(1)).copied().ok_or(
                    PositionsError::NoSuchBurmesterPoint {
                        asked,
                        count: points.len(),
                    },
                )
            };
            let [a, b] = choice.burmester_pair;
            let four_bar = four_bar_of(poses, [pick(a)?, pick(b)?])?;
            return Ok(PositionsDesign {
                four_bar,
                burmester: Some(points),
            });
        }
        n => return Err(PositionsError::Count(n)),
    };
    Ok(PositionsDesign {
        four_bar,
        burmester: None,
    })
}
