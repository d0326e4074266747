//! A cam file (RON): the program in millimetres and degrees, the base circle, the
//! follower and the cam's speed, read strictly (unknown fields refused) and turned
//! into a [`DiscCam`] in SI with every number checked.
//!
//! ```ron
//! Cam(
//!     name: "Roller cam",
//!     base_radius_mm: 40.0,
//!     follower: Translating(offset_mm: 8.0, face: Roller(radius_mm: 10.0)),
//!     rpm: 60.0,
//!     segments: [
//!         Rise(law: Cycloidal, lift: 20.0, deg: 120.0),
//!         Dwell(deg: 60.0),
//!         Return(law: ModifiedSine, lift: 20.0, deg: 100.0),
//!         Dwell(deg: 80.0),
//!     ],
//! )
//! ```
//!
//! A lift is in millimetres for a translating follower and in degrees for an
//! oscillating one.

use serde::{Deserialize, Serialize};

use super::disc::{DiscCam, Face, Follower};
use super::laws::Law;
use super::program::{Program, Segment, SegmentKind};
use crate::error::{LinkageError, Result};
use crate::error::{Param, Valid};

/// What touches the cam, in millimetres.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum FaceSpec {
    /// A point.
    KnifeEdge,
    /// A roller.
    Roller {
        /// Its radius, mm.
        radius_mm: f64,
    },
    /// A flat face at right angles to the travel.
    Flat,
}

/// The follower, in millimetres.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum FollowerSpec {
    /// Along a line offset from the cam's centre.
    Translating {
        /// The offset, mm.
        offset_mm: f64,
        /// What touches the cam.
        face: FaceSpec,
    },
    /// An arm about a pivot.
    Oscillating {
        /// The pivot's distance from the cam's centre, mm.
        pivot_mm: f64,
        /// The arm, mm.
        arm_mm: f64,
        /// What touches the cam.
        face: FaceSpec,
    },
}

/// One segment, in degrees of cam (and millimetres or degrees of lift).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum SegmentSpec {
    /// A rise.
    Rise {
        /// Its law.
        law: Law,
        /// Its lift (mm, or degrees of an oscillating arm).
        lift: f64,
        /// Its cam angle, degrees.
        deg: f64,
    },
    /// A dwell.
    Dwell {
        /// Its cam angle, degrees.
        deg: f64,
    },
    /// A return.
    Return {
        /// Its law.
        law: Law,
        /// Its fall (mm, or degrees of an oscillating arm).
        lift: f64,
        /// Its cam angle, degrees.
        deg: f64,
    },
}

impl SegmentSpec {
    /// Its cam angle, degrees.
    pub fn angle_deg(&self) -> f64 {
        match *self {
            Self::Rise { deg, .. } | Self::Dwell { deg } | Self::Return { deg, .. } => deg,
        }
    }

    /// Its cam angle, to change.
    pub fn angle_deg_mut(&mut self) -> &mut f64 {
        match self {
            Self::Rise { deg, .. } | Self::Dwell { deg } | Self::Return { deg, .. } => deg,
        }
    }

    /// The lift of a rise or return (none for a dwell).
    pub fn lift(&self) -> Option<f64> {
        match *self {
            Self::Rise { lift, .. } | Self::Return { lift, .. } => Some(lift),
            Self::Dwell { .. } => None,
        }
    }

    /// The lift of a rise or return, to change.
    pub fn lift_mut(&mut self) -> Option<&mut f64> {
        match self {
            Self::Rise { lift, .. } | Self::Return { lift, .. } => Some(lift),
            Self::Dwell { .. } => None,
        }
    }

    /// The law of a rise or return (none for a dwell).
    pub fn law(&self) -> Option<Law> {
        match *self {
            Self::Rise { law, .. } | Self::Return { law, .. } => Some(law),
            Self::Dwell { .. } => None,
        }
    }

    /// The law of a rise or return, to change.
    pub fn law_mut(&mut self) -> Option<&mut Law> {
        match self {
            Self::Rise { law, .. } | Self::Return { law, .. } => Some(law),
            Self::Dwell { .. } => None,
        }
    }
}

/// A cam file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Cam", deny_unknown_fields)]
pub struct CamSpec {
    /// Its name.
    pub name: String,
    /// The base circle's radius, mm.
    pub base_radius_mm: f64,
    /// The follower.
    pub follower: FollowerSpec,
    /// The cam's speed, rpm (counter-clockwise positive).
    pub rpm: f64,
    /// The program over a turn.
    pub segments: Vec<SegmentSpec>,
}

/// A cam file's cam in SI, with its speed.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CamDesign {
    /// Its name.
    pub name: String,
    /// The cam.
    pub cam: DiscCam,
    /// Its speed, rad/s.
    pub speed_rad_s: f64,
}

impl CamSpec {
    /// Reads a cam file.
    ///
    /// # Errors
    /// A syntax error (with its line and column) or a value out of range (named).
    pub fn from_ron(text: &str) -> Result<Self> {
        ron::from_str(text).map_err(|e| LinkageError::SceneSyntax {
            line: e.span.start.line,
            column: e.span.start.col,
            message: e.code.to_string(),
        })
    }

    /// The cam in SI.
    ///
    /// # Errors
    /// A speed, size or program out of range, named with the valid range.
    pub fn design(&self) -> Result<CamDesign> {
        let mm = 1e-3;
        let oscillating = matches!(self.follower, FollowerSpec::Oscillating { .. });
        let lift_unit = if oscillating { 1f64.to_radians() } else { mm };
        let segments = segments_of(&self.segments, lift_unit);
        let face = |f: FaceSpec| match f {
            FaceSpec::KnifeEdge => Face::KnifeEdge,
            FaceSpec::Roller { radius_mm } => Face::Roller {
                radius_m: radius_mm * mm,
            },
            FaceSpec::Flat => Face::Flat,
        };
        let follower = match self.follower {
            FollowerSpec::Translating { offset_mm, face: f } => Follower::Translating {
                offset_m: offset_mm * mm,
                face: face(f),
            },
            FollowerSpec::Oscillating {
                pivot_mm,
                arm_mm,
                face: f,
            } => Follower::Oscillating {
                pivot_m: pivot_mm * mm,
                arm_m: arm_mm * mm,
                face: face(f),
            },
        };
        if !(self.rpm.is_finite() && self.rpm != 0.0) {
            return Err(LinkageError::invalid(
                Param::CamRpm,
                self.rpm,
                Valid::NotZeroShort,
            ));
        }
        let cam = DiscCam::new(Program::new(segments)?, self.base_radius_mm * mm, follower)?;
        Ok(CamDesign {
            name: self.name.clone(),
            cam,
            speed_rad_s: self.rpm * std::f64::consts::TAU / 60.0,
        })
    }
}

/// The segments in SI: angles from degrees, lifts times `lift_unit` (metres or
/// radians per unit of the file's lifts).
pub(crate) fn segments_of(specs: &[SegmentSpec], lift_unit: f64) -> Vec<Segment> {
    specs
        .iter()
        .map(|s| match *s {
            SegmentSpec::Rise { law, lift, deg } => Segment {
                kind: SegmentKind::Rise {
                    law,
                    lift: lift * lift_unit,
                },
                angle_rad: deg.to_radians(),
            },
            SegmentSpec::Dwell { deg } => Segment {
                kind: SegmentKind::Dwell,
                angle_rad: deg.to_radians(),
            },
            SegmentSpec::Return { law, lift, deg } => Segment {
                kind: SegmentKind::Return {
                    law,
                    lift: lift * lift_unit,
                },
                angle_rad: deg.to_radians(),
            },
        })
        .collect()
}
