//! The GPU's view of a shape: one instance per link, pin, spring, vector or trace
//! segment. `#[repr(C)]` and `Pod` so the instance buffer is written as bytes; the
//! layout mirrors `Instance` in `shaders/linkage.wgsl`.

use bytemuck::{Pod, Zeroable};
use glam::Vec2;

/// What the fragment shader draws; the values match the WGSL constants.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u32)]
pub enum Kind {
    /// Rounded bar from `p0` to `p1` (a binary link).
    Bar = 0,
    /// Rounded triangle `p0 p1 p2` (a ternary link).
    Plate = 1,
    /// Pin at `p0`.
    Pin = 2,
    /// Ground: base line `p1`–`p2`, hatched `param.x` deep.
    Ground = 3,
    /// Block centred at `p0`, axis towards `p1`, half sizes `param`.
    Block = 4,
    /// Coil spring `p0`–`p1`: `param.x` turns, `param.y` amplitude.
    Spring = 5,
    /// Arrow `p0`→`p1` with a head `param.x` long.
    Arrow = 6,
    /// Thin line `p0`–`p1` (traces, guides).
    Line = 7,
    /// Dashed line `p0`–`p1`, dashes `param.x` long.
    Dash = 8,
    /// Triangle `p0 p1 p2` of one flat colour, grown by `radius` (pieces of a larger
    /// area, such as a cam's disc, that meet edge to edge without seams).
    Fill = 9,
}

/// One instance: positions in metres relative to the view centre (f32 is enough
/// there, since the centre was subtracted in f64).
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
#[repr(C)]
pub struct Shape {
    /// First point, m.
    pub p0: [f32; 2],
    /// Second point, m.
    pub p1: [f32; 2],
    /// Third point, m (plates; else equal to `p0`).
    pub p2: [f32; 2],
    /// Half width or pin radius, m.
    pub radius: f32,
    /// [`Kind`] as u32.
    pub kind: u32,
    /// Colour, gamma-space RGBA in [0, 1].
    pub color: [f32; 4],
    /// Kind-specific sizes (see [`Kind`]).
    pub param: [f32; 2],
}

impl Shape {
    /// A shape of `kind` through up to three points, or `None` if any number is not
    /// finite (nothing non-finite reaches the GPU).
    pub fn new(
        kind: Kind,
        points: [Vec2; 3],
        radius: f32,
        color: [f32; 4],
        param: [f32; 2],
    ) -> Option<Self> {
        let finite = points.iter().all(|p| p.is_finite())
            && radius.is_finite()
            && color.iter().all(|c| c.is_finite())
            && param.iter().all(|c| c.is_finite());
        finite.then(|| Self {
            p0: points[0].to_array(),
            p1: points[1].to_array(),
            p2: points[2].to_array(),
            radius,
            kind: kind as u32,
            color,
            param,
        })
    }
}

/// The shapes of the frame, written by the app and read by the renderer's paint
/// callback (shared, so that no per-frame copy of the list is made).
pub type SharedShapes = std::sync::Arc<std::sync::Mutex<Vec<Shape>>>;

/// The view transform handed to the shader (`View` in WGSL; 16 bytes).
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
#[repr(C)]
pub struct ViewUniform {
    /// Clip units per metre, x and y.
    pub clip_per_m: [f32; 2],
    /// Metres per physical pixel.
    pub m_per_px: f32,
    /// Padding to 16 bytes (uniform buffers are sized in 16-byte steps).
    pub pad: f32,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn non_finite_shapes_are_refused() {
        let p = Vec2::new(f32::NAN, 0.0);
        assert!(
            Shape::new(
                Kind::Bar,
                [p, Vec2::ZERO, Vec2::ZERO],
                1.0,
                [1.0; 4],
                [0.0; 2]
            )
            .is_none()
        );
        assert!(
            Shape::new(
                Kind::Bar,
                [Vec2::ONE, Vec2::ZERO, Vec2::ZERO],
                1.0,
                [1.0; 4],
                [0.0; 2]
            )
            .is_some()
        );
    }
}
