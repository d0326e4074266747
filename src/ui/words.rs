//! The model's data in the app's language: an Assur group by its links and joint,
//! a force polygon's stage by its links' numbers, a term's direction, a drawing
//! tool. The solver and the model give these as data (`GroupLabel`, `Stage`,
//! `TermDirection`); what the sheets also show is worded by the sheets' catalogue
//! (`linkage_diagram::words`) in the app's language, so that a sheet says what the
//! app said; the app's own things through the app's catalogue.

use linkage::Mechanism;
use linkage::dyad::GroupLabel;
use linkage::force_polygon::StagePolygon;
use linkage_diagram::words::{self, Lang};

use crate::i18n::tr;

/// The language the sheets' words are given in: the app's, this frame.
pub fn lang() -> Lang {
    match crate::i18n::language() {
        crate::i18n::Language::English => Lang::English,
        crate::i18n::Language::Chinese => Lang::Chinese,
    }
}

/// A group as the user knows it: "coupler and rocker, joined at C" (连杆 与 摇杆，在 C
/// 处铰接), a cam's follower "follower, on the cam at F", or by its number; worded
/// as the sheets word it.
pub fn group(label: &GroupLabel) -> String {
    words::group(lang(), label)
}

/// A force polygon's stage: its group and its links' numbers, or the crank.
pub fn stage_title(stage: &StagePolygon, m: &Mechanism) -> String {
    words::stage_title(lang(), stage, m)
}

/// A polygon term's direction: "perp CD" (⊥CD), "C to D" (C→D).
pub fn direction(d: &linkage::polygon::TermDirection) -> String {
    words::direction(lang(), d)
}

/// How a force polygon's stage treats a force: known, direction known, solved.
pub fn row_status(status: linkage_diagram::force_figure::RowStatus) -> String {
    words::row_status(lang(), status)
}

/// A couple's sense of turning.
pub fn sense(sense: linkage_diagram::force_figure::Sense) -> String {
    words::sense(lang(), sense)
}

/// A drawing tool's name on its button.
pub fn tool_name(tool: crate::drawing::Tool) -> String {
    use crate::drawing::Tool;
    match tool {
        Tool::Pivot => tr!("draw.tool_pivot"),
        Tool::Link => tr!("draw.tool_link"),
        Tool::Slider => tr!("draw.tool_slider"),
        Tool::Driver => tr!("draw.tool_driver"),
        Tool::Move => tr!("draw.tool_move"),
        Tool::Spring => tr!("draw.tool_spring"),
        Tool::Damper => tr!("draw.tool_damper"),
        Tool::Force => tr!("draw.tool_force"),
        Tool::Delete => tr!("draw.tool_delete"),
    }
}

/// What to do with a drawing tool, in a line.
pub fn tool_hint(tool: crate::drawing::Tool) -> String {
    use crate::drawing::Tool;
    match tool {
        Tool::Pivot => tr!("draw.hint_pivot"),
        Tool::Link => tr!("draw.hint_link"),
        Tool::Slider => tr!("draw.hint_slider"),
        Tool::Driver => tr!("draw.hint_driver"),
        Tool::Move => tr!("draw.hint_move"),
        Tool::Spring => tr!("draw.hint_spring"),
        Tool::Damper => tr!("draw.hint_damper"),
        Tool::Force => tr!("draw.hint_force"),
        Tool::Delete => tr!("draw.hint_delete"),
    }
}
