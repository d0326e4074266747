//! Which points are joints and which joints each link carries. It depends only on the
//! mechanism, so it is derived once per edit instead of in every frame's drawing.

use linkage::motion::Vec2;
use linkage::{Mechanism, PointId};

use super::cam_curves::{CAM_SAMPLES, CamCurves};

/// The joint structure of one mechanism, by point and link index.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Topology {
    /// Points that are joints (pins and slider points), each once, ascending.
    pub joint_points: Vec<PointId>,
    /// Per link (indexed by its `LinkId`): the points of its revolute joints, in
    /// revolute order.
    pub link_joints: Vec<Vec<PointId>>,
    /// Per link: its other points (tool points, centroids, spring anchors).
    pub link_others: Vec<Vec<PointId>>,
    /// Points on moving links that are not joints: drawn as marks.
    pub marks: Vec<PointId>,
    /// Per cam joint (as `Mechanism::cams`): its profile in the cam link's own
    /// coordinates, m, a closed outline of [`CAM_OUTLINE`] points. Made once per
    /// mechanism, since a frame only turns it with its link.
    pub cam_profiles: Vec<Vec<Vec2>>,
    /// Per cam joint, per outline point: whether the cam passes a limit there (the
    /// pressure angle past the joint's limit, or undercut), drawn in red.
    pub cam_past_limit: Vec<Vec<bool>>,
}

/// Points of a cam's drawn outline: a segment every 2 degrees of cam.
pub const CAM_OUTLINE: usize = 180;

/// The outline takes every this many of the cam curves' samples (the same angles:
/// `TAU * 2i / 360` is `TAU * i / 180` to the last bit, a power of two apart).
const OUTLINE_STRIDE: usize = CAM_SAMPLES / CAM_OUTLINE;
const _: () = assert!(OUTLINE_STRIDE * CAM_OUTLINE == CAM_SAMPLES);

impl Topology {
    /// The topology of `m`; its cams' outlines from `cams`, the curves of `m`'s cam
    /// joints (in `Mechanism::cams` order), so that the cam is evaluated once.
    pub fn of(m: &Mechanism, cams: &[CamCurves]) -> Self {
        let joint_points = m.joint_points();
        let link_joints: Vec<Vec<PointId>> = m
            .link_ids()
            .map(|l| {
                m.revolutes
                    .iter()
                    .filter(|r| r.a == l || r.b == l)
                    .map(|r| r.point)
                    .collect()
            })
            .collect();
        let link_others = m
            .links
            .iter()
            .zip(&link_joints)
            .map(|(link, joints)| {
                link.points
                    .iter()
                    .map(|&(p, _)| p)
                    .filter(|p| !joints.contains(p))
                    .collect()
            })
            .collect();
        let marks = m
            .point_ids()
            .filter(|i| joint_points.binary_search(i).is_err() && m.points[*i].link != m.ground)
            .collect();
        // Each outline point once: where it is on the cam link, and whether it passes
        // a limit there.
        let (cam_profiles, cam_past_limit) = m
            .cams
            .iter()
            .zip(cams)
            .map(|(c, curves)| {
                curves
                    .points
                    .iter()
                    .step_by(OUTLINE_STRIDE)
                    .map(|p| {
                        let [x, y] = p.profile_m;
                        let on_link = c.centre_on_cam + Vec2::new(x, y);
                        (on_link, p.past_limit(curves.pressure_limit_rad))
                    })
                    .unzip()
            })
            .unzip();
        Self {
            joint_points,
            link_joints,
            link_others,
            marks,
            cam_profiles,
            cam_past_limit,
        }
    }
}
