//! The parts of a force polygon as data: its forces and couples, the stage (an Assur
//! group or the crank) it closes, and the reactions the stages solve.

use super::symbol::{CoupleSymbol, ForceSymbol};
use crate::dyad::DyadLabel;
use crate::ids::{LinkId, PointId};
use crate::motion::Vec2;

/// A joint of the mechanism: an index into its revolutes or its prismatic joints.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum JointId {
    /// `Mechanism::revolutes[n]`.
    Revolute(usize),
    /// `Mechanism::sliders[n]`.
    Prismatic(usize),
    /// `Mechanism::cams[n]`: the cam's push on its follower, along the common normal.
    Cam(usize),
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
