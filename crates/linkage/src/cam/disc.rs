//! A disc cam turning counter-clockwise about the origin and its follower: a
//! translating follower (offset from the cam's centre, moving along +y) with a knife
//! edge, a roller or a flat face, or an oscillating roller arm. From the program's
//! motion per radian of cam it gives, at each cam angle, the pitch curve (the roller
//! centre's path on the cam) and the profile, the pressure angle, and the radii of
//! curvature of both, in closed form: the contact point's path C(θ) in the frame and
//! its derivatives by θ are exact, and the cam's own frame turns them by −θ.
//!
//! With q' = C' − J C and q'' = C'' − 2 J C' − C (J turns by +90°), the pitch curve's
//! tangent is q', its outward normal J q̂' (the curve runs clockwise on the cam), and
//! its radius of curvature ρ = −|q'|³ / (q' × q''), positive where convex. A roller's
//! profile is the pitch curve moved in by the roller's radius: its radius ρ − r_r,
//! undercut where that is not positive on a convex part.

use serde::Serialize;

use super::program::{FollowerMotion, Program};
use crate::error::{LinkageError, Result};
use crate::error::{Param, Valid};
use crate::motion::Vec2;

/// What touches the cam.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum Face {
    /// A point.
    KnifeEdge,
    /// A roller of this radius, m.
    Roller {
        /// Its radius, m.
        radius_m: f64,
    },
    /// A flat face at right angles to the follower's travel (translating only).
    Flat,
}

/// The follower.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum Follower {
    /// Moves along the line x = `offset_m` (+y away from the cam).
    Translating {
        /// Its line's offset from the cam's centre, m.
        offset_m: f64,
        /// What touches the cam.
        face: Face,
    },
    /// Turns about a pivot at (`pivot_m`, 0) with an arm `arm_m` long, its roller
    /// below the line of centres; the program's displacement is the arm's angle, rad,
    /// counter-clockwise, which swings the roller away from the cam's centre.
    Oscillating {
        /// The pivot's distance from the cam's centre, m.
        pivot_m: f64,
        /// The arm, pivot to roller centre (or knife edge), m.
        arm_m: f64,
        /// What touches the cam (a knife edge or a roller).
        face: Face,
    },
}

/// A disc cam: its program, base circle and follower.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DiscCam {
    /// The follower's motion over the turn.
    pub program: Program,
    /// The base circle's radius (the profile's, where the follower is lowest), m.
    pub base_radius_m: f64,
    /// The follower.
    pub follower: Follower,
}

/// The cam and follower at one cam angle; points in the cam's own frame.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct CamPoint {
    /// Cam angle, rad.
    pub angle_rad: f64,
    /// The follower's motion there (per radian of cam).
    pub motion: FollowerMotion,
    /// The pitch curve's point (the roller's centre; the contact for a knife edge or
    /// a flat face), m.
    pub pitch_m: [f64; 2],
    /// The profile's point (where the follower touches), m.
    pub profile_m: [f64; 2],
    /// The pressure angle, rad: between the contact normal and the follower's
    /// direction of travel.
    pub pressure_angle_rad: f64,
    /// The pitch curve's radius of curvature, m (positive convex, negative concave).
    pub pitch_radius_m: f64,
    /// The profile's radius of curvature, m.
    pub profile_radius_m: f64,
}

impl CamPoint {
    /// Whether the cam passes a limit here: the pressure angle past `limit_rad`, or
    /// the profile undercut (its radius of curvature not positive where the pitch
    /// curve is convex: the roller would cut away the cam it runs on).
    pub fn past_limit(&self, limit_rad: f64) -> bool {
        self.pressure_angle_rad.abs() > limit_rad
            || (self.pitch_radius_m > 0.0 && self.profile_radius_m <= 0.0)
    }
}

/// The pitch curve where the roller's centre is, on a cam turning counter-clockwise.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Pitch {
    /// The outward normal, in the frame (away from the cam's centre where convex).
    pub(crate) outward: Vec2,
    /// The radius of curvature, m (positive convex, negative concave).
    pub(crate) radius_m: f64,
}

/// The pitch curve at a roller centre C (from the cam's centre, in the frame) and its
/// first two derivatives by the cam's angle: what the point's path leaves on the cam
/// that turns under it (see the module's documentation). Shared by the disc cam and
/// the cam joint of a mechanism, which place C differently.
pub(crate) fn pitch_on_turning_cam([c, c1, c2]: [Vec2; 3]) -> Pitch {
    let q1 = c1 - j(c);
    let q2 = c2 - j(c1) * 2.0 - c;
    let tangent = q1 / q1.norm();
    Pitch {
        outward: j(tangent),
        radius_m: -q1.norm().powi(3) / cross(q1, q2),
    }
}

