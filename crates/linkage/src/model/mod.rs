//! The validated mechanism: SI units, indices instead of names, joints made explicit.

use nalgebra::{UnitComplex, Vector2};

use crate::error::{LinkageError, Result};
pub use crate::ids::{LinkId, PointId};
use crate::motion::{LinkMotion, SlideMotion, Vec2, perp};
use crate::real::{Real, splat, splat_vec};
use crate::scene::{Branch, ForcesSpec, Models, SceneFile, SolverSpec};

mod cam_joint;
mod cams;
mod drive;
mod drive_train;
mod driver;
mod forces;
mod from_scene;
mod joints;
mod links;
mod units;

pub use crate::error::CamProblem;
pub use crate::error::{LonePoint, MadeJoint, SceneProblem};
pub use cam_joint::{CamContact, CamJoint, FollowerGuide};
pub use drive::{Drive, Motor};
pub use drive_train::{DriveTrain, MemberAtCrank};

/// A rigid link.
#[derive(Clone, Debug, PartialEq)]
pub struct Link {
    /// Name from the scene.
    pub name: String,
    /// True for the frame.
    pub is_ground: bool,
    /// The link's points: (index into `Mechanism::points`, link coordinates in m).
    pub points: Vec<(PointId, Vec2)>,
    /// Mass, kg, when the scene gives it.
    pub mass_kg: Option<f64>,
    /// Centroid in link coordinates, m.
    pub centroid_m: Option<Vec2>,
    /// Moment of inertia about the centroid, kg·m².
    pub inertia_kg_m2: Option<f64>,
}

impl Link {
    /// Local coordinates of a point on this link, if the link carries it.
    pub fn local(&self, point: PointId) -> Option<Vec2> {
        self.points
            .iter()
            .find(|(p, _)| *p == point)
            .map(|(_, v)| *v)
    }
}

/// A named point; it moves with `link` (the first link that lists it).
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// Name from the scene.
    pub name: String,
    /// Link it is computed from.
    pub link: LinkId,
    /// Coordinates on that link, m.
    pub local: Vec2,
}

/// A revolute joint between links `a` and `b` at a shared point.
#[derive(Clone, Debug, PartialEq)]
pub struct Revolute {
    /// The shared point.
    pub point: PointId,
    /// First link.
    pub a: LinkId,
    /// Joint point in `a`'s coordinates, m.
    pub a_local: Vec2,
    /// Second link.
    pub b: LinkId,
    /// Joint point in `b`'s coordinates, m.
    pub b_local: Vec2,
}

/// A prismatic joint: `slider_local` on `slider` stays on the guide line of `guide`.
#[derive(Clone, Debug, PartialEq)]
pub struct Prismatic {
    /// Display name, `slider/guide`.
    pub name: String,
    /// Sliding link.
    pub slider: LinkId,
    /// The slider's point on the line.
    pub point: PointId,
    /// That point in slider coordinates, m.
    pub slider_local: Vec2,
    /// Guide link.
    pub guide: LinkId,
    /// A point of the line in guide coordinates, m.
    pub through_local: Vec2,
    /// Unit direction of the line in guide coordinates.
    pub direction_local: Vec2,
    /// Slider angle minus guide angle, as a rotation.
    pub relative: UnitComplex<f64>,
}

impl Prismatic {
    /// World direction of the guide line.
    pub fn direction<T: Real>(&self, links: &[LinkMotion<T>]) -> Vector2<T> {
        links[self.guide].rotation * splat_vec(&self.direction_local)
    }

    /// Displacement of the slider point along the guide from `through`, with its
    /// first and second time derivatives (relative to the guide, Coriolis removed).
    pub fn motion<T: Real>(&self, links: &[LinkMotion<T>]) -> SlideMotion<T> {
        let guide = &links[self.guide];
        let u = self.direction(links);
        let p = links[self.slider].point(&self.slider_local);
        let on_guide = guide.material_point_at(&p.position);
        let v_rel = p.velocity - on_guide.velocity;
        let a_rel = p.acceleration
            - on_guide.acceleration
            - perp(&v_rel) * (splat::<T>(2.0) * guide.omega_rad_s);
        SlideMotion {
            displacement_m: (p.position - guide.world(&self.through_local)).dot(&u),
            velocity_m_s: v_rel.dot(&u),
            acceleration_m_s2: a_rel.dot(&u),
        }
    }
}

/// The input.
#[derive(Clone, Debug, PartialEq)]
pub struct Driver {
    /// Input link.
    pub link: LinkId,
    /// Index into `Mechanism::revolutes` of its joint with ground.
    pub pivot: usize,
    /// Input speed, rad/s.
    pub speed_rad_s: f64,
    /// Input angle at t = 0, rad.
    pub start_rad: f64,
}

