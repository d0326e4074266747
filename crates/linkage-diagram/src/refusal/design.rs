//! Why a synthesis gives no linkage (which pivot, which coefficients), why its
//! typed inputs were not read, and why a polygon's equation has no construction.

use linkage::DesignRefusal;
use linkage::synthesis::positions::PositionsError;
use linkage::synthesis::rows::RowError;

use crate::construction::NoConstruction;

use crate::numbers::significant;
use crate::words::{Lang, sw};

/// A point's coordinates, to six significant digits.
fn place(at: &[f64; 2]) -> String {
    format!("({}, {})", significant(at[0], 6), significant(at[1], 6))
}

/// Why the requirements give no linkage.
pub fn design(lang: Lang, d: &DesignRefusal) -> String {
    match d {
        DesignRefusal::MovingPivotsCoincide => sw!(lang, "design.moving_pivots_coincide"),
        DesignRefusal::CentreAtInfinity { number, at } => {
            sw!(
                lang,
                "design.centre_at_infinity",
                number = number,
                at = place(at)
            )
        }
        DesignRefusal::MovingPivotIsPole { number } => {
            sw!(lang, "design.moving_pivot_is_pole", number = number)
        }
        DesignRefusal::CranksShareMovingPivot => sw!(lang, "design.cranks_share_pivot"),
        DesignRefusal::NoCentrePointNear { number, near } => {
            sw!(
                lang,
                "design.no_centre_point",
                number = number,
                near = place(near)
            )
        }
        DesignRefusal::FixedPivotIsPole { number } => {
            sw!(lang, "design.fixed_pivot_is_pole", number = number)
        }
        DesignRefusal::InfiniteLink { k1, k2 } => sw!(
            lang,
            "design.infinite_link",
            k1 = significant(*k1, 6),
            k2 = significant(*k2, 6)
        ),
        DesignRefusal::NoCoupler { k, coupler_squared } => sw!(
            lang,
            "design.no_coupler",
            k1 = significant(k[0], 6),
            k2 = significant(k[1], 6),
            k3 = significant(k[2], 6),
            squared = significant(*coupler_squared, 6)
        ),
        DesignRefusal::PartMissing { part } => sw!(lang, "design.part_missing", part = part),
        DesignRefusal::DrawingIncomplete => sw!(lang, "design.drawing_incomplete"),
    }
}

/// Why typed rows of numbers were not read.
pub fn rows(lang: Lang, e: &RowError) -> String {
    sw!(
        lang,
        "design.row",
        line = e.line,
        text = e.text,
        width = e.width
    )
}

/// Why no four-bar carries the body through its positions.
pub fn positions(lang: Lang, e: &PositionsError) -> String {
    match e {
        PositionsError::Count(n) => sw!(lang, "design.position_count", count = n),
        PositionsError::NoMovingPivots => sw!(lang, "design.no_moving_pivots"),
        PositionsError::NoFixedNear => sw!(lang, "design.no_fixed_near"),
        PositionsError::NoSuchBurmesterPoint { asked, count } => {
            sw!(
                lang,
                "design.no_such_burmester_point",
                asked = asked,
                count = count
            )
        }
        PositionsError::Method(e) => super::error(lang, e, linkage::scene::LengthUnit::Metre),
    }
}

/// Why a vector equation has no two-line construction.
pub fn construction(lang: Lang, e: &NoConstruction) -> String {
    match e {
        NoConstruction::NotTwoUnknownMagnitudes => sw!(lang, "design.not_two_unknowns"),
        NoConstruction::ParallelLines => sw!(lang, "design.parallel_lines"),
        NoConstruction::ZeroUnknown(term) => sw!(lang, "design.zero_unknown", term = term),
    }
}
