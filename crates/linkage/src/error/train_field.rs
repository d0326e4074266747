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

impl std::fmt::Display for TrainField {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::AxisOn { member } => write!(f, "member {member}'s axis_on"),
            Self::Inertia { member } => write!(f, "member {member}'s inertia_kg_m2"),
            Self::GearMember { gear } => write!(f, "gear {gear}'s member"),
            Self::Teeth { gear } => write!(f, "gear {gear}'s teeth"),
            Self::Mesh { a, b } => write!(f, "mesh ({a}, {b})"),
            Self::StageFrom { from, to } => write!(f, "stage {from} → {to}'s from"),
            Self::StageTo { from, to } => write!(f, "stage {from} → {to}'s to"),
            Self::StageRatio { from, to } => write!(f, "stage {from} → {to}'s ratio"),
            Self::MeshEfficiency => write!(f, "mesh_efficiency"),
            Self::StageEfficiency { from, to } => write!(f, "stage {from} → {to}'s efficiency"),
            Self::Input { member } => write!(f, "input on {member}"),
            Self::InputOnFrame => write!(f, "an input"),
            Self::InputRpm { member } => write!(f, "input on {member}'s rpm"),
            Self::Load => write!(f, "the load"),
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
