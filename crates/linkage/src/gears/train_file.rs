//! A gear train as data: the file a user writes (RON, `assets/trains/*.ron`) and
//! the names in it. Members are the bodies that turn (shafts with their gears, a
//! planet, a carrier, a ring); each turns about an axis held by the frame or by a
//! carrier; gears are fixed to members; meshes pair two gears; belt and chain stages
//! pair two members by a ratio; inputs give members' speeds (a brake is an input of
//! 0 rpm). Documented in docs/trains.md.

use serde::{Deserialize, Serialize};

/// The frame's name: the member every fixed axis is held by.
pub const FRAME: &str = "frame";

/// Whether `name` is the frame's.
pub fn is_frame(name: &str) -> bool {
    name == FRAME
}

/// A train file (its default: no members, which `Train::new` refuses).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TrainFile {
    /// What the train is.
    pub name: String,
    /// A note (where the numbers come from).
    #[serde(default)]
    pub notes: String,
    /// The module for the planetary assembly checks, mm (one for the whole train);
    /// the checks in modules where absent.
    #[serde(default)]
    pub module_mm: Option<f64>,
    /// The bodies that turn.
    pub members: Vec<MemberFile>,
    /// The gears, each fixed to a member.
    #[serde(default)]
    pub gears: Vec<GearFile>,
    /// Pairs of gears in mesh, by name.
    #[serde(default)]
    pub meshes: Vec<(String, String)>,
    /// Every mesh's efficiency (0.97 to 0.99 for cut spur gears), for the torques;
    /// ideal (1) where absent. The speeds do not depend on it.
    #[serde(default)]
    pub mesh_efficiency: Option<f64>,
    /// Belt and chain stages between members.
    #[serde(default)]
    pub stages: Vec<StageFile>,
    /// Members' speeds given, rpm: as many as the train's degrees of freedom.
    #[serde(default)]
    pub inputs: Vec<InputFile>,
}

impl TrainFile {
    /// A train file's text read (its names and numbers are checked by
    /// [`super::Train::new`]).
    ///
    /// # Errors
    /// Text that is not a train file: the parser's message, with its line and column.
    pub fn from_ron(text: &str) -> Result<Self, ron::error::SpannedError> {
        ron::from_str(text)
    }
}

/// A body that turns.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MemberFile {
    /// Its name.
    pub name: String,
    /// The member that holds its axis: the frame (by default) or a carrier.
    #[serde(default = "frame")]
    pub axis_on: String,
    /// On a carrier: how many planets it carries, equally spaced (for the assembly
    /// checks; the speeds do not depend on it).
    #[serde(default)]
    pub planets: Option<u32>,
    /// Its moment of inertia about its axis, kg·m² (for the inertia reduced to a
    /// member).
    #[serde(default)]
    pub inertia_kg_m2: f64,
}

fn frame() -> String {
    FRAME.to_string()
}

/// A gear fixed to a member.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GearFile {
    /// Its name.
    pub name: String,
    /// The member it is fixed to.
    pub member: String,
    /// Its number of teeth.
    pub teeth: u32,
    /// Whether its teeth are internal (a ring).
    #[serde(default)]
    pub internal: bool,
}

/// A belt or chain stage: `from` turns `ratio` times as fast as `to`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StageFile {
    /// Belt or chain.
    pub kind: StageKind,
    /// The driving member.
    pub from: String,
    /// The driven member.
    pub to: String,
    /// ω_from / ω_to (the driven pulley's or sprocket's size over the driver's).
    pub ratio: f64,
    /// A crossed belt turns the driven member the other way.
    #[serde(default)]
    pub crossed: bool,
    /// Its efficiency (a V-belt about 0.96, a roller chain 0.97), for the torques;
    /// ideal (1) where absent.
    #[serde(default)]
    pub efficiency: Option<f64>,
}

/// What a stage is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum StageKind {
    /// A belt (V-belt, flat belt, toothed belt).
    Belt,
    /// A roller chain.
    Chain,
}

/// A member's speed given.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InputFile {
    /// The member.
    pub member: String,
    /// Its speed, rpm (positive counter-clockwise seen from the front).
    pub rpm: f64,
}
