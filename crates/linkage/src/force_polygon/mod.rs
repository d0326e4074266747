//! Force polygons: graphical kinetostatics as the textbooks work it. The chain is
//! taken apart into its Assur groups and solved from the output back to the crank,
//! one group at a time: the group's known forces (external loads, weights,
//! d'Alembert inertia forces, the reactions of the groups already solved) and its
//! unknown outer reactions form one closed polygon, the inner joint's reaction is its
//! diagonal, and the crank's balancing torque closes the last stage.
//!
//! Each stage solves only its own equilibrium (three equations per link, moments
//! about the stage's own joint), so its reactions are an independent check of the
//! whole-chain Newton–Euler solution of [`crate::kinetostatics`].

mod stage;
mod symbol;

use crate::dyad::DyadLabel;
use crate::error::{LinkageError, Result};
use crate::ids::{LinkId, PointId};
use crate::kinetostatics::Kinetostatics;
use crate::motion::Vec2;
use crate::solve::Kinematics;

pub use symbol::{CoupleSymbol, ForceSymbol, SymbolParts, link_number};

/// A joint of the mechanism: an index into its revolutes or its prismatic joints.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum JointId {
    /// `Mechanism::revolutes[n]`.
    Revolute(usize),
    /// `Mechanism::sliders[n]`.
    Prismatic(usize),
}

/// One force of a polygon.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForceVector {
    /// What it is.
    pub symbol: ForceSymbol,
    /// The force, N.
    pub force: Vec2,
    /// A point of its line of action, m.
    pub at: Vec2,
    /// Its magnitude was known before the stage was solved.
    pub magnitude_known: bool,
    /// Its direction was known before the stage was solved (a guide's reaction is
    /// normal to the guide).
    pub direction_known: bool,
}

/// One couple of a stage.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoupleTerm {
    /// What it is.
    pub symbol: CoupleSymbol,
    /// The link it acts on.
    pub link: LinkId,
    /// Its moment, N·m, counter-clockwise positive.
    pub moment: f64,
    /// Known before its stage was solved (a load, an inertia couple, a couple from a
    /// stage solved before); false for the stage's own guide couples and the
    /// balancing torque.
    pub known: bool,
}

/// Which part of the chain a stage solves.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Stage {
    /// Assur group `index` of the decomposition.
    Group {
        /// Its index in the decomposition (0 next to the crank).
        index: usize,
        /// Its kind, links and inner joint.
        dyad: DyadLabel,
    },
    /// The crank, with the balancing torque.
    Crank {
        /// The driver link.
        link: LinkId,
    },
}

/// One stage's closed polygon.
#[derive(Clone, Debug, PartialEq)]
pub struct StagePolygon {
    /// The group or the crank.
    pub stage: Stage,
    /// Its links (a group's two, in the order the polygon takes them).
    pub links: Vec<LinkId>,
    /// The forces head to tail, summing to zero. A group: the first link's outer
    /// reactions, its known forces, the second link's known forces, its outer
    /// reactions. The crank: its known forces, then the frame's reaction.
    pub polygon: Vec<ForceVector>,
    /// A group's inner reaction (on the second link from the first): the diagonal
    /// from the polygon's start to the end of the first link's forces.
    pub inner: Option<ForceVector>,
    /// The couples on the stage's links, the balancing torque last on the crank.
    pub couples: Vec<CoupleTerm>,
}

impl StagePolygon {
    /// The largest force of the polygon (and its diagonal), N.
    pub fn largest(&self) -> f64 {
        self.polygon
            .iter()
            .chain(self.inner.iter())
            .map(|f| f.force.norm())
            .fold(0.0, f64::max)
    }

    /// How far the polygon is from closing, N: the length of the sum of its forces.
    pub fn closure_gap(&self) -> f64 {
        self.polygon
            .iter()
            .fold(Vec2::zeros(), |s, f| s + f.force)
            .norm()
    }
}

/// A joint's reaction as the Newton–Euler solution states it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointForce {
    /// The joint.
    pub joint: JointId,
    /// Its point.
    pub point: PointId,
    /// Force on the revolute's second link from its first (on the slider from the
    /// guide), N.
    pub force: Vec2,
    /// The couple on the slider from the guide, N·m (0 for a revolute).
    pub couple: f64,
}

/// The force polygons of one position.
#[derive(Clone, Debug, PartialEq)]
pub struct ForcePolygons {
    /// The input angle, rad.
    pub input_rad: f64,
    /// The stages in the order solved: the last group first, the crank last.
    pub stages: Vec<StagePolygon>,
    /// The balancing torque on the crank, N·m.
    pub balancing_torque: f64,
    /// Every joint's reaction, revolutes then prismatic joints in scene order.
    pub joints: Vec<JointForce>,
}

/// The force polygons of the scene of `k` at `input_rad` and the scene's crank
/// speed. `ks` solves the motion (and checks the position: a dead point of the input
/// is refused as by [`Kinetostatics::at`]).
///
/// # Errors
/// A chain that is not a crank and dyads (solved by Newton alone), a position where
/// the chain does not assemble or a stage's reactions are indeterminate.
pub fn force_polygons(
    k: &mut Kinematics,
    ks: &mut Kinetostatics,
    input_rad: f64,
) -> Result<ForcePolygons> {
    let Some(cf) = k.closed_form() else {
        return Err(LinkageError::NotDecomposable(
            "force polygons need the chain as a crank and dyads; this one is solved by \
             Newton alone"
                .into(),
        ));
    };
    let groups: Vec<(LinkId, LinkId)> = cf.groups.iter().map(|g| g.links()).collect();
    ks.at(k, input_rad)?;
    let m = k.mechanism();
    let mut solver = stage::Stages::new(m, ks.solution(), ks.forces());
    let mut stages = Vec::with_capacity(groups.len() + 1);
    for (index, &(i, j)) in groups.iter().enumerate().rev() {
        let dyad = k.dyad(index).expect("a closed-form chain names its groups");
        stages.push(solver.solve(Stage::Group { index, dyad }, &[i, j], input_rad)?);
    }
    let link = m.driver.link;
    stages.push(solver.solve(Stage::Crank { link }, &[link], input_rad)?);
    Ok(ForcePolygons {
        input_rad,
        stages,
        balancing_torque: solver.balancing_torque(),
        joints: solver.joint_forces(),
    })
}
