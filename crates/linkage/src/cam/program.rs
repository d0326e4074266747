//! A cam program: segments over the cam's turn — a rise by a law, a dwell, a return
//! by a law — their follower motion at any cam angle (displacement, velocity,
//! acceleration and jerk per radian of cam), the continuity class at every join, and
//! each law's peak coefficients C_v, C_a, C_j.

use serde::Serialize;

use super::laws::{Law, Motion};
use crate::error::{LinkageError, Result};
use crate::error::{Param, Valid};

const TAU: f64 = std::f64::consts::TAU;

/// What a segment does.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum SegmentKind {
    /// The follower rises by `lift` with a law.
    Rise {
        /// The law.
        law: Law,
        /// The rise (m, or rad for an oscillating follower).
        lift: f64,
    },
    /// The follower stands still.
    Dwell,
    /// The follower returns by `lift` with a law.
    Return {
        /// The law.
        law: Law,
        /// The fall.
        lift: f64,
    },
}

/// One segment of a program.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Segment {
    /// What it does.
    pub kind: SegmentKind,
    /// The cam angle it takes, rad.
    pub angle_rad: f64,
}

/// The follower's motion at one cam angle: per radian of cam (multiply by ω, ω², ω³
/// for time derivatives at a constant cam speed ω).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct FollowerMotion {
    /// Displacement from the lowest position.
    pub s: f64,
    /// ds/dθ.
    pub v: f64,
    /// d²s/dθ².
    pub a: f64,
    /// d³s/dθ³.
    pub j: f64,
}

/// How smooth the motion is at a join: the first derivative that jumps there.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
pub enum Continuity {
    /// The displacement itself jumps (a program that does not close).
    Broken,
    /// Displacement continuous, velocity jumps (infinite acceleration).
    C0,
    /// Velocity continuous, acceleration jumps (infinite jerk).
    C1,
    /// Acceleration continuous, jerk jumps.
    C2,
    /// Jerk continuous too.
    C3,
}

/// The continuity at one join.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Join {
    /// The cam angle of the join, rad (0 is the program's start, where its end
    /// meets it).
    pub angle_rad: f64,
    /// The segment ending there (the last one at angle 0).
    pub before: usize,
    /// The segment starting there.
    pub after: usize,
    /// The class.
    pub continuity: Continuity,
    /// The jumps of s, v, a and j there (after − before), per radian of cam.
    pub jumps: [f64; 4],
}

/// A program over the cam's turn.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Program {
    segments: Vec<Segment>,
    /// Start angle of each segment, rad.
    starts: Vec<f64>,
    /// The displacement each segment starts from.
    bases: Vec<f64>,
}

impl Program {
    /// A program of `segments`, which must take the whole turn (2π to 1e-9) with
    /// positive angles and finite, positive lifts.
    ///
    /// # Errors
    /// An empty program, an angle or lift out of range, or angles that do not add up
    /// to a turn (named with the sum).
    pub fn new(segments: Vec<Segment>) -> Result<Self> {
        let invalid = LinkageError::invalid;
        if segments.is_empty() {
            return Err(invalid(Param::Segments, 0.0, Valid::AtLeastOne));
        }
        let mut starts = Vec::with_capacity(segments.len());
        let mut bases = Vec::with_capacity(segments.len());
        let (mut at, mut base) = (0.0, 0.0);
        for (i, seg) in segments.iter().enumerate() {
            if !(seg.angle_rad.is_finite() && seg.angle_rad > 0.0) {
                let param = Param::SegmentAngle(i);
                return Err(invalid(param, seg.angle_rad, Valid::PositiveShort));
            }
            if let SegmentKind::Rise { lift, .. } | SegmentKind::Return { lift, .. } = seg.kind
                && !(lift.is_finite() && lift > 0.0)
            {
                return Err(invalid(Param::SegmentLift(i), lift, Valid::PositiveShort));
            }
            starts.push(at);
            bases.push(base);
            at += seg.angle_rad;
            base += match seg.kind {
                SegmentKind::Rise { lift, .. } => lift,
                SegmentKind::Return { lift, .. } => -lift,
                SegmentKind::Dwell => 0.0,
            };
        }
        if (at - TAU).abs() > 1e-9 * TAU {
            return Err(invalid(Param::SegmentAngleSum, at, Valid::OneTurn));
        }
        Ok(Self {
            segments,
            starts,
            bases,
        })
    }

