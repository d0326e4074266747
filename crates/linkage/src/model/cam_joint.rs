//! A cam joint of the mechanism: a disc cam on a link pinned to ground drives a
//! follower (an arm pinned to ground, or a slider on a ground guide) through a
//! roller. The follower's coordinate is the program's lift at the cam's angle, so
//! the follower is placed as soon as the cam's link is; the profile is what the
//! roller's path leaves on the turning cam.

use nalgebra::UnitComplex;

use crate::cam::{CamPoint, FollowerMotion, Program, pitch_on_turning_cam, turn};
use crate::ids::{LinkId, PointId};
use crate::model::Prismatic;
use crate::motion::{LinkMotion, PointMotion, Vec2, perp};
use crate::real::{Real, splat, splat_vec};

/// How the follower is guided on the frame.
#[derive(Clone, Debug, PartialEq)]
pub enum FollowerGuide {
    /// An arm about its ground pin; its coordinate is its angle, rad.
    Arm {
        /// Index into `Mechanism::revolutes` of the pin.
        pivot: usize,
        /// The pin in the world, m.
        pivot_world: Vec2,
        /// The pin in the follower's coordinates, m.
        pivot_on_follower: Vec2,
    },
    /// A slider on a ground guide; its coordinate is its travel along the guide from
    /// the guide's `through` point, m.
    Slide {
        /// Index into `Mechanism::sliders`.
        slider: usize,
        /// The guide's point in the world, m.
        through_world: Vec2,
        /// The guide's unit direction in the world.
        direction: Vec2,
        /// The slider's point in its own coordinates, m.
        slider_local: Vec2,
        /// The follower's fixed rotation.
        rotation: UnitComplex<f64>,
    },
}

/// A cam joint: the cam's link, the follower, its roller and the program.
#[derive(Clone, Debug, PartialEq)]
pub struct CamJoint {
    /// Display name, `cam/follower`.
    pub name: String,
    /// The link that carries the cam.
    pub cam: LinkId,
    /// Index into `Mechanism::revolutes` of the cam link's ground pin.
    pub cam_pivot: usize,
    /// The cam's centre (that pin) in the world, m.
    pub centre: Vec2,
    /// The cam's centre in the cam link's coordinates, m.
    pub centre_on_cam: Vec2,
    /// The follower.
    pub follower: LinkId,
    /// How the follower is guided.
    pub guide: FollowerGuide,
    /// The roller's centre, a point of the follower.
    pub roller: PointId,
    /// That point in the follower's coordinates, m.
    pub roller_local: Vec2,
    /// The roller's radius, m.
    pub roller_radius_m: f64,
    /// The follower's coordinate at zero lift (rad for an arm, m for a slider).
    pub rest: f64,
    /// The cam link's angle where the program begins, rad.
    pub phase_rad: f64,
    /// The follower's lift over the cam's turn (rad for an arm, m for a slider).
    pub program: Program,
}

/// Where the roller touches the cam at one cam angle, in the world.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CamContact {
    /// The roller's centre, m.
    pub roller: Vec2,
    /// The contact normal, unit, pointing from the cam to the roller: the cam pushes
    /// the follower along it.
    pub normal: Vec2,
    /// The contact point on the profile, m.
    pub point: Vec2,
    /// The pressure angle, rad: between the normal and the roller centre's travel.
    pub pressure_angle_rad: f64,
    /// The pitch curve's radius of curvature, m (positive convex).
    pub pitch_radius_m: f64,
    /// The profile's radius of curvature, m (the pitch curve's less the roller's).
    pub profile_radius_m: f64,
}

impl CamJoint {
    /// The follower's coordinate (rest plus lift) and its derivatives per radian of
    /// cam, at the cam link's angle `cam_angle` (rad).
    pub fn follower_at(&self, cam_angle: f64) -> FollowerMotion {
        let m = self.program.at(cam_angle - self.phase_rad);
        FollowerMotion {
            s: self.rest + m.s,
            ..m
        }
    }

    /// The follower placed at coordinate `q` moving at `q_dot`, `q_ddot` (per second).
    #[inline(always)]
    pub(crate) fn place_follower<T: Real>(&self, q: T, q_dot: T, q_ddot: T) -> LinkMotion<T> {
        match &self.guide {
            FollowerGuide::Arm {
                pivot_world,
                pivot_on_follower,
                ..
            } => {
                let (sin, cos) = q.sin_cos_of();
                let pin = PointMotion {
                    position: splat_vec(pivot_world),
                    ..Default::default()
                };
                LinkMotion::from_pin(
                    UnitComplex::from_cos_sin_unchecked(cos, sin),
                    q_dot,
                    q_ddot,
                    pivot_on_follower,
                    &pin,
                )
            }
            FollowerGuide::Slide {
                through_world,
                direction,
                slider_local,
                rotation,
                ..
            } => {
                let u = splat_vec::<T>(direction);
                let turned = rotation * slider_local;
                let origin = PointMotion {
                    position: splat_vec::<T>(&(through_world - turned)) + u * q,
                    velocity: u * q_dot,
                    acceleration: u * q_ddot,
                };
                let (c, s) = (splat(rotation.cos_angle()), splat(rotation.sin_angle()));
                LinkMotion {
                    rotation: UnitComplex::from_cos_sin_unchecked(c, s),
                    omega_rad_s: T::zero(),
                    alpha_rad_s2: T::zero(),
                    origin,
                }
            }
        }
    }