/// A validated 1-DOF planar mechanism in SI units.
#[derive(Clone, Debug, PartialEq)]
pub struct Mechanism {
    /// Title.
    pub name: String,
    /// Description.
    pub description: String,
    /// Notes for the student.
    pub notes: Vec<String>,
    /// What the scene computes.
    pub models: Models,
    /// Links (ground included).
    pub links: Vec<Link>,
    /// Index of the ground link.
    pub ground: LinkId,
    /// Named points, in order of first appearance.
    pub points: Vec<Point>,
    /// Revolute joints (from shared point names).
    pub revolutes: Vec<Revolute>,
    /// Prismatic joints.
    pub sliders: Vec<Prismatic>,
    /// The input.
    pub driver: Driver,
    /// Branch per dyad inner point: (point index, branch).
    pub branches: Vec<(PointId, Branch)>,
    /// Main output link (time ratio).
    pub output: LinkId,
    /// Newton starting guesses per link: (origin m, angle rad).
    pub guess: Vec<Option<(Vec2, f64)>>,
    /// Force elements, lengths in m and angles in rad.
    pub forces: ForcesSpec,
    /// Solver settings.
    pub solver: SolverSpec,
    /// Largest point distance from the origin, m: the scale for tolerances.
    pub size_m: f64,
    /// The motor, gear and flywheel on the driver, if the scene gives them.
    pub drive: Option<Drive>,
    /// Cam joints: a disc cam on one link driving a follower link.
    pub cams: Vec<CamJoint>,
}

/// Largest angle a scene may give, rad (about 3200 turns). A double holds angles up to
/// here to 4e-12 rad; far beyond it the reduction to one turn, which every sine and
/// cosine does, loses the angle itself (at 1e16 deg one unit in the last place is
/// over a turn, and a sweep from there is no longer monotonic).
pub const MAX_ANGLE_RAD: f64 = 2.0e4;

impl Mechanism {
    /// Parses and validates scene text.
    pub fn from_ron(text: &str) -> Result<Self> {
        Self::from_scene(&SceneFile::parse(text)?)
    }

    /// Index of a link by name.
    pub fn link_index(&self, name: &str) -> Option<LinkId> {
        self.links.iter().position(|l| l.name == name).map(LinkId)
    }

    /// Index of a point by name.
    pub fn point_index(&self, name: &str) -> Option<PointId> {
        self.points.iter().position(|p| p.name == name).map(PointId)
    }

    /// The points that are joints (pins and slider points), each once, ascending.
    pub fn joint_points(&self) -> Vec<PointId> {
        let mut joints: Vec<PointId> = self
            .revolutes
            .iter()
            .map(|r| r.point)
            .chain(self.sliders.iter().map(|sl| sl.point))
            .collect();
        joints.sort_unstable();
        joints.dedup();
        joints
    }

    /// Moving links (all but ground), in scene order.
    pub fn moving_links(&self) -> impl Iterator<Item = LinkId> + '_ {
        self.link_ids().filter(move |&i| i != self.ground)
    }

    /// Every link's id, ground included, in scene order.
    pub fn link_ids(&self) -> impl Iterator<Item = LinkId> + use<> {
        (0..self.links.len()).map(LinkId)
    }

    /// Every named point's id, in order of first appearance.
    pub fn point_ids(&self) -> impl Iterator<Item = PointId> + use<> {
        (0..self.points.len()).map(PointId)
    }

    /// The revolute joint (its index in `revolutes`) that pins moving link `link` to
    /// ground, if one does.
    pub fn ground_pivot_of(&self, link: LinkId) -> Option<usize> {
        let g = self.ground;
        (link != g)
            .then(|| {
                self.revolutes
                    .iter()
                    .position(|r| (r.a == link && r.b == g) || (r.b == link && r.a == g))
            })
            .flatten()
    }

    /// The scene's branch for the dyad whose inner joint is `point`.
    pub fn branch_for(&self, point: PointId) -> Option<&Branch> {
        self.branches
            .iter()
            .find(|(p, _)| *p == point)
            .map(|(_, b)| b)
    }

    /// Replaces (or adds) the branch of the dyad whose inner joint is named `point`.
    pub fn set_branch(&mut self, point: &str, branch: Branch) -> Result<()> {
        let pi = self.point_index(point).ok_or_else(|| {
            LinkageError::from(SceneProblem::NoPointForBranch {
                point: point.to_string(),
            })
        })?;
        match self.branches.iter_mut().find(|(p, _)| *p == pi) {
            Some(entry) => entry.1 = branch,
            None => self.branches.push((pi, branch)),
        }
        Ok(())
    }
}
