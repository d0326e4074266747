//! What a gear train gives, as data (a leaf under the train's solve, its rows and
//! its assembly checks); why one is refused is `crate::error::TrainError`.

use serde::Serialize;

pub use crate::error::TrainError;

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
