//! The 2-D camera of the mechanism view: pan, zoom about the pointer, fit to a box,
//! and the mapping between metres (y up) and screen points (y down).

use eframe::egui::{Pos2, Rect, Vec2};

use super::shape::ViewUniform;

/// Smallest and largest zoom relative to the fitted view: past these a wheel does
/// nothing, so the view never degenerates to a point or overflows f32.
const ZOOM_LIMITS: [f64; 2] = [1e-3, 1e4];

/// Where the camera looks and how close.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// World point at the centre of the view, m.
    pub center_m: [f64; 2],
    /// Screen points per metre.
    pub points_per_m: f64,
    /// `points_per_m` of the last fit (the zoom limits are relative to it).
    pub fitted_points_per_m: f64,
    /// Whether the user panned or zoomed since the last fit: the view then stays
    /// where the user put it when the mechanism or the view's size changes.
    pub by_hand: bool,
}

impl Default for Camera {
    fn default() -> Self {
        Self {
            center_m: [0.0, 0.0],
            points_per_m: 100.0,
            fitted_points_per_m: 100.0,
            by_hand: false,
        }
    }
}

impl Camera {
    /// Frames the box `[min x, min y, max x, max y]` (m) in `rect` with a margin.
    pub fn fit(&mut self, bounds_m: [f64; 4], rect: Rect) {
        self.fit_within(bounds_m, rect, rect);
    }

    /// Frames the box in `inner`, a part of the view's `rect` (what the view's
    /// legend and message leave clear), with a margin.
    pub fn fit_within(&mut self, bounds_m: [f64; 4], rect: Rect, inner: Rect) {
        let inner = if inner.width() > 1.0 && inner.height() > 1.0 {
            inner
        } else {
            rect
        };
        let w = (bounds_m[2] - bounds_m[0]).max(1e-12);
        let h = (bounds_m[3] - bounds_m[1]).max(1e-12);
        let scale = (f64::from(inner.width()) / w).min(f64::from(inner.height()) / h) * 0.9;
        if scale.is_finite() && scale > 0.0 {
            self.points_per_m = scale;
            self.fitted_points_per_m = scale;
            // The box's centre at the inner rectangle's centre (y up in the world).
            let shift = inner.center() - rect.center();
            self.center_m = [
                0.5 * (bounds_m[0] + bounds_m[2]) - f64::from(shift.x) / scale,
                0.5 * (bounds_m[1] + bounds_m[3]) + f64::from(shift.y) / scale,
            ];
            self.by_hand = false;
        }
    }

    /// Screen position of a world point in `rect`.
    pub fn to_screen(&self, p_m: [f64; 2], rect: Rect) -> Pos2 {
        let c = rect.center();
        Pos2::new(
            c.x + ((p_m[0] - self.center_m[0]) * self.points_per_m) as f32,
            c.y - ((p_m[1] - self.center_m[1]) * self.points_per_m) as f32,
        )
    }

    /// World point under a screen position in `rect`.
    pub fn to_world(&self, p: Pos2, rect: Rect) -> [f64; 2] {
        let c = rect.center();
        [
            self.center_m[0] + f64::from(p.x - c.x) / self.points_per_m,
            self.center_m[1] - f64::from(p.y - c.y) / self.points_per_m,
        ]
    }

    /// Moves the view by a screen drag.
    pub fn pan(&mut self, drag: Vec2) {
        if drag == Vec2::ZERO {
            return;
        }
        self.center_m[0] -= f64::from(drag.x) / self.points_per_m;
        self.center_m[1] += f64::from(drag.y) / self.points_per_m;
        self.by_hand = true;
    }

    /// Zooms by `factor` keeping the world point under `pointer` fixed.
    pub fn zoom_at(&mut self, factor: f64, pointer: Pos2, rect: Rect) {
        let next = self.points_per_m * factor;
        let relative = next / self.fitted_points_per_m;
        let allowed = factor.is_finite()
            && factor > 0.0
            && (ZOOM_LIMITS[0]..=ZOOM_LIMITS[1]).contains(&relative);
        if !allowed {
            return;
        }
        let before = self.to_world(pointer, rect);
        self.points_per_m = next;
        self.by_hand = true;
        let after = self.to_world(pointer, rect);
        self.center_m[0] += before[0] - after[0];
        self.center_m[1] += before[1] - after[1];
    }

    /// The shader's transform for `rect` at `pixels_per_point`.
    pub fn uniform(&self, rect: Rect, pixels_per_point: f32) -> ViewUniform {
        let w = f64::from(rect.width().max(1.0));
        let h = f64::from(rect.height().max(1.0));
        ViewUniform {
            clip_per_m: [
                (2.0 * self.points_per_m / w) as f32,
                (2.0 * self.points_per_m / h) as f32,
            ],
            m_per_px: (1.0 / (self.points_per_m * f64::from(pixels_per_point))) as f32,
            pad: 0.0,
        }
    }

    /// A world point relative to the view centre, as the GPU takes it.
    pub fn local(&self, p_m: [f64; 2]) -> glam::Vec2 {
        glam::Vec2::new(
            (p_m[0] - self.center_m[0]) as f32,
            (p_m[1] - self.center_m[1]) as f32,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect() -> Rect {
        Rect::from_min_size(Pos2::new(10.0, 20.0), Vec2::new(400.0, 300.0))
    }

    #[test]
    fn screen_and_world_are_inverse_and_y_points_up() {
        let mut cam = Camera::default();
        cam.fit([-1.0, -0.5, 3.0, 2.0], rect());
        let p = [0.7, 1.3];
        let back = cam.to_world(cam.to_screen(p, rect()), rect());
        assert!((back[0] - p[0]).abs() < 1e-5 && (back[1] - p[1]).abs() < 1e-5);
        assert!(cam.to_screen([0.0, 1.0], rect()).y < cam.to_screen([0.0, 0.0], rect()).y);
    }

    /// Fitted within a part of the view, the box lies inside that part; panning
    /// marks the camera as moved by hand, a fit clears it.
    #[test]
    fn a_fit_within_keeps_the_box_inside_the_part_and_clears_by_hand() {
        let mut cam = Camera::default();
        let inner = rect().with_min_y(rect().min.y + 60.0);
        cam.pan(Vec2::new(3.0, 0.0));
        assert!(cam.by_hand);
        let bounds = [-1.0, -0.5, 3.0, 2.0];
        cam.fit_within(bounds, rect(), inner);
        assert!(!cam.by_hand);
        for corner in [[bounds[0], bounds[1]], [bounds[2], bounds[3]]] {
            let p = cam.to_screen(corner, rect());
            assert!(inner.contains(p), "{p:?} outside {inner:?}");
        }
    }

    #[test]
    fn zoom_keeps_the_point_under_the_pointer_and_stops_at_its_limits() {
        let mut cam = Camera::default();
        cam.fit([0.0, 0.0, 1.0, 1.0], rect());
        let pointer = Pos2::new(100.0, 80.0);
        let before = cam.to_world(pointer, rect());
        cam.zoom_at(1.7, pointer, rect());
        let after = cam.to_world(pointer, rect());
        assert!((before[0] - after[0]).abs() < 1e-6 && (before[1] - after[1]).abs() < 1e-6);
        for _ in 0..200 {
            cam.zoom_at(10.0, pointer, rect());
        }
        assert!(cam.points_per_m <= cam.fitted_points_per_m * ZOOM_LIMITS[1]);
        cam.zoom_at(f64::NAN, pointer, rect());
        assert!(cam.points_per_m.is_finite());
    }
}
