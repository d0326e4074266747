//! What a gear train gives and why it is refused, as data (a leaf under the train's
//! solve, its rows and its assembly checks).

use serde::Serialize;
use thiserror::Error;

/// Why a train is refused.
#[derive(Clone, Debug, Error, PartialEq, Serialize)]
pub enum TrainError {
    /// A name used but not defined.
    #[error("{what} names `{name}`, which is not one of the train's {kind}")]
    Unknown {
        /// Where the name is used ("gear z1's member").
        what: String,
        /// The name.
        name: String,
        /// "members" or "gears".
        kind: &'static str,
    },
    /// A name defined twice.
    #[error("`{name}` is defined twice")]
    Duplicate {
        /// The name.
        name: String,
    },
    /// A number outside its range.
    #[error("{what} {value} is outside the range {min} … {max}")]
    OutOfRange {
        /// Which number ("gear z1's teeth").
        what: String,
        /// The value.
        value: f64,
        /// The least allowed.
        min: f64,
        /// The largest allowed.
        max: f64,
    },
    /// Two gears in mesh whose axes are held by members that turn apart.
    #[error(
        "gears `{a}` and `{b}` cannot mesh: their axes are held by `{a_axis}` and `{b_axis}`, \
         which keep no fixed distance (a planet's axis is held by its carrier, and meshes \
         with gears on the carrier's axis)"
    )]
    AxesApart {
        /// One gear.
        a: String,
        /// The other.
        b: String,
        /// The member holding the first's axis.
        a_axis: String,
        /// The member holding the other's.
        b_axis: String,
    },
    /// An internal gear with no more teeth than the external gear it meshes with.
    #[error(
        "internal gear `{ring}` ({ring_teeth} teeth) must have more teeth than `{mate}` ({mate_teeth}) inside it"
    )]
    RingTooSmall {
        /// The internal gear.
        ring: String,
        /// Its teeth.
        ring_teeth: u32,
        /// The external gear inside it.
        mate: String,
        /// Its teeth.
        mate_teeth: u32,
    },
    /// A train with no member that turns.
    #[error("a train needs at least one member that turns")]
    NoMembers,
    /// Two internal gears in mesh.
    #[error(
        "gears `{a}` and `{b}` are both internal: an internal gear meshes with an external one"
    )]
    BothInternal {
        /// One gear.
        a: String,
        /// The other.
        b: String,
    },
    /// Not as many inputs as the train's degrees of freedom.
    #[error("the train has {dof} degree(s) of freedom: give {dof} input speed(s) ({given} given)")]
    Inputs {
        /// The degrees of freedom.
        dof: usize,
        /// The inputs given.
        given: usize,
    },
    /// The inputs fix some members twice and others not at all, or contradict the
    /// meshes (two inputs on members the gears tie together).
    #[error(
        "the inputs do not fix the train: `{member}` is left free or tied to another input; \
         give the inputs on members the gears do not tie together"
    )]
    InputsTied {
        /// A member the inputs leave undetermined or over-determined.
        member: String,
    },
}

/// A converted-train (Willis) ratio: with the carrier held, `from` turns `ratio`
/// times as fast as `to`: (ω_from − ω_H)/(ω_to − ω_H).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct WillisRatio {
    /// The carrier H.
    pub carrier: String,
    /// One central member.
    pub from: String,
    /// The other.
    pub to: String,
    /// i^H_from,to.
    pub ratio: f64,
}

/// A planetary set's assembly condition.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum AssemblyCheck {
    /// Each planet meets every central gear it meshes with at one distance from the
    /// carrier's axis (in modules): coaxiality.
    Coaxial {
        /// The carrier.
        carrier: String,
        /// The distances found, modules (one value: coaxial).
        distances_modules: Vec<f64>,
        /// Whether they are one.
        holds: bool,
    },
    /// Equally spaced planets fit: (z_sun + z_ring)/k is a whole number.
    EqualSpacing {
        /// The carrier.
        carrier: String,
        /// The planets k.
        planets: u32,
        /// (z_sun + z_ring)/k.
        value: f64,
        /// Whether it is whole.
        holds: bool,
    },
    /// Neighbouring planets clear each other's tips: (z_s + z_p) sin(π/k) > z_p + 2
    /// (h_a* = 1), the clearance in modules.
    Neighbours {
        /// The carrier.
        carrier: String,
        /// The planets k.
        planets: u32,
        /// The gap between neighbouring tip circles, modules.
        clearance_modules: f64,
        /// Whether it is positive.
        holds: bool,
    },
}

/// A member's speed.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MemberSpeed {
    /// The member.
    pub member: String,
    /// Its speed, rpm (positive counter-clockwise seen from the front).
    pub rpm: f64,
}

/// A train solved.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TrainSolution {
    /// The train's name.
    pub name: String,
    /// Its degrees of freedom.
    pub dof: usize,
    /// Every member's speed, in the file's order.
    pub speeds_rpm: Vec<MemberSpeed>,
    /// The converted-train ratios of each carrier's central members.
    pub willis: Vec<WillisRatio>,
    /// The planetary sets' assembly conditions.
    pub assembly: Vec<AssemblyCheck>,
}

impl TrainSolution {
    /// A member's speed, rpm.
    pub fn speed_rpm(&self, member: &str) -> Option<f64> {
        self.speeds_rpm
            .iter()
            .find(|s| s.member == member)
            .map(|s| s.rpm)
    }

    /// The ratio ω_a / ω_b.
    pub fn ratio(&self, a: &str, b: &str) -> Option<f64> {
        Some(self.speed_rpm(a)? / self.speed_rpm(b)?)
    }
}
