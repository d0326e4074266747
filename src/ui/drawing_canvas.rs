//! The mechanism view while drawing: clicks and drags become edits of the drawing,
//! by the tool in hand; places snap to a 10 mm grid and onto points near the
//! pointer. The drawing is drawn by the GPU renderer over a light grid, with point
//! names beside it and a rubber band from a link's first end to the pointer.

use eframe::egui::{self, Align2, Color32, FontId, Pos2, Rect, Sense, Stroke};
use linkage::Vec2;
use linkage::drawing::Drawing;

use crate::command::Command;
use crate::drawing::edit::{DrawingEdit, End};
use crate::drawing::{Pending, Tool};
use crate::render::Renderer;
use crate::render::drawing_shapes::build_drawing;
use crate::render::shape::SharedShapes;
use crate::render::view::Camera;
use crate::state::AppState;
use crate::ui::viewport::navigate;

/// How near a point (points) a click must be to take it.
const GRAB_PT: f32 = 10.0;
/// How near another point's x or y (points) a dragged point snaps into line with it.
const ALIGN_PT: f32 = 6.0;
/// Grid lines per metre (10 mm apart).
const GRID_PER_M: f64 = 100.0;
/// What an empty drawing shows: 0.5 m by 0.4 m about the origin's right.
const EMPTY_VIEW_M: [f64; 4] = [-0.1, -0.15, 0.4, 0.25];

/// Draws the drawing and turns the pointer into its edits.
pub fn show(
    ui: &mut egui::Ui,
    st: &mut AppState,
    camera: &mut Camera,
    shapes: &SharedShapes,
    renderer: Option<&Renderer>,
) {
    let (rect, response) = ui.allocate_exact_size(ui.available_size(), Sense::click_and_drag());
    st.controls.view = Some([rect.min.x, rect.min.y, rect.max.x, rect.max.y]);
    let Some(b) = st.drawing.as_mut() else {
        return;
    };
    if b.fit_pending && rect.width() > 1.0 {
        camera.fit(bounds(b.drawing()), rect);
        b.fit_pending = false;
    }
    let dragging_point = pointer(ui, &response, rect, st, camera);
    // A drawn point or link shows where the pointer is now.
    st.apply_commands();
    navigate(ui, &response, rect, camera, !dragging_point);
    draw(ui, rect, st, camera, shapes, renderer);
}

/// The drawing's box, or a default view when it has fewer than two points.
fn bounds(drawing: &Drawing) -> [f64; 4] {
    if drawing.points.len() < 2 {
        return EMPTY_VIEW_M;
    }
    drawing.points.iter().fold(
        [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ],
        |b, p| {
            [
                b[0].min(p.at.x),
                b[1].min(p.at.y),
                b[2].max(p.at.x),
                b[3].max(p.at.y),
            ]
        },
    )
}

/// Handles this frame's clicks and drags; returns whether a point is being dragged
/// (then the view does not pan).
fn pointer(
    ui: &egui::Ui,
    response: &egui::Response,
    rect: Rect,
    st: &mut AppState,
    cam: &Camera,
) -> bool {
    let Some(b) = st.drawing.as_ref() else {
        return false;
    };
    let tool = b.tool;
    if tool == Tool::Move {
        return drag_point(ui, response, rect, st, cam);
    }
    if response.clicked()
        && let Some(at) = response.interact_pointer_pos()
        && let Some(edit) = click(st, cam, at, rect)
    {
        st.push(Command::Drawing(edit));
    }
    false
}

