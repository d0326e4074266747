//! The frame's palette, and the pose as the shape builders see it: where its points
//! fall in the camera's coordinates and how thick bars and pins are drawn.

use glam::Vec2;

use super::view::Camera;
use crate::session::Session;
use linkage::PointId;

/// Colours, gamma-space RGBA.
pub(super) mod colour {
    pub const LINK: [f32; 4] = [0.28, 0.47, 0.72, 1.0];
    pub const PLATE: [f32; 4] = [0.36, 0.55, 0.78, 0.85];
    pub const DRIVER: [f32; 4] = [0.82, 0.52, 0.18, 1.0];
    pub const GROUND: [f32; 4] = [0.55, 0.55, 0.55, 1.0];
    pub const PIN: [f32; 4] = [0.12, 0.12, 0.14, 1.0];
    pub const MARK: [f32; 4] = [0.75, 0.2, 0.55, 1.0];
    pub const BLOCK: [f32; 4] = [0.45, 0.62, 0.42, 1.0];
    pub const SPRING: [f32; 4] = [0.78, 0.25, 0.2, 1.0];
    pub const TRACE: [f32; 4] = [0.62, 0.38, 0.85, 1.0];
    pub const VELOCITY: [f32; 4] = [0.1, 0.65, 0.25, 1.0];
    pub const ACCELERATION: [f32; 4] = [0.9, 0.2, 0.15, 1.0];
    pub const FORCE: [f32; 4] = [0.16, 0.2, 0.62, 1.0];
    /// A cam's disc: opaque, so that the triangles of its fan show no seams.
    pub const CAM: [f32; 4] = [0.80, 0.74, 0.58, 1.0];
    pub const CAM_EDGE: [f32; 4] = [0.42, 0.36, 0.24, 1.0];
    pub const ROLLER: [f32; 4] = [0.30, 0.30, 0.34, 1.0];
    /// A cam's rim where it passes a limit.
    pub const PAST_LIMIT: [f32; 4] = [0.85, 0.15, 0.12, 1.0];
}

/// The pose as drawn: where its points fall in the camera's local coordinates, and
/// how thick its bars and pins are.
pub(super) struct Drawn<'a> {
    pub(super) s: &'a Session,
    pub(super) cam: &'a Camera,
    /// A bar's width, m.
    pub(super) bar: f32,
    /// A pin's radius, m.
    pub(super) pin: f32,
}

impl Drawn<'_> {
    /// Point `p` of the pose, m.
    pub(super) fn at(&self, p: PointId) -> [f64; 2] {
        let q = self.s.pose().points[p].position;
        [q.x, q.y]
    }

    /// Point `p` in the camera's local coordinates.
    pub(super) fn pos(&self, p: PointId) -> Vec2 {
        self.cam.local(self.at(p))
    }
}
