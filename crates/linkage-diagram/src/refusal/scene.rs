//! Why a scene file describes no valid mechanism, why a cam joint cannot be built
//! and why a share link carries no scene. The scene file's own keys (`ground`,
//! `branches`, `models`) stay as written there: the reader finds them in the file.

use linkage::SceneProblem;
use linkage::error::{CamProblem, LonePoint, MadeJoint};
use linkage::share::ShareError;

use super::list;
use super::train::drive_train;
use crate::numbers::significant;
use crate::words::{Lang, sw};

/// Why a scene is not a valid mechanism: its links, points and joints.
pub fn scene(lang: Lang, p: &SceneProblem) -> String {
    match p {
        SceneProblem::GroundCount { found } => sw!(lang, "scene.ground_count", found = found),
        SceneProblem::NoSize => sw!(lang, "scene.no_size"),
        SceneProblem::UnnamedLink { number } => sw!(lang, "scene.unnamed_link", number = number),
        SceneProblem::DuplicateLink { link } => sw!(lang, "scene.duplicate_link", link = link),
        SceneProblem::LinkWithoutPoints { link } => sw!(lang, "scene.no_points", link = link),
        SceneProblem::ZeroLength { link, a, b } => {
            sw!(lang, "scene.zero_length", link = link, a = a, b = b)
        }
        SceneProblem::LengthLost {
            link,
            a,
            b,
            gap_m,
            size_m,
            farthest_point,
            farthest_link,
        } => sw!(
            lang,
            "scene.length_lost",
            link = link,
            a = a,
            b = b,
            gap = significant(*gap_m, 4),
            size = significant(*size_m, 4),
            point = farthest_point,
            far_link = farthest_link
        ),
        SceneProblem::Mobility {
            mobility,
            moving,
            joints,
            cams,
            lone,
            made,
        } => sw!(
            lang,
            "scene.mobility",
            mobility = mobility,
            moving = moving,
            joints = joints,
            cams = cams,
            lone = lone_points(lang, lone, made)
        ),
        SceneProblem::Cam { joint, problem } => {
            sw!(lang, "scene.cam", joint = joint, why = cam(lang, problem))
        }
        other => names_and_branches(lang, other),
    }
}

/// The problems of names that point nowhere and of assembly branches.
fn names_and_branches(lang: Lang, p: &SceneProblem) -> String {
    match p {
        SceneProblem::UnknownLink {
            context,
            name,
            known,
        } => sw!(
            lang,
            "scene.unknown_link",
            context = context,
            name = name,
            known = list(lang, known)
        ),
        SceneProblem::PointNotOnLink {
            context,
            point,
            link,
        } => sw!(
            lang,
            "scene.point_not_on_link",
            context = context,
            point = point,
            link = link
        ),
        SceneProblem::SliderOnItsGuide { context } => {
            sw!(lang, "scene.slider_on_its_guide", context = context)
        }
        SceneProblem::DriverIsGround => sw!(lang, "scene.driver_is_ground"),
        SceneProblem::DriverNotOnGround { link } => {
            sw!(lang, "scene.driver_not_on_ground", link = link)
        }
        SceneProblem::UnknownBranchKey { name } => {
            sw!(lang, "scene.unknown_branch_key", name = name)
        }
        SceneProblem::BranchNamesUnknownPoint { of, name } => {
            sw!(lang, "scene.branch_unknown_point", of = of, name = name)
        }
        SceneProblem::ForceNamesUnknownPoint { element, name } => {
            sw!(
                lang,
                "scene.force_unknown_point",
                element = element,
                name = name
            )
        }
        SceneProblem::ForceNamesUnknownLink { element, name } => {
            sw!(
                lang,
                "scene.force_unknown_link",
                element = element,
                name = name
            )
        }
        SceneProblem::NoPointForBranch { point } => {
            sw!(lang, "scene.no_point_for_branch", point = point)
        }
        SceneProblem::MissingBranch { kind, joint } => {
            sw!(lang, "scene.missing_branch", kind = kind, joint = joint)
        }
        SceneProblem::BranchEnds { joint, a, c } => {
            sw!(lang, "scene.branch_ends", joint = joint, a = a, c = c)
        }
        SceneProblem::BranchNotASide { joint, a, c } => {
            sw!(lang, "scene.branch_not_a_side", joint = joint, a = a, c = c)
        }
        SceneProblem::BranchNotAlong {
            joint_kind, joint, ..
        } => {
            sw!(
                lang,
                "scene.branch_not_along",
                kind = joint_kind,
                joint = joint
            )
        }
        other => chain_and_models(lang, other),
    }
}

