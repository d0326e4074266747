//! The pose: the solver of the current mechanism, the current (always valid) solution
//! and its polygon data (velocity, acceleration and, for a scene with masses or
//! forces, the force polygons). It is cheap and always current: every edit and every
//! frame of playback moves it.

use linkage::force_polygon::{ForcePolygons, force_polygons};
use linkage::kinetostatics::Kinetostatics;
use linkage::polygon::{VectorEquation, polygons};
use linkage::scene::Models;
use linkage::{Kinematics, LinkageError, Mechanism, Solution};

use super::topology::Topology;

/// The current mechanism in its current position.
pub struct Pose {
    kin: Kinematics,
    solution: Solution,
    topology: Topology,
    polygons: Vec<VectorEquation>,
    /// The force model of a scene with kinetostatics data (or why it has none).
    kinetostatics: Option<Result<Kinetostatics, LinkageError>>,
    forces: Option<Result<ForcePolygons, LinkageError>>,
}

impl Pose {
    /// The pose of `kin` at `solution` (solved by `kin`).
    pub fn new(mut kin: Kinematics, solution: Solution, topology: Topology) -> Self {
        let polygons = polygons(&kin, &solution);
        let kinetostatics =
            (kin.mechanism().models != Models::Kinematics).then(|| Kinetostatics::new(&mut kin));
        let mut pose = Self {
            kin,
            solution,
            topology,
            polygons,
            kinetostatics,
            forces: None,
        };
        pose.forces = pose.solve_forces();
        pose
    }

    /// The force polygons at the current solution's input angle (at the scene's crank
    /// speed); `None` for a kinematics-only scene.
    fn solve_forces(&mut self) -> Option<Result<ForcePolygons, LinkageError>> {
        let input = self.solution.input_rad;
        match self.kinetostatics.as_mut()? {
            Ok(ks) => Some(force_polygons(&mut self.kin, ks, input)),
            Err(e) => Some(Err(e.clone())),
        }
    }

    /// The force polygons at the current position, or why there are none there;
    /// `None` for a scene without masses or forces (kinematics only).
    pub fn forces(&self) -> Option<&Result<ForcePolygons, LinkageError>> {
        self.forces.as_ref()
    }

    /// The mechanism.
    pub fn mechanism(&self) -> &Mechanism {
        self.kin.mechanism()
    }

    /// The solver (for its path and tolerances).
    pub fn kinematics(&self) -> &Kinematics {
        &self.kin
    }

    /// Joints and links by index (fixed per mechanism).
    pub fn topology(&self) -> &Topology {
        &self.topology
    }

    /// The current solution: always a valid, solved one.
    pub fn solution(&self) -> &Solution {
        &self.solution
    }

    /// The velocity and acceleration polygon equations at the current solution.
    pub fn polygons(&self) -> &[VectorEquation] {
        &self.polygons
    }

    /// Solves at `input_rad` and shows it; on failure nothing changes.
    ///
    /// # Errors
    /// The solver's error (the reachable range where the chain does not assemble).
    pub fn solve(&mut self, input_rad: f64) -> linkage::Result<()> {
        let s = self.kin.solve(input_rad)?;
        self.show(s);
        Ok(())
    }

    /// Shows `solution` (a pose of the same mechanism, e.g. from a dynamic run).
    pub fn show(&mut self, solution: Solution) {
        self.polygons = polygons(&self.kin, &solution);
        self.solution = solution;
        self.forces = self.solve_forces();
    }
}
