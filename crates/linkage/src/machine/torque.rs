//! The torque a crank turning at a constant speed needs, and the mechanism's reduced
//! inertia, at any crank angle: from the reduced model of the dynamics,
//! `J φ'' + ½ J' φ'² = M + T`, with φ'' = 0, so `T = ½ J' ω² − M(φ, ω)` (the inertia
//! forces are in ½ J' ω², the loads in M).

use crate::dynamics::ForceModel;
use crate::error::{LinkageError, MachineAnalysis, Result};
use crate::motion::Solution;
use crate::solve::Kinematics;

/// `Ok` when `k`'s input turns a full cycle; else [`LinkageError::NotACrank`] saying
/// that `needs` needs a crank, with where the chain does assemble.
pub(crate) fn full_turn(k: &Kinematics, needs: MachineAnalysis) -> Result<()> {
    let reachable = k.assembly_ranges();
    if reachable.full_rotation {
        Ok(())
    } else {
        Err(LinkageError::NotACrank { needs, reachable })
    }
}

/// One position of the crank at the nominal speed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CrankLoad {
    /// The torque on the crank that keeps its speed constant, N·m.
    pub(crate) torque_n_m: f64,
    /// The mechanism's inertia reduced to the crank, kg·m².
    pub(crate) reduced_inertia_kg_m2: f64,
}

/// Evaluates [`CrankLoad`] at any angle of one mechanism turning at `speed_rad_s`.
pub(crate) struct CrankTorque<'a> {
    k: &'a mut Kinematics,
    forces: ForceModel,
    unit: Solution,
    speed_rad_s: f64,
}

impl<'a> CrankTorque<'a> {
    /// The evaluator for `k` at its scene's crank speed.
    pub(crate) fn new(k: &'a mut Kinematics) -> Result<Self> {
        let start = k.mechanism().driver.start_rad;
        let speed_rad_s = k.mechanism().driver.speed_rad_s;
        let at_start = k.solve(start)?;
        // The torque the load asks for: the drive (its motor and flywheel) is what
        // is being sized, so it is left out.
        let mut load_only = k.mechanism().clone();
        load_only.drive = None;
        let forces = ForceModel::new(&load_only, &at_start)?;
        let unit = k.empty_solution();
        Ok(Self {
            k,
            forces,
            unit,
            speed_rad_s,
        })
    }

    /// The nominal crank speed, rad/s.
    pub(crate) fn speed_rad_s(&self) -> f64 {
        self.speed_rad_s
    }

    /// Torque and reduced inertia at crank angle `phi`.
    pub(crate) fn at(&mut self, phi: f64) -> Result<CrankLoad> {
        self.k.solve_into(phi, 1.0, &mut self.unit)?;
        let w = self.speed_rad_s;
        let r = self.forces.reduce(&self.unit, w);
        Ok(CrankLoad {
            torque_n_m: 0.5 * r.dj_dq * w * w - r.moment(),
            reduced_inertia_kg_m2: r.j,
        })
    }

    /// Where the working-stroke forces switch, as signed ratios (see
    /// [`ForceModel::switching_ratios`]) at crank angle `phi`.
    pub(crate) fn switching(&mut self, phi: f64) -> Result<Vec<f64>> {
        self.k.solve_into(phi, 1.0, &mut self.unit)?;
        Ok(self.forces.switching_ratios(&self.unit))
    }
}