/// The problems of the chain as a whole and of what the scene models.
fn chain_and_models(lang: Lang, p: &SceneProblem) -> String {
    match p {
        SceneProblem::DyadZeroLength { link, which } => {
            sw!(lang, "scene.dyad_zero_length", link = link, which = which)
        }
        SceneProblem::RedundantJoints { dof } => sw!(lang, "scene.redundant_joints", dof = dof),
        SceneProblem::EquationCount {
            equations,
            unknowns,
        } => sw!(
            lang,
            "scene.equation_count",
            equations = equations,
            unknowns = unknowns
        ),
        SceneProblem::Unconnected { link } => sw!(lang, "scene.unconnected", link = link),
        SceneProblem::MissingInertia { link, field } => {
            sw!(lang, "scene.missing_inertia", link = link, field = field)
        }
        SceneProblem::Massless => sw!(lang, "scene.massless"),
        SceneProblem::KinematicsOnly { scene } => sw!(lang, "scene.kinematics_only", scene = scene),
        SceneProblem::NoCrankSpeed => sw!(lang, "scene.no_crank_speed"),
        SceneProblem::NotPivoted { link } => sw!(lang, "scene.not_pivoted", link = link),
        SceneProblem::NotAsDrawn { point } => sw!(lang, "scene.not_as_drawn", point = point),
        SceneProblem::CannotWrite { why } => sw!(lang, "scene.cannot_write", why = why),
        SceneProblem::DriveTrain(p) => sw!(lang, "scene.drive_train", why = drive_train(lang, p)),
        // `scene` and `names_and_branches` word the others before they come here;
        // one added to the solver and not yet here reads in the solver's English.
        other => other.to_string(),
    }
}

/// The points on one link only (they were meant to make joints), or the joints
/// made where none is alone.
fn lone_points(lang: Lang, lone: &[LonePoint], made: &[MadeJoint]) -> String {
    if lone.is_empty() {
        let made: Vec<String> = made
            .iter()
            .map(|j| match j {
                MadeJoint::Pin { point, a, b } => {
                    sw!(lang, "scene.made_pin", point = point, a = a, b = b)
                }
                MadeJoint::Slider { link } => sw!(lang, "scene.made_slider", link = link),
            })
            .collect();
        return sw!(lang, "scene.none_alone", made = list(lang, &made));
    }
    let lone: Vec<String> = lone
        .iter()
        .map(|p| sw!(lang, "scene.lone_point", point = p.point, link = p.link))
        .collect();
    list(lang, &lone)
}

/// Why a cam joint cannot be built.
pub fn cam(lang: Lang, c: &CamProblem) -> String {
    match c {
        CamProblem::CamNotOnGround { link } => sw!(lang, "cam.not_on_ground", link = link),
        CamProblem::FollowerNotSeparate { link } => {
            sw!(lang, "cam.follower_not_separate", link = link)
        }
        CamProblem::FollowerNotGuided { link } => sw!(lang, "cam.follower_not_guided", link = link),
        CamProblem::RollerOnPivot { point } => sw!(lang, "cam.roller_on_pivot", point = point),
        CamProblem::RollerOverCentre {
            closest_m,
            at_deg,
            roller_m,
        } => sw!(
            lang,
            "cam.roller_over_centre",
            closest = significant(*closest_m, 4),
            at = significant(*at_deg, 4),
            roller = significant(*roller_m, 4)
        ),
    }
}

/// Why a share link carries no scene, or a scene does not fit one.
pub fn share(lang: Lang, e: &ShareError) -> String {
    match e {
        ShareError::TooLong { chars, max } => sw!(lang, "share.too_long", chars = chars, max = max),
        ShareError::Missing => sw!(lang, "share.missing"),
        ShareError::UnknownVersion { start } => sw!(lang, "share.unknown_version", start = start),
        ShareError::NotBase64(why) | ShareError::NotDeflate(why) => {
            sw!(lang, "share.damaged", why = why)
        }
        ShareError::Unpacks { max } => sw!(lang, "share.unpacks", max = max),
        ShareError::NotText => sw!(lang, "share.not_text"),
    }
}
