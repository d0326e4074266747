//! The scene file format (RON), as people write it: lengths in the scene's unit,
//! angles in degrees unless `angle_unit: Radian`.
//!
//! A link lists its points in its own coordinates. A point name that appears on two
//! links is a revolute joint between them; a point on one link only is a marker
//! (a coupler point, a spring end). Prismatic joints are listed in `sliders`.
//! See `assets/scenes/README.md` for a worked example of every field.

use indexmap::IndexMap;
use serde::{Deserialize, Serialize};

pub use crate::scene_cam::CamJointSpec;
pub use crate::scene_drive::{DriveSpec, DriveTrainSpec, MotorSpec, Shaft};

use crate::error::SceneProblem;
use crate::error::{LinkageError, Result};

/// What a scene asks the program to compute.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Models {
    /// Positions, velocities and accelerations only: no forces are evaluated.
    Kinematics,
    /// Kinematics plus kinetostatics (driven scenes) using the declared forces and masses.
    Kinetostatics,
    /// Forward dynamics of the 1-DOF chain under the declared forces.
    Dynamics,
}

/// Unit of every length in the scene file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum LengthUnit {
    /// Metres (SI).
    #[default]
    Metre,
    /// Millimetres, as machine drawings use.
    Millimetre,
}

impl LengthUnit {
    /// Metres per unit.
    pub fn to_metres(self) -> f64 {
        match self {
            Self::Metre => 1.0,
            Self::Millimetre => 1e-3,
        }
    }
}

/// Unit of every angle in the scene file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum AngleUnit {
    /// Degrees (what people type).
    #[default]
    Degree,
    /// Radians.
    Radian,
}

impl AngleUnit {
    /// Radians per unit.
    pub fn to_radians(self) -> f64 {
        match self {
            Self::Degree => std::f64::consts::PI / 180.0,
            Self::Radian => 1.0,
        }
    }
}

/// One rigid link.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LinkSpec {
    /// Unique name (CSV columns use it).
    pub name: String,
    /// True for the frame; exactly one link is ground. Its points are world coordinates.
    #[serde(default)]
    pub ground: bool,
    /// Named points in link coordinates.
    #[serde(deserialize_with = "crate::unique_map::deserialize")]
    pub points: IndexMap<String, (f64, f64)>,
    /// Mass, kg (dynamics only).
    #[serde(default)]
    pub mass: Option<f64>,
    /// Centroid in link coordinates (dynamics only).
    #[serde(default)]
    pub centroid: Option<(f64, f64)>,
    /// Moment of inertia about the centroid, kg·m² (dynamics only).
    #[serde(default)]
    pub inertia: Option<f64>,
}

/// A prismatic joint: `point` of link `slider` stays on the line of link `guide`
/// through `through` at `angle`, and the slider turns with the guide.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SliderSpec {
    /// The sliding link.
    pub slider: String,
    /// The slider's point that stays on the guide line.
    pub point: String,
    /// The link carrying the guide (ground or a moving link).
    pub guide: String,
    /// A point of the guide link on the guide line.
    pub through: String,
    /// Direction of the guide line in the guide link's coordinates.
    pub angle: f64,
    /// Slider angle minus guide angle (constant).
    #[serde(default)]
    pub relative_angle: f64,
}

/// Constant input speed.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Speed {
    /// Revolutions per minute (positive = counter-clockwise).
    Rpm(f64),
    /// Radians per second (positive = counter-clockwise).
    RadPerSecond(f64),
}

/// The driver: the input link's absolute angle is the input coordinate.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DriverSpec {
    /// Link whose x-axis angle is the input; it must share a point with ground.
    pub link: String,
    /// Input speed for velocities and for time.
    pub speed: Speed,
    /// Input angle at the start (t = 0).
    #[serde(default)]
    pub start: f64,
}

