//! The scene's cam joints, validated and in SI: the cam's link pinned to ground, the
//! follower pinned to ground or sliding on it, the roller on the follower, the program
//! a turn long, and a roller that clears the cam's centre all the way round.

use std::f64::consts::TAU;

use super::joints::Names;
use super::units::{Units, finite_named, invalid, positive_named, scene_angle};
use crate::cam::{Program, segments_of};
use crate::error::CamProblem;
use crate::error::Result;
use crate::error::SceneProblem;
use crate::model::{CamJoint, FollowerGuide, LinkId, Prismatic, Revolute};
use crate::scene::{CamJointSpec, SceneFile};

/// Cam angles at which the roller's clearance of the cam's centre is checked.
const CLEARANCE_SAMPLES: usize = 60;
/// How far beyond the roller's radius the least sample must lie to need no search.
const CLEAR_BY: f64 = 1.5;

/// Every cam joint of the scene, in SI.
pub(super) fn cam_joints(
    scene: &SceneFile,
    names: &Names<'_>,
    ground: LinkId,
    revolutes: &[Revolute],
    sliders: &[Prismatic],
    units: Units,
) -> Result<Vec<CamJoint>> {
    scene
        .cams
        .iter()
        .map(|spec| cam_joint(spec, names, ground, revolutes, sliders, units))
        .collect()
}

fn refused(spec: &CamJointSpec, problem: CamProblem) -> crate::error::LinkageError {
    invalid(SceneProblem::Cam {
        joint: format!("{}/{}", spec.cam, spec.follower),
        problem,
    })
}

fn cam_joint(
    spec: &CamJointSpec,
    names: &Names<'_>,
    ground: LinkId,
    revolutes: &[Revolute],
    sliders: &[Prismatic],
    units: Units,
) -> Result<CamJoint> {
    let ctx = format!("cam `{}` on `{}`", spec.follower, spec.cam);
    let cam = names.link(&ctx, &spec.cam)?;
    let follower = names.link(&ctx, &spec.follower)?;
    let pin_to_ground = |link: LinkId| {
        revolutes.iter().enumerate().find_map(|(i, r)| {
            if r.a == ground && r.b == link {
                Some((i, r.a_local, r.b_local))
            } else if r.b == ground && r.a == link {
                Some((i, r.b_local, r.a_local))
            } else {
                None
            }
        })
    };
    let (cam_pivot, centre, centre_on_cam) = pin_to_ground(cam)
        .filter(|_| cam != ground)
        .ok_or_else(|| {
            refused(
                spec,
                CamProblem::CamNotOnGround {
                    link: spec.cam.clone(),
                },
            )
        })?;
    if follower == ground || follower == cam {
        let link = spec.follower.clone();
        return Err(refused(spec, CamProblem::FollowerNotSeparate { link }));
    }
    let guide = follower_guide(spec, follower, ground, sliders, pin_to_ground(follower))?;
    let (roller, roller_local) = names.point_on(&ctx, follower, &spec.roller)?;
    let roller_radius_m =
        positive_named(spec.roller_radius, || format!("{ctx}.roller_radius"))? * units.len;
    if let FollowerGuide::Arm {
        pivot_on_follower, ..
    } = &guide
        && (roller_local - pivot_on_follower).norm() == 0.0
    {
        let point = spec.roller.clone();
        return Err(refused(spec, CamProblem::RollerOnPivot { point }));
    }
    let arm = matches!(guide, FollowerGuide::Arm { .. });
    let (rest, lift_unit) = if arm {
        (
            scene_angle(&format!("{ctx}.rest"), spec.rest, units.ang)?,
            1f64.to_radians(),
        )
    } else {
        (
            finite_named(spec.rest, || format!("{ctx}.rest"))? * units.len,
            units.len,
        )
    };
    let joint = CamJoint {
        name: format!("{}/{}", spec.cam, spec.follower),
        cam,
        cam_pivot,
        centre,
        centre_on_cam,
        follower,
        guide,
        roller,
        roller_local,
        roller_radius_m,
        rest,
        phase_rad: scene_angle(&format!("{ctx}.phase"), spec.phase, units.ang)?,
        program: Program::new(segments_of(&spec.segments, lift_unit))?,
    };
    check_clearance(spec, &joint)?;
    Ok(joint)
}

/// An arm about the follower's ground pin, or the slider it is on a ground guide.
fn follower_guide(
    spec: &CamJointSpec,
    follower: LinkId,
    ground: LinkId,
    sliders: &[Prismatic],
    pin: Option<(usize, crate::motion::Vec2, crate::motion::Vec2)>,
) -> Result<FollowerGuide> {
    if let Some((pivot, pivot_world, pivot_on_follower)) = pin {
        return Ok(FollowerGuide::Arm {
            pivot,
            pivot_world,
            pivot_on_follower,
        });
    }
    let (slider, s) = sliders
        .iter()
        .enumerate()
        .find(|(_, s)| s.slider == follower && s.guide == ground)
        .ok_or_else(|| {
            refused(
                spec,
                CamProblem::FollowerNotGuided {
                    link: spec.follower.clone(),
                },
            )
        })?;
    Ok(FollowerGuide::Slide {
        slider,
        through_world: s.through_local,
        direction: s.direction_local,
        slider_local: s.slider_local,
        rotation: s.relative,
    })
}

/// The roller's centre stays farther from the cam's centre than its radius: the
/// least distance over the turn, bracketed on a scan and, where it comes near the
/// radius, located between the samples ([`crate::extremum`]). Every scene build
/// checks it (a length edit's limit search builds the scene a few dozen times), so
/// the scan is coarse: 1440 samples were most of a cam scene's refused edit, 20 ms
/// in the browser.
fn check_clearance(spec: &CamJointSpec, joint: &CamJoint) -> Result<()> {
    let samples = crate::extremum::sample(CLEARANCE_SAMPLES, 0.0, TAU, |theta| {
        Some(joint.pitch_distance(theta))
    });
    let least_sample = samples.iter().map(|s| s[1]).fold(f64::INFINITY, f64::min);
    // Between samples 6° apart a smooth distance dips far less than half again
    // below the least sample: clear by that much, no closer look is needed.
    if least_sample > CLEAR_BY * joint.roller_radius_m {
        return Ok(());
    }
    let closest = crate::extremum::locate_min(&samples, Some(TAU), |theta| {
        Some(joint.pitch_distance(theta))
    });
    let (closest_m, at) = closest.map_or((f64::INFINITY, 0.0), |e| (e.value, e.angle_rad));
    if closest_m > joint.roller_radius_m {
        return Ok(());
    }
    Err(refused(
        spec,
        CamProblem::RollerOverCentre {
            closest_m,
            at_deg: at.to_degrees(),
            roller_m: joint.roller_radius_m,
        },
    ))
}
