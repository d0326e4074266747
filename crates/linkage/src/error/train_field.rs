//! Where in a train file a refused name or number stands, as data: the refusal's
//! words (English here, both languages in `linkage-diagram`'s refusals) are made
//! from it, with the file's own keys as written there so that the reader finds them.

use serde::Serialize;

/// Where in a train file a name or a number is given.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub enum TrainField {
    /// A member's `axis_on`.
    AxisOn {
        /// The member.
        member: String,
    },
    /// A member's `inertia_kg_m2`.
    Inertia {
        /// The member.
        member: String,
    },
    /// A gear's `member`.
    GearMember {
        /// The gear.
        gear: String,
    },
    /// A gear's `teeth`.
    Teeth {
        /// The gear.
        gear: String,
    },
    /// A mesh of two gears.
    Mesh {
        /// One gear's name as written.
        a: String,
        /// The other's.
        b: String,
    },
    /// A stage's `from`.
    StageFrom {
        /// The stage's driving member as written.
        from: String,
        /// Its driven member as written.
        to: String,
    },
    /// A stage's `to`.
    StageTo {
        /// The stage's driving member as written.
        from: String,
        /// Its driven member as written.
        to: String,
    },
    /// The file's `mesh_efficiency`.
    MeshEfficiency,
    /// A stage's `efficiency`.
    StageEfficiency {
        /// The stage's driving member.
        from: String,
        /// Its driven member.
        to: String,
    },
    /// A stage's `ratio`.
    StageRatio {
        /// The stage's driving member.
        from: String,
        /// Its driven member.
        to: String,
    },
    /// An input's `member`.
    Input {
        /// The member as written.
        member: String,
    },
    /// An input given on the frame (which does not turn).
    InputOnFrame,
    /// An input's `rpm`.
    InputRpm {
        /// The member.
        member: String,
    },
    /// The load put on a member (`linkage train --load`).
    Load,
}

/// Whose field a [`TrainField`] is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FieldOwner<'a> {
    /// A member, by name.
    Member(&'a str),
    /// A gear, by name.
    Gear(&'a str),
    /// A mesh of two gears, by their names as written.
    Mesh(&'a str, &'a str),
    /// A belt or chain stage, by its driving and driven members.
    Stage(&'a str, &'a str),
    /// The input on a member.
    Input(&'a str),
    /// An input given on the frame.
    InputOnFrame,
    /// The file itself: a key at its top level.
    File,
    /// The load put on a member (`linkage train --load`).
    Load,
}

impl TrainField {
    /// Whose field this is.
    pub fn owner(&self) -> FieldOwner<'_> {
        match self {
            Self::AxisOn { member } | Self::Inertia { member } => FieldOwner::Member(member),
            Self::GearMember { gear } | Self::Teeth { gear } => FieldOwner::Gear(gear),
            Self::Mesh { a, b } => FieldOwner::Mesh(a, b),
            Self::StageFrom { from, to }
            | Self::StageTo { from, to }
            | Self::StageRatio { from, to }
            | Self::StageEfficiency { from, to } => FieldOwner::Stage(from, to),
            Self::Input { member } | Self::InputRpm { member } => FieldOwner::Input(member),
            Self::InputOnFrame => FieldOwner::InputOnFrame,
            Self::MeshEfficiency => FieldOwner::File,
            Self::Load => FieldOwner::Load,
        }
    }

    /// The field's key as written in the train file, so that the reader finds it;
    /// none where the field is its owner itself (a mesh, an input's member, the load).
    pub fn key(&self) -> Option<&'static str> {
        Some(match self {
            Self::AxisOn { .. } => "axis_on",
            Self::Inertia { .. } => "inertia_kg_m2",
            Self::GearMember { .. } => "member",
            Self::Teeth { .. } => "teeth",
            Self::StageFrom { .. } => "from",
            Self::StageTo { .. } => "to",
            Self::StageRatio { .. } => "ratio",
            Self::StageEfficiency { .. } => "efficiency",
            Self::MeshEfficiency => "mesh_efficiency",
            Self::InputRpm { .. } => "rpm",
            Self::Mesh { .. } | Self::Input { .. } | Self::InputOnFrame | Self::Load => {
                return None;
            }
        })
    }
}

impl std::fmt::Display for TrainField {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.owner() {
            FieldOwner::Member(member) => write!(f, "member {member}")?,
            FieldOwner::Gear(gear) => write!(f, "gear {gear}")?,
            FieldOwner::Mesh(a, b) => write!(f, "mesh ({a}, {b})")?,
            FieldOwner::Stage(from, to) => write!(f, "stage {from} → {to}")?,
            FieldOwner::Input(member) => write!(f, "input on {member}")?,
            FieldOwner::InputOnFrame => f.write_str("an input")?,
            FieldOwner::Load => f.write_str("the load")?,
            FieldOwner::File => {}
        }
        match (self.owner(), self.key()) {
            (FieldOwner::File, Some(key)) => f.write_str(key),
            (_, Some(key)) => write!(f, "'s {key}"),
            (_, None) => Ok(()),
        }
    }
}

/// What a name must be one of.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum NameKind {
    /// The train's members (the frame among them).
    Members,
    /// The train's gears.
    Gears,
    /// The members that turn: not the frame (a member held still is an input of 0).
    TurningMembers,
}

impl std::fmt::Display for NameKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Members => "members",
            Self::Gears => "gears",
            Self::TurningMembers => "members that turn (a member held still is an input of 0 rpm)",
        })
    }
}