/// `v` turned by +90°.
fn j(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

fn cross(a: Vec2, b: Vec2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// `v` turned by `angle`.
pub(crate) fn turn(v: Vec2, angle: f64) -> Vec2 {
    let (s, c) = angle.sin_cos();
    Vec2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

impl DiscCam {
    /// A cam of `program` with a base circle of `base_radius_m` and `follower`.
    ///
    /// # Errors
    /// A base circle, roller, offset or arm that cannot fit (named with its range).
    pub fn new(program: Program, base_radius_m: f64, follower: Follower) -> Result<Self> {
        let invalid = LinkageError::invalid;
        if !(base_radius_m.is_finite() && base_radius_m > 0.0) {
            return Err(invalid(
                Param::BaseRadius,
                base_radius_m,
                Valid::PositiveShort,
            ));
        }
        let face = match follower {
            Follower::Translating { offset_m, face } => {
                let prime = base_radius_m + roller(face);
                if !(offset_m.is_finite() && offset_m.abs() < prime) {
                    let valid = Valid::BelowPrimeCircle { prime_m: prime };
                    return Err(invalid(Param::FollowerOffset, offset_m, valid));
                }
                face
            }
            Follower::Oscillating {
                pivot_m,
                arm_m,
                face,
            } => {
                let prime = base_radius_m + roller(face);
                if matches!(face, Face::Flat) {
                    return Err(invalid(
                        Param::OscillatingFlatFace,
                        0.0,
                        Valid::KnifeOrRoller,
                    ));
                }
                if !(arm_m.is_finite()
                    && arm_m > 0.0
                    && (pivot_m - arm_m).abs() < prime
                    && prime < pivot_m + arm_m)
                {
                    let valid = Valid::ArmReachesPrime { prime_m: prime };
                    return Err(invalid(Param::FollowerArm, arm_m, valid));
                }
                face
            }
        };
        if let Face::Roller { radius_m } = face
            && !(radius_m.is_finite() && radius_m > 0.0)
        {
            return Err(invalid(Param::RollerRadius, radius_m, Valid::PositiveShort));
        }
        Ok(Self {
            program,
            base_radius_m,
            follower,
        })
    }

    /// The prime circle's radius: the base circle's plus the roller's.
    pub fn prime_radius_m(&self) -> f64 {
        let face = match self.follower {
            Follower::Translating { face, .. } | Follower::Oscillating { face, .. } => face,
        };
        self.base_radius_m + roller(face)
    }

    /// The pitch point C in the frame and its first two derivatives by θ, with the
    /// follower's direction of travel there.
    pub(super) fn pitch_point(&self, m: &FollowerMotion) -> ([Vec2; 3], Vec2) {
        let rp = self.prime_radius_m();
        match self.follower {
            Follower::Translating {
                face: Face::Flat, ..
            } => {
                // The face touches where its normal through the contact meets the
                // cam's centre's line: x = ds/dθ, at height r_b + s.
                let c = Vec2::new(m.v, rp + m.s);
                let c1 = Vec2::new(m.a, m.v);
                let c2 = Vec2::new(m.j, m.a);
                ([c, c1, c2], Vec2::y())
            }
            Follower::Translating { offset_m: e, .. } => {
                let s0 = (rp * rp - e * e).sqrt();
                let c = Vec2::new(e, s0 + m.s);
                ([c, Vec2::new(0.0, m.v), Vec2::new(0.0, m.a)], Vec2::y())
            }
            Follower::Oscillating { pivot_m, arm_m, .. } => {
                let pivot = Vec2::new(pivot_m, 0.0);
                // The roller below the line of centres at zero lift, so that a lift
                // (counter-clockwise) swings it away from the cam's centre: the
                // distance² p² + l² + 2pl·cos γ grows as γ rises to 0.
                let gamma0 = -((rp * rp - pivot_m * pivot_m - arm_m * arm_m)
                    / (2.0 * pivot_m * arm_m))
                    .clamp(-1.0, 1.0)
                    .acos();
                let g = gamma0 + m.s;
                let u = Vec2::new(g.cos(), g.sin());
                let c = pivot + u * arm_m;
                let c1 = j(u) * (arm_m * m.v);
                let c2 = j(u) * (arm_m * m.a) - u * (arm_m * m.v * m.v);
                ([c, c1, c2], j(u))
            }
        }
    }

    /// The cam and follower at cam angle `theta`.
    pub fn at(&self, theta: f64) -> CamPoint {
        let m = self.program.at(theta);
        let ([c, c1, c2], travel) = self.pitch_point(&m);
        let Pitch {
            outward,
            radius_m: pitch_radius,
        } = pitch_on_turning_cam([c, c1, c2]);
        let (profile, profile_radius, normal) = match self.face() {
            Face::Roller { radius_m } => (c - outward * radius_m, pitch_radius - radius_m, outward),
            Face::KnifeEdge => (c, pitch_radius, outward),
            // The flat face: C is the contact itself and the normal is the face's.
            Face::Flat => (c, self.base_radius_m + m.s + m.a, Vec2::y()),
        };
        // The angle between the normal's line and the travel, in (−90°, 90°]: the
        // normal's sense does not matter.
        let pressure = (cross(travel, normal) / normal.dot(&travel)).atan();
        CamPoint {
            angle_rad: theta,
            motion: m,
            pitch_m: vec_of(turn(c, -theta)),
            profile_m: vec_of(turn(profile, -theta)),
            pressure_angle_rad: pressure,
            pitch_radius_m: pitch_radius,
            profile_radius_m: profile_radius,
        }
    }

    pub(super) fn face(&self) -> Face {
        match self.follower {
            Follower::Translating { face, .. } | Follower::Oscillating { face, .. } => face,
        }
    }
}

fn vec_of(v: Vec2) -> [f64; 2] {
    [v.x, v.y]
}

fn roller(face: Face) -> f64 {
    match face {
        Face::Roller { radius_m } => radius_m,
        _ => 0.0,
    }
}
