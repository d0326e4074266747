//! Why a position is singular (a dead point, links in line) and why a chain has no
//! closed-form decomposition into dyads.

use linkage::error::{Singularity, Undecomposable};

use super::list;
use crate::numbers::significant;
use crate::words::{Lang, sw};

/// Why a position is singular.
pub fn singularity(lang: Lang, s: &Singularity) -> String {
    match s {
        Singularity::DyadInLine {
            links: [a, b],
            point,
        } => {
            sw!(lang, "singular.in_line", a = a, b = b, point = point)
        }
        Singularity::DeadPoint => sw!(lang, "singular.dead_point"),
        Singularity::LoopJacobian => sw!(lang, "singular.loop_jacobian"),
        Singularity::InputDeadPoint => sw!(lang, "singular.input_dead_point"),
        Singularity::GroupReactions => sw!(lang, "singular.group_reactions"),
        Singularity::JointReactions => sw!(lang, "singular.joint_reactions"),
        Singularity::StepCollapsed { t_s, rtol, atol } => sw!(
            lang,
            "singular.step_collapsed",
            t = significant(*t_s, 6),
            rtol = rtol,
            atol = atol
        ),
        Singularity::NoInertia { j_kg_m2 } => {
            sw!(lang, "singular.no_inertia", j = significant(*j_kg_m2, 4))
        }
        Singularity::CoordinateDeadPoint {
            coordinate,
            regular,
            ratio,
        } => sw!(
            lang,
            "singular.coordinate_dead_point",
            coordinate = coordinate,
            regular = regular,
            ratio = significant(*ratio, 2)
        ),
    }
}

/// Why a chain has no closed-form decomposition into dyads.
pub fn undecomposable(lang: Lang, u: &Undecomposable) -> String {
    match u {
        Undecomposable::NoDyad { links } => {
            sw!(lang, "singular.no_dyad", links = list(lang, links))
        }
        Undecomposable::RedundantJoint { links: [a, b] } => {
            sw!(lang, "singular.redundant_joint", a = a, b = b)
        }
        Undecomposable::NeedsGuess { link } => sw!(lang, "singular.needs_guess", link = link),
        Undecomposable::NoSolver { newton: true } => sw!(lang, "singular.no_newton_solver"),
        Undecomposable::NoSolver { newton: false } => sw!(lang, "singular.no_closed_form_solver"),
        Undecomposable::ForcePolygonsNeedDyads => sw!(lang, "singular.force_polygons_need_dyads"),
        Undecomposable::ForceStage { links, unknowns } => {
            sw!(
                lang,
                "singular.force_stage",
                links = links,
                unknowns = unknowns
            )
        }
        Undecomposable::KinetostaticsDof {
            equations,
            unknowns,
        } => sw!(
            lang,
            "singular.kinetostatics_dof",
            equations = equations,
            unknowns = unknowns
        ),
    }
}
