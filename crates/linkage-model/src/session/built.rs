//! A mechanism built from a scene with what an edit shows at once: the solver, the
//! pose and the curves (the report, the modelled curves and the dynamic run follow
//! when shown).

use linkage::{Kinematics, Mechanism, SceneFile, Solution};

use super::cam_curves::CamCurves;
use super::curves::Curves;
use super::topology::Topology;

/// A scene built and solved at one input.
pub(crate) struct Built {
    pub(super) kin: Kinematics,
    pub(super) pose: Solution,
    pub(super) topology: Topology,
    pub(super) curves: Curves,
}

impl Built {
    /// Builds at `input` (or the scene's start angle); `earlier_cams` are the cam
    /// curves before the edit, kept where a cam joint is unchanged.
    pub(crate) fn new(
        scene: &SceneFile,
        input: Option<f64>,
        earlier_cams: &[CamCurves],
    ) -> linkage::Result<Self> {
        let kin = Kinematics::new(Mechanism::from_scene(scene)?)?;
        let start = kin.mechanism().driver.start_rad;
        Self::at(kin, input.unwrap_or(start), earlier_cams)
    }

    /// Where point `name` is in the built pose, m.
    pub(crate) fn point_position(&self, name: &str) -> Option<linkage::Vec2> {
        let p = self.kin.mechanism().point_index(name)?;
        Some(self.pose.points[p].position)
    }

    /// Solves `kin` at `input` and sweeps it (`earlier_cams` as in [`Self::new`]).
    pub(crate) fn at(
        mut kin: Kinematics,
        input: f64,
        earlier_cams: &[CamCurves],
    ) -> linkage::Result<Self> {
        let pose = kin.solve(input)?;
        let curves = Curves::compute(&mut kin, earlier_cams)?;
        Ok(Self {
            topology: Topology::of(kin.mechanism(), &curves.cams),
            kin,
            pose,
            curves,
        })
    }
}