/// The assembly branch of one dyad, keyed in the scene by the dyad's inner joint point.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Branch {
    /// The inner joint lies left of the directed line from the first to the second end pin.
    Left(String, String),
    /// The inner joint lies right of that line.
    Right(String, String),
    /// Slider group: the inner joint lies ahead, along the guide direction.
    Along,
    /// Slider group: the inner joint lies behind, against the guide direction.
    Against,
}

impl Branch {
    /// The other assembly mode.
    pub fn flipped(&self) -> Self {
        match self {
            Self::Left(a, b) => Self::Right(a.clone(), b.clone()),
            Self::Right(a, b) => Self::Left(a.clone(), b.clone()),
            Self::Along => Self::Against,
            Self::Against => Self::Along,
        }
    }
}

/// Free length of a spring.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum FreeLength {
    /// Unstretched at the start position.
    UnstretchedAtStart,
    /// Given free length (scene length unit).
    Length(f64),
}

/// A linear spring between two named points.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpringSpec {
    /// First end point.
    pub a: String,
    /// Second end point.
    pub b: String,
    /// Stiffness, N/m.
    pub k_n_per_m: f64,
    /// Free length.
    pub free_length: FreeLength,
}

/// A viscous damper.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum DamperSpec {
    /// Between two named points, N·s/m.
    Linear {
        /// First end point.
        a: String,
        /// Second end point.
        b: String,
        /// Coefficient, N·s/m.
        c_n_s_per_m: f64,
    },
    /// Between two links' rotations, N·m·s/rad.
    Rotational {
        /// First link.
        link_a: String,
        /// Second link.
        link_b: String,
        /// Coefficient, N·m·s/rad.
        c_n_m_s: f64,
    },
}

/// When a point force acts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum ForceWhen {
    /// Always.
    #[default]
    Always,
    /// Only while the point moves against the force (a working stroke).
    WorkingStroke,
}

/// A constant force at a named point.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointForceSpec {
    /// Where it acts.
    pub point: String,
    /// Force vector, N (world frame).
    pub force_n: (f64, f64),
    /// When it acts.
    #[serde(default)]
    pub when: ForceWhen,
}

/// A constant torque on a link, N·m (counter-clockwise positive).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TorqueSpec {
    /// Link it acts on.
    pub link: String,
    /// Torque, N·m.
    pub torque_n_m: f64,
}

/// What happens when an end stop is reached.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum StopAction {
    /// Motion stops there.
    #[default]
    Stop,
    /// Only recorded as an event.
    Report,
}

/// An end stop: an event when a link reaches an angle.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StopSpec {
    /// Event name.
    pub name: String,
    /// Link whose angle is watched.
    pub link: String,
    /// Angle (scene angle unit).
    pub angle: f64,
    /// Stop or report.
    #[serde(default)]
    pub action: StopAction,
}

/// Forces a scene declares; only scenes whose `models` needs them use them.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ForcesSpec {
    /// Gravity vector, m/s².
    #[serde(default)]
    pub gravity: Option<(f64, f64)>,
    /// Springs.
    #[serde(default)]
    pub springs: Vec<SpringSpec>,
    /// Dampers.
    #[serde(default)]
    pub dampers: Vec<DamperSpec>,
    /// Point forces.
    #[serde(default)]
    pub point_forces: Vec<PointForceSpec>,
    /// Torques.
    #[serde(default)]
    pub torques: Vec<TorqueSpec>,
    /// End stops.
    #[serde(default)]
    pub stops: Vec<StopSpec>,
}

/// Which kinematic solver path a scene prefers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum SolverPath {
    /// Closed form when the chain decomposes into dyads, else Newton.
    #[default]
    Auto,
    /// Closed-form Assur dyads only.
    ClosedForm,
    /// Newton–Raphson on the loop-closure constraints.
    Newton,
}