    /// The roller's centre in the world at coordinate `q`, with its first two
    /// derivatives by `q`, and its direction of travel (unit).
    fn roller_by_coordinate(&self, q: f64) -> ([Vec2; 3], Vec2) {
        match &self.guide {
            FollowerGuide::Arm {
                pivot_world,
                pivot_on_follower,
                ..
            } => {
                let r = turn(self.roller_local - pivot_on_follower, q);
                let along = perp(&r);
                ([pivot_world + r, along, -r], along / along.norm())
            }
            FollowerGuide::Slide { direction, .. } => {
                let at = self.place_follower(q, 0.0, 0.0).world(&self.roller_local);
                ([at, *direction, Vec2::zeros()], *direction)
            }
        }
    }

    /// Where the roller touches the cam at the cam link's angle `cam_angle` (rad).
    pub fn contact(&self, cam_angle: f64) -> CamContact {
        self.contact_of(self.follower_at(cam_angle))
    }

    /// Where the roller touches the cam with the follower at `m`.
    fn contact_of(&self, m: FollowerMotion) -> CamContact {
        let ([w, dw, ddw], travel) = self.roller_by_coordinate(m.s);
        // The roller centre's path by the cam's angle (chain rule through q).
        let c = [w - self.centre, dw * m.v, ddw * (m.v * m.v) + dw * m.a];
        let pitch = pitch_on_turning_cam(c);
        let n = pitch.outward;
        CamContact {
            roller: w,
            normal: n,
            point: w - n * self.roller_radius_m,
            pressure_angle_rad: (travel.x * n.y - travel.y * n.x).atan2(n.dot(&travel)),
            pitch_radius_m: pitch.radius_m,
            profile_radius_m: pitch.radius_m - self.roller_radius_m,
        }
    }

    /// The cam and its follower at the cam link's angle `cam_angle` as a cam file's
    /// cam gives them: the program's lift (from the lowest position, not the rest)
    /// and its rates per radian of cam, and the pitch and profile points in the cam's
    /// own frame about its centre (the cam link's axes).
    pub fn point_at(&self, cam_angle: f64) -> CamPoint {
        // The program and the turn back to the cam's frame each once (the panel and
        // the drawn outline take some thousands of points per edit of the cam).
        let motion = self.program.at(cam_angle - self.phase_rad);
        let contact = self.contact_of(FollowerMotion {
            s: self.rest + motion.s,
            ..motion
        });
        let (sin, cos) = (-cam_angle).sin_cos();
        let on_cam = |p: Vec2| {
            let q = p - self.centre;
            [cos * q.x - sin * q.y, sin * q.x + cos * q.y]
        };
        CamPoint {
            angle_rad: cam_angle,
            motion,
            pitch_m: on_cam(contact.roller),
            profile_m: on_cam(contact.point),
            pressure_angle_rad: contact.pressure_angle_rad,
            pitch_radius_m: contact.pitch_radius_m,
            profile_radius_m: contact.profile_radius_m,
        }
    }

    /// The largest pressure angle a designer allows: 30° for a translating follower,
    /// 45° for an arm (whose guide is a pin, not a sliding stem that can jam), as the
    /// textbooks advise.
    pub fn pressure_limit_rad(&self) -> f64 {
        match self.guide {
            FollowerGuide::Arm { .. } => 45f64.to_radians(),
            FollowerGuide::Slide { .. } => 30f64.to_radians(),
        }
    }

    /// The roller centre's distance from the cam's centre at the cam link's angle.
    pub(crate) fn pitch_distance(&self, cam_angle: f64) -> f64 {
        let m = self.follower_at(cam_angle);
        (self.roller_by_coordinate(m.s).0[0] - self.centre).norm()
    }

    /// The slider the follower rides, for a translating follower.
    pub fn slider<'a>(&self, sliders: &'a [Prismatic]) -> Option<&'a Prismatic> {
        match self.guide {
            FollowerGuide::Slide { slider, .. } => sliders.get(slider),
            FollowerGuide::Arm { .. } => None,
        }
    }
}