    /// The segments.
    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }

    /// Each segment's cam angles, (start, end), rad.
    pub fn spans(&self) -> Vec<(f64, f64)> {
        self.starts
            .iter()
            .zip(&self.segments)
            .map(|(&start, seg)| (start, start + seg.angle_rad))
            .collect()
    }

    /// The largest lift of its rises and returns.
    pub fn largest_lift(&self) -> f64 {
        self.segments
            .iter()
            .map(|s| match s.kind {
                SegmentKind::Rise { lift, .. } | SegmentKind::Return { lift, .. } => lift,
                SegmentKind::Dwell => 0.0,
            })
            .fold(0.0, f64::max)
    }

    /// The follower's motion at cam angle `theta` (rad, any turn).
    pub fn at(&self, theta: f64) -> FollowerMotion {
        let t = theta.rem_euclid(TAU);
        let i = self.starts.iter().rposition(|&s| s <= t).unwrap_or(0);
        self.in_segment(i, t - self.starts[i])
    }

    /// The motion `x` rad into segment `i`.
    fn in_segment(&self, i: usize, x: f64) -> FollowerMotion {
        let seg = &self.segments[i];
        let beta = seg.angle_rad;
        let (law, lift, sign) = match seg.kind {
            SegmentKind::Dwell => {
                return FollowerMotion {
                    s: self.bases[i],
                    ..FollowerMotion::default()
                };
            }
            SegmentKind::Rise { law, lift } => (law, lift, 1.0),
            SegmentKind::Return { law, lift } => (law, lift, -1.0),
        };
        let m: Motion = law.at(x / beta);
        FollowerMotion {
            s: self.bases[i] + sign * lift * m.s,
            v: sign * lift * m.v / beta,
            a: sign * lift * m.a / beta.powi(2),
            j: sign * lift * m.j / beta.powi(3),
        }
    }

    /// The continuity at every join, the turn's closing join (angle 0) first.
    pub fn joins(&self) -> Vec<Join> {
        let n = self.segments.len();
        (0..n)
            .map(|after| {
                let before = (after + n - 1) % n;
                let left = self.in_segment(before, self.segments[before].angle_rad);
                let right = self.in_segment(after, 0.0);
                let jumps = [
                    right.s - left.s,
                    right.v - left.v,
                    right.a - left.a,
                    right.j - left.j,
                ];
                Join {
                    angle_rad: self.starts[after],
                    before,
                    after,
                    continuity: self.class(&jumps),
                    jumps,
                }
            })
            .collect()
    }

    /// The class of a join's jumps, each compared with its own scale: the largest
    /// lift over the shortest segment's angle to the derivative's power.
    fn class(&self, jumps: &[f64; 4]) -> Continuity {
        let lift = self
            .bases
            .iter()
            .fold(0.0_f64, |m, b| m.max(b.abs()))
            .max(self.largest_lift());
        let shortest = self
            .segments
            .iter()
            .map(|s| s.angle_rad)
            .fold(f64::INFINITY, f64::min);
        let classes = [
            Continuity::Broken,
            Continuity::C0,
            Continuity::C1,
            Continuity::C2,
        ];
        for (d, class) in classes.into_iter().enumerate() {
            let scale = lift / shortest.powi(d as i32);
            if jumps[d].abs() > 1e-9 * scale {
                return class;
            }
        }
        Continuity::C3
    }
}

/// A law's peak coefficients: the largest |v|, |a| and |j| of its normalised rise.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PeakCoefficients {
    /// C_v.
    pub velocity: f64,
    /// C_a.
    pub acceleration: f64,
    /// C_j.
    pub jerk: f64,
}

/// Samples over [0, 1] for the peaks: where a peak falls between samples the
/// error is of the order of the step squared times the curvature (about 1e-9 here).
const PEAK_SAMPLES: usize = 40_001;

/// `law`'s peak coefficients over its rise (impulses at its ends aside: the
/// constant-velocity law's infinite acceleration is its joins', see [`Program::joins`]).
pub fn peak_coefficients(law: Law) -> PeakCoefficients {
    let mut p = PeakCoefficients {
        velocity: 0.0,
        acceleration: 0.0,
        jerk: 0.0,
    };
    for i in 0..PEAK_SAMPLES {
        let m = law.at(i as f64 / (PEAK_SAMPLES - 1) as f64);
        p.velocity = p.velocity.max(m.v.abs());
        p.acceleration = p.acceleration.max(m.a.abs());
        p.jerk = p.jerk.max(m.j.abs());
    }
    p
}
