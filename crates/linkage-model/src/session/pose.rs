//! The pose: the solver of the current mechanism, the current (always valid) solution
//! and its polygon data. It is cheap and always current: every edit and every frame
//! of playback moves it.

use linkage::polygon::{VectorEquation, polygons};
use linkage::{Kinematics, Mechanism, Solution};

use super::topology::Topology;

/// The current mechanism in its current position.
pub struct Pose {
    kin: Kinematics,
    solution: Solution,
    topology: Topology,
    polygons: Vec<VectorEquation>,
}

impl Pose {
    /// The pose of `kin` at `solution` (solved by `kin`).
    pub fn new(kin: Kinematics, solution: Solution, topology: Topology) -> Self {
        let polygons = polygons(&kin, &solution);
        Self {
            kin,
            solution,
            topology,
            polygons,
        }
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
    }
}