/// Solver settings in a scene.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SolverSpec {
    /// Preferred path.
    #[serde(default)]
    pub path: SolverPath,
    /// Newton tolerance on the constraint residual, as a share of the mechanism's size
    /// (its largest point distance from the origin), and in rad for a slider's turn;
    /// default 1e-14.
    #[serde(default = "default_tolerance")]
    pub tolerance: f64,
    /// Newton iteration limit.
    #[serde(default = "default_max_iterations")]
    pub max_iterations: usize,
}

fn default_tolerance() -> f64 {
    1e-14
}

fn default_max_iterations() -> usize {
    30
}

impl Default for SolverSpec {
    fn default() -> Self {
        Self {
            path: SolverPath::Auto,
            tolerance: default_tolerance(),
            max_iterations: default_max_iterations(),
        }
    }
}

/// A whole scene file (written `Scene( ... )` in RON).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Scene", deny_unknown_fields)]
pub struct SceneFile {
    /// Title shown to the user.
    pub name: String,
    /// What the scene is and where its data come from.
    #[serde(default)]
    pub description: String,
    /// Remarks a student should read (contradictions, assumptions).
    #[serde(default)]
    pub notes: Vec<String>,
    /// What the scene computes.
    pub models: Models,
    /// Unit of lengths.
    #[serde(default)]
    pub length_unit: LengthUnit,
    /// Unit of angles.
    #[serde(default)]
    pub angle_unit: AngleUnit,
    /// The links, ground first by convention.
    pub links: Vec<LinkSpec>,
    /// Prismatic joints.
    #[serde(default)]
    pub sliders: Vec<SliderSpec>,
    /// The input.
    pub driver: DriverSpec,
    /// Assembly branch per dyad, keyed by the dyad's inner joint point.
    #[serde(default, deserialize_with = "crate::unique_map::deserialize")]
    pub branches: IndexMap<String, Branch>,
    /// The main output link (for the time ratio); the last link when absent.
    #[serde(default)]
    pub output: Option<String>,
    /// Starting guesses `(x, y, angle)` per link for chains only Newton can solve.
    #[serde(default, deserialize_with = "crate::unique_map::deserialize")]
    pub guess: IndexMap<String, (f64, f64, f64)>,
    /// Force elements.
    #[serde(default)]
    pub forces: ForcesSpec,
    /// Solver settings.
    #[serde(default)]
    pub solver: SolverSpec,
    /// The motor, gear and flywheel that drive the driver (dynamics and the steady
    /// state); absent: the driver turns at its speed, or is released.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub drive: Option<DriveSpec>,
    /// Cam joints: a disc cam on one link driving a follower link.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub cams: Vec<CamJointSpec>,
}

impl SceneFile {
    /// This scene with `other`'s loads: what it models, its forces, and the mass,
    /// centroid and inertia of each of its links that `other` has by the same name.
    /// A linkage designed anew takes a paper's data (the die cutter's pressing
    /// force and die) from that paper's scene file so.
    pub fn with_loads_of(mut self, other: &SceneFile) -> Self {
        self.models = other.models;
        self.forces = other.forces.clone();
        for link in &mut self.links {
            if let Some(o) = other.links.iter().find(|o| o.name == link.name) {
                (link.mass, link.centroid, link.inertia) = (o.mass, o.centroid, o.inertia);
            }
        }
        self
    }

    /// Parses scene text. Syntax errors, unknown fields (with the fields allowed there)
    /// and keys given twice carry line and column.
    pub fn parse(text: &str) -> Result<Self> {
        ron::Options::default()
            .from_str(text)
            .map_err(|e: ron::error::SpannedError| LinkageError::SceneSyntax {
                line: e.span.start.line,
                column: e.span.start.col,
                message: e.code.to_string(),
            })
    }

    /// Writes the scene as pretty RON.
    pub fn to_ron(&self) -> Result<String> {
        ron::ser::to_string_pretty(self, ron::ser::PrettyConfig::default())
            .map_err(|e| LinkageError::from(SceneProblem::CannotWrite { why: e.to_string() }))
    }
}
