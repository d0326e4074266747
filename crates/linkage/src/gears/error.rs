//! Why a gear or a pair cannot be made, as data: the number refused, the gear it
//! belongs to and the range it must keep.

use serde::Serialize;
use thiserror::Error;

/// A gear's number, named in a refusal.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum GearParam {
    /// The module, m.
    Module,
    /// The number of teeth.
    Teeth,
    /// The pressure angle, rad.
    PressureAngle,
    /// The addendum coefficient h_a*.
    AddendumCoefficient,
    /// The clearance (dedendum) coefficient c*.
    ClearanceCoefficient,
    /// The profile shift coefficient x.
    Shift,
}

impl GearParam {
    /// The parameter in the command line's words, with its unit.
    pub fn words(self) -> &'static str {
        match self {
            Self::Module => "module (m)",
            Self::Teeth => "number of teeth",
            Self::PressureAngle => "pressure angle (rad)",
            Self::AddendumCoefficient => "addendum coefficient h_a*",
            Self::ClearanceCoefficient => "clearance coefficient c*",
            Self::Shift => "profile shift coefficient x",
        }
    }
}

/// Which gear of a pair.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Member {
    /// The first gear (the pinion, the driver).
    Pinion,
    /// The second gear (the wheel, or the ring of an internal pair).
    Wheel,
}

impl Member {
    /// The gear in the command line's words.
    pub fn words(self) -> &'static str {
        match self {
            Self::Pinion => "pinion",
            Self::Wheel => "wheel",
        }
    }
}

/// Why a gear or a pair is refused.
#[derive(Clone, Debug, Error, PartialEq, Serialize)]
pub enum GearError {
    /// A number outside its range (or not a number).
    #[error("{}: {} {value} is outside the range {min} … {max}", member.map_or("gear", Member::words), param.words())]
    OutOfRange {
        /// The gear it belongs to, where a pair is asked.
        member: Option<Member>,
        /// Which number.
        param: GearParam,
        /// The value given.
        value: f64,
        /// The least value allowed.
        min: f64,
        /// The largest value allowed.
        max: f64,
    },
    /// A shift that leaves no rim: an external gear's root circle, or an internal
    /// one's tip circle, reaches the centre.
    #[error(
        "{}: profile shift x = {shift} leaves no rim (its {} circle reaches the centre); x must be {} {limit}",
        member.map_or("gear", Member::words),
        if *internal { "tip" } else { "root" },
        if *internal { "below" } else { "above" }
    )]
    NoRim {
        /// The gear it belongs to, where a pair is asked.
        member: Option<Member>,
        /// The shift given.
        shift: f64,
        /// The bound the shift must keep: a least shift for an external gear, a
        /// largest for an internal one.
        limit: f64,
        /// Whether the gear is internal.
        internal: bool,
    },
    /// The two gears of a pair differ in module or pressure angle: they cannot mesh.
    #[error(
        "the pinion and the wheel must share the module and the pressure angle to mesh \
         (pinion: {pinion_module_m} m, {pinion_angle_rad} rad; wheel: {wheel_module_m} m, {wheel_angle_rad} rad)"
    )]
    Mismatched {
        /// The pinion's module, m.
        pinion_module_m: f64,
        /// The pinion's pressure angle, rad.
        pinion_angle_rad: f64,
        /// The wheel's module, m.
        wheel_module_m: f64,
        /// The wheel's pressure angle, rad.
        wheel_angle_rad: f64,
    },
    /// Both gears internal, or the pinion internal: a pair is two external gears or
    /// an external pinion in an internal wheel.
    #[error("a pair is two external gears or an external pinion inside an internal wheel")]
    InternalPinion,
    /// An internal wheel with no more teeth than the pinion it should hold.
    #[error(
        "the internal wheel's {wheel} teeth must be more than the pinion's {pinion} (at least {least})"
    )]
    RingTooSmall {
        /// The pinion's teeth.
        pinion: u32,
        /// The wheel's teeth.
        wheel: u32,
        /// The least number of teeth of the wheel.
        least: u32,
    },
    /// A centre distance the base circles or the teeth cannot keep.
    #[error(
        "centre distance {given_m} m is outside the range {min_m} … {max_m} m for these gears \
         (working pressure angle 0 … {max_angle_deg}°)"
    )]
    CentreDistance {
        /// The distance given, m.
        given_m: f64,
        /// The least distance, m: the base circles' (working pressure angle 0).
        min_m: f64,
        /// The largest distance, m.
        max_m: f64,
        /// The largest working pressure angle, degrees.
        max_angle_deg: f64,
    },
    /// The teeth jam at the centre distance given: they are too thick for it.
    #[error(
        "at centre distance {centre_m} m the teeth overlap by {overlap_m} m on the working \
         pitch circle: the shifts must sum to at most {shift_sum_max} (they sum to {shift_sum})"
    )]
    TeethJam {
        /// The distance given, m.
        centre_m: f64,
        /// How much the teeth overlap, m of arc on the working pitch circle.
        overlap_m: f64,
        /// The shifts' sum.
        shift_sum: f64,
        /// The largest sum of shifts the distance takes without backlash.
        shift_sum_max: f64,
    },
    /// No working pressure angle meets the shifts.
    #[error(
        "the shifts' sum {shift_sum} asks for a working pressure angle outside 0 … {max_angle_deg}°"
    )]
    NoWorkingAngle {
        /// The shifts' sum.
        shift_sum: f64,
        /// The largest working pressure angle, degrees.
        max_angle_deg: f64,
    },
}