/// The edit a click at `at` makes with the tool in hand (a link's first click only
/// notes its end).
fn click(st: &mut AppState, cam: &Camera, at: Pos2, rect: Rect) -> Option<DrawingEdit> {
    let b = st.drawing.as_mut()?;
    let mut pending = b.pending.take();
    let drawing = b.drawing();
    let near = point_near(drawing, cam, at, rect);
    let place = snapped(cam, at, rect);
    let end = near.map_or(End::New(place), End::Point);
    let edit = match b.tool {
        Tool::Pivot => Some(match near {
            Some(point) => DrawingEdit::SetGround {
                point,
                ground: true,
            },
            None => DrawingEdit::AddPivot(place),
        }),
        Tool::Link => match pending.take() {
            None | Some(Pending::ElementFrom { .. }) => {
                pending = Some(match (near, link_near(drawing, cam, at, rect)) {
                    (None, Some(link)) => Pending::OnLink(link),
                    _ => Pending::LinkFrom(end),
                });
                None
            }
            Some(Pending::LinkFrom(from)) => Some(DrawingEdit::AddLink(from, end)),
            Some(Pending::OnLink(link)) => Some(DrawingEdit::AddPointToLink { link, end }),
        },
        Tool::Slider => near.map(|point| DrawingEdit::AddSlider {
            point,
            angle_rad: 0.0,
        }),
        Tool::Driver => link_at(drawing, cam, at, rect).map(DrawingEdit::SetDriver),
        Tool::Delete => match near {
            Some(p) => Some(DrawingEdit::DeletePoint(p)),
            None => link_near(drawing, cam, at, rect).map(DrawingEdit::DeleteLink),
        },
        Tool::Spring | Tool::Damper => {
            let damper = b.tool == Tool::Damper;
            match (pending.take(), near) {
                (Some(Pending::ElementFrom { point: a, .. }), Some(point)) if damper => {
                    Some(DrawingEdit::AddDamper(a, point))
                }
                (Some(Pending::ElementFrom { point: a, .. }), Some(point)) => {
                    Some(DrawingEdit::AddSpring(a, point))
                }
                (_, Some(point)) => {
                    pending = Some(Pending::ElementFrom { damper, point });
                    None
                }
                (_, None) => None,
            }
        }
        Tool::Force => near.map(DrawingEdit::AddForce),
        Tool::Move => None,
    };
    b.pending = pending;
    edit
}

/// The move tool: the point under the press follows the pointer, snapped; the drag
/// is one undo step.
fn drag_point(
    ui: &egui::Ui,
    response: &egui::Response,
    rect: Rect,
    st: &mut AppState,
    cam: &Camera,
) -> bool {
    let Some(b) = st.drawing.as_mut() else {
        return false;
    };
    if response.drag_started()
        && let Some(at) = ui
            .input(|i| i.pointer.press_origin())
            .or_else(|| response.interact_pointer_pos())
    {
        b.dragged = point_near(b.drawing(), cam, at, rect);
    }
    if response.drag_stopped() || !ui.input(|i| i.pointer.any_down()) {
        b.end_gesture();
        return false;
    }
    let Some(point) = b.dragged else {
        return false;
    };
    if let Some(at) = response.interact_pointer_pos() {
        let to = aligned(b.drawing(), point, snapped(cam, at, rect), cam, at, rect);
        if b.drawing().points[point].at != to {
            st.push(Command::Drawing(DrawingEdit::MovePoint { point, to }));
        }
    }
    true
}

/// The pointer's world place on the grid.
fn snapped(cam: &Camera, at: Pos2, rect: Rect) -> Vec2 {
    let w = cam.to_world(at, rect);
    // Divided, not multiplied by 0.01: each place is the double nearest k / 100.
    Vec2::new(
        (w[0] * GRID_PER_M).round() / GRID_PER_M,
        (w[1] * GRID_PER_M).round() / GRID_PER_M,
    )
}

/// `to` moved into line with any other point whose x or y is within [`ALIGN_PT`] of
/// the pointer: a drag lines points up horizontally and vertically.
fn aligned(
    drawing: &Drawing,
    moving: usize,
    mut to: Vec2,
    cam: &Camera,
    at: Pos2,
    rect: Rect,
) -> Vec2 {
    for (_, p) in drawing
        .points
        .iter()
        .enumerate()
        .filter(|(i, _)| *i != moving)
    {
        let s = screen(cam, p.at, rect);
        if (s.x - at.x).abs() <= ALIGN_PT {
            to.x = p.at.x;
        }
        if (s.y - at.y).abs() <= ALIGN_PT {
            to.y = p.at.y;
        }
    }
    to
}

fn screen(cam: &Camera, p: Vec2, rect: Rect) -> Pos2 {
    cam.to_screen([p.x, p.y], rect)
}

/// The item of the nearest of `distances` (points on screen) within [`GRAB_PT`].
fn nearest<T>(distances: impl Iterator<Item = (f32, T)>) -> Option<T> {
    distances
        .filter(|(d, _)| *d <= GRAB_PT)
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, item)| item)
}

/// The point within [`GRAB_PT`] of `at`, the nearest.
fn point_near(drawing: &Drawing, cam: &Camera, at: Pos2, rect: Rect) -> Option<usize> {
    nearest(
        drawing
            .points
            .iter()
            .enumerate()
            .map(|(i, p)| (screen(cam, p.at, rect).distance(at), i)),
    )
}

