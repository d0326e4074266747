//! The model's data in the app's language: an Assur group by its links and joint,
//! a force polygon's stage by its links' numbers. The solver and the model give
//! these as data (`GroupLabel`, `Stage`); the sheets and the command line word them
//! in English (`linkage_diagram::force_figure`), the app here through the catalogue.

use linkage::Mechanism;
use linkage::dyad::{DyadKind, DyadLabel, GroupLabel};
use linkage::force_polygon::{Stage, StagePolygon};

use crate::i18n::tr;

/// A group as the user knows it: "coupler and rocker, joined at C" (连杆与摇杆，在 C
/// 处相连), a cam's follower "follower, on the cam at F", or by its number.
pub fn group(label: &GroupLabel) -> String {
    match label {
        GroupLabel::Dyad(d) => dyad(d),
        GroupLabel::Numbered(n) => tr!("group.numbered", n = n),
    }
}

/// A dyad by its links and inner joint.
pub fn dyad(d: &DyadLabel) -> String {
    let [a, b] = &d.links;
    if d.kind == DyadKind::CamFollower {
        tr!("group.follower", a = a, joint = d.inner_point)
    } else {
        tr!("group.dyad", a = a, b = b, joint = d.inner_point)
    }
}

/// A force polygon's stage: its group and its links' numbers, or the crank.
pub fn stage_title(stage: &StagePolygon, m: &Mechanism) -> String {
    let numbers = linkage_diagram::force_figure::stage_numbers(stage, m);
    match &stage.stage {
        Stage::Group { dyad: d, .. } if d.kind != DyadKind::CamFollower => {
            tr!("group.stage", group = dyad(d), numbers = numbers)
        }
        // A cam's follower is one link.
        Stage::Group { dyad: d, .. } => tr!("group.stage_one", group = dyad(d), number = numbers),
        Stage::Crank { link } => {
            tr!(
                "group.stage_one",
                group = m.links[*link].name,
                number = numbers
            )
        }
    }
}
