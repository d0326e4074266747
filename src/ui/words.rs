//! The model's data in the app's language: an Assur group by its links and joint,
//! a force polygon's stage by its links' numbers, a term's direction, a drawing
//! tool. The solver and the model give these as data (`GroupLabel`, `Stage`,
//! `TermDirection`); what the sheets also show is worded by the sheets' catalogue
//! (`linkage_diagram::words`) in the app's language, so that a sheet says what the
//! app said; the app's own things through the app's catalogue.

use linkage::Mechanism;
use linkage::drawing::DrawingProblem;
use linkage::dyad::GroupLabel;
use linkage::force_polygon::StagePolygon;
use linkage::scene::LengthUnit;
use linkage_diagram::words::{self, Lang};

use crate::i18n::tr;

/// The language the sheets' words are given in: the app's, this frame.
pub fn lang() -> Lang {
    match crate::i18n::language() {
        crate::i18n::Language::English => Lang::English,
        crate::i18n::Language::Chinese => Lang::Chinese,
    }
}

/// A solver's refusal in the app's language, lengths in `unit`: the links by
/// their points, the crank's angle in degrees, each condition with its range.
pub fn refusal(e: &linkage::LinkageError, unit: LengthUnit) -> String {
    linkage_diagram::refusal::error(lang(), e, unit)
}

/// Why the drawing is not yet a mechanism, and what to do next with the drawing
/// tools.
pub fn drawing_problem(p: &DrawingProblem, unit: LengthUnit) -> String {
    match p {
        DrawingProblem::NoLinks => tr!("draw.no_links"),
        DrawingProblem::Mobility(m) => {
            let dof = m.dof();
            let (moving, joints) = (m.moving, m.revolutes + m.prismatics);
            if dof > 1 {
                tr!("draw.too_free", dof = dof, moving = moving, joints = joints)
            } else {
                tr!("draw.locked", dof = dof, moving = moving, joints = joints)
            }
        }
        DrawingProblem::NoDriver => tr!(
            "draw.no_driver",
            tool = tool_name(crate::drawing::Tool::Driver)
        ),
        DrawingProblem::DriverNotGrounded(link) => tr!("draw.driver_not_grounded", link = link),
        DrawingProblem::Invalid(e) => refusal(e, unit),
    }
}

/// Why the open scene cannot become a drawing.
pub fn not_drawable(why: &linkage::drawing::NotDrawable) -> String {
    use linkage::drawing::NotDrawable;
    match why {
        NotDrawable::Forces => tr!("drawing.keeps_forces"),
        NotDrawable::BlockCarriesPoints(block) => {
            tr!("drawing.block_carries_points", block = block)
        }
        NotDrawable::PointNotDrawn(point) => tr!("drawing.point_not_drawn", point = point),
        NotDrawable::CamJoint(joint) => tr!("drawing.cam_joint", joint = joint),
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
