//! A scene file validated and converted to a [`Mechanism`], section by section: the
//! links and their points, the joints they make, the sliders, the mobility, the
//! driver, the branches, the guesses, the forces and the solver's settings. Each
//! section names what it refuses and, where one exists, the valid range.

use super::cams::cam_joints;
use super::driver::{branches, driver, guesses};
use super::forces::convert_forces;
use super::joints::{Names, check_mobility, revolutes, sliders};
use super::links::{bodies, check_joint_gaps};
use super::units::{Units, invalid};
use crate::error::SceneProblem;
use crate::error::{LinkageError, Result};
use crate::error::{Param, Valid};
use crate::model::{Drive, LinkId, Mechanism};
use crate::scene::SceneFile;

impl Mechanism {
    /// Validates a parsed scene and converts it to SI.
    pub fn from_scene(scene: &SceneFile) -> Result<Self> {
        let units = Units {
            len: scene.length_unit.to_metres(),
            ang: scene.angle_unit.to_radians(),
        };
        let bodies = bodies(scene, units)?;
        let revolutes = revolutes(&bodies.on_links);
        check_joint_gaps(&bodies)?;
        let names = Names {
            links: &bodies.links,
            points: &bodies.points,
        };
        let sliders = sliders(scene, &names, units)?;
        check_mobility(&bodies, &revolutes, &sliders, scene.cams.len())?;
        let ground = bodies
            .links
            .iter()
            .position(|l| l.is_ground)
            .map(LinkId)
            .ok_or(invalid(SceneProblem::GroundCount { found: 0 }))?;
        let driver = driver(scene, &names, ground, &revolutes, units)?;
        let cams = cam_joints(scene, &names, ground, &revolutes, &sliders, units)?;
        let branches = branches(scene, &bodies.points)?;
        let output = match &scene.output {
            Some(name) => names.link("output", name)?,
            None => LinkId(bodies.links.len() - 1),
        };
        let guess = guesses(scene, &names, units)?;
        let forces = convert_forces(
            &scene.forces,
            units.len,
            units.ang,
            &bodies.links,
            &bodies.points,
        )?;
        if !(scene.solver.tolerance > 0.0 && scene.solver.tolerance.is_finite()) {
            return Err(LinkageError::invalid(
                Param::Scene("solver.tolerance".into()),
                scene.solver.tolerance,
                Valid::SolverTolerance { typical: 1e-13 },
            ));
        }
        if bodies.size_m <= 0.0 {
            return Err(invalid(SceneProblem::NoSize));
        }
        Ok(Self {
            name: scene.name.clone(),
            description: scene.description.clone(),
            notes: scene.notes.clone(),
            models: scene.models,
            links: bodies.links,
            ground,
            points: bodies.points,
            revolutes,
            sliders,
            driver,
            branches,
            output,
            guess,
            forces,
            solver: scene.solver,
            size_m: bodies.size_m,
            drive: scene.drive.as_ref().map(Drive::from_spec).transpose()?,
            cams,
        })
    }
}