/// The link whose outline passes within [`GRAB_PT`] of `at`, the nearest.
fn link_near(drawing: &Drawing, cam: &Camera, at: Pos2, rect: Rect) -> Option<usize> {
    let distance = |a: Pos2, b: Pos2| {
        let ab = b - a;
        let t = ((at - a).dot(ab) / ab.length_sq().max(1e-6)).clamp(0.0, 1.0);
        (a + t * ab).distance(at)
    };
    nearest(drawing.links.iter().enumerate().flat_map(|(l, link)| {
        let pts: Vec<Pos2> = link
            .points
            .iter()
            .map(|&p| screen(cam, drawing.points[p].at, rect))
            .collect();
        let n = pts.len();
        (0..n).map(move |i| (distance(pts[i], pts[(i + 1) % n]), l))
    }))
}

/// The link under `at`, or one through the point under it (the first).
fn link_at(drawing: &Drawing, cam: &Camera, at: Pos2, rect: Rect) -> Option<usize> {
    link_near(drawing, cam, at, rect).or_else(|| {
        let p = point_near(drawing, cam, at, rect)?;
        drawing.links.iter().position(|l| l.points.contains(&p))
    })
}

/// The grid, the drawing (GPU), the names, and a link's rubber band.
fn draw(
    ui: &egui::Ui,
    rect: Rect,
    st: &AppState,
    camera: &Camera,
    shapes: &SharedShapes,
    renderer: Option<&Renderer>,
) {
    let Some(b) = st.drawing.as_ref() else {
        return;
    };
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 0.0, Color32::from_rgb(246, 246, 242));
    grid(&painter, rect, camera);
    let marked = match b.pending {
        Some(Pending::LinkFrom(End::Point(p))) => Some(p),
        _ => b.dragged,
    };
    if let Ok(mut list) = shapes.lock() {
        build_drawing(&mut list, b.drawing(), camera, marked);
    }
    let view = camera.uniform(rect, ui.ctx().pixels_per_point());
    crate::ui::viewport::paint_shapes(&painter, rect, view, shapes, renderer);
    let font = FontId::proportional(13.0);
    for p in &b.drawing().points {
        let s = screen(camera, p.at, rect);
        painter.text(
            s + egui::vec2(8.0, -8.0),
            Align2::LEFT_BOTTOM,
            &p.name,
            font.clone(),
            Color32::BLACK,
        );
    }
    let from = match b.pending {
        Some(Pending::LinkFrom(End::Point(p))) => {
            Some(screen(camera, b.drawing().points[p].at, rect))
        }
        Some(Pending::LinkFrom(End::New(at))) => Some(screen(camera, at, rect)),
        _ => None,
    };
    if let (Some(from), Some(to)) = (from, ui.input(|i| i.pointer.hover_pos())) {
        painter.line_segment(
            [from, to],
            Stroke::new(1.5, Color32::from_rgb(180, 60, 140)),
        );
    }
    painter.text(
        rect.left_top() + egui::vec2(8.0, 8.0),
        Align2::LEFT_TOP,
        format!(
            "{}: {}",
            crate::ui::words::tool_name(b.tool),
            crate::ui::words::tool_hint(b.tool)
        ),
        FontId::proportional(12.0),
        Color32::DARK_GRAY,
    );
}

/// Light lines every 10 mm (every 50 mm darker), or coarser where they would crowd.
fn grid(painter: &egui::Painter, rect: Rect, cam: &Camera) {
    let mut step = 1.0 / GRID_PER_M;
    while step * cam.points_per_m < 8.0 {
        step *= 5.0;
    }
    let lo = cam.to_world(rect.left_bottom(), rect);
    let hi = cam.to_world(rect.right_top(), rect);
    let line = |i: i64| {
        let major = i % 5 == 0;
        Stroke::new(
            if major { 0.8 } else { 0.4 },
            Color32::from_gray(if major { 205 } else { 225 }),
        )
    };
    for i in (lo[0] / step).floor() as i64..=(hi[0] / step).ceil() as i64 {
        let x = screen(cam, Vec2::new(i as f64 * step, 0.0), rect).x;
        painter.vline(x, rect.y_range(), line(i));
    }
    for i in (lo[1] / step).floor() as i64..=(hi[1] / step).ceil() as i64 {
        let y = screen(cam, Vec2::new(0.0, i as f64 * step), rect).y;
        painter.hline(rect.x_range(), y, line(i));
    }
}
