//! Dragging in the mechanism view. Without "move points", grabbing a point of the
//! driver link turns it to follow the pointer (drive by hand). With it, the joint
//! under the pointer follows it, snapped to a 1 mm grid and into line with other joints
//! (within 6 points, horizontally or vertically; Alt drags freely). Each frame of
//! the drag is one `Session::move_point`, and the drag as a whole one undo step. A
//! place where the chain does not assemble is refused by the session: the point
//! stays at its last valid place and the reason shows.

use eframe::egui::{self, Pos2, Rect};

use crate::render::view::Camera;
use crate::session::SceneEdit;
use crate::state::AppState;

/// How near a joint (points) a press must be to grab it.
const GRAB_PT: f32 = 10.0;
/// How near another joint's x or y (points) snaps into line with it.
const ALIGN_PT: f32 = 6.0;
/// The grid, metres.
const GRID_M: f64 = 1e-3;

/// A joint being dragged, or the driver turned by hand.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PointDrag {
    /// The point being dragged, by name.
    pub dragged_point: Option<String>,
    /// While the driver is turned by hand: its grabbed point's angle from the input.
    pub turning: Option<f64>,
}

impl PointDrag {
    /// Whether a joint is being dragged or the driver turned by hand.
    pub fn active(&self) -> bool {
        self.dragged_point.is_some() || self.turning.is_some()
    }
}

/// Handles the view's pointer in edit mode; returns whether a point is being dragged
/// (then the view does not pan).
pub fn handle(
    ui: &egui::Ui,
    response: &egui::Response,
    rect: Rect,
    st: &mut AppState,
    cam: &Camera,
    drag: &mut PointDrag,
) -> bool {
    // Grab by where the button went down: by the frame that sees the drag start the
    // pointer may have gone several points on (a slow frame, a quick hand).
    let pressed_at = ui.input(|i| i.pointer.press_origin());
    if response.drag_started()
        && let Some(at) = pressed_at.or_else(|| response.interact_pointer_pos())
    {
        if st.view.edit_points {
            drag.dragged_point = joint_near(st, cam, at, rect);
        } else {
            drag.turning = driver_handle(st, cam, at, rect);
        }
    }
    if response.drag_stopped() {
        drag.dragged_point = None;
        drag.turning = None;
        return false;
    }
    // A pointer held still asks for nothing: an edit in every frame would keep the
    // app repainting (and a refused one would be asked again and again).
    let moved = response.drag_delta() != egui::Vec2::ZERO;
    if let Some(offset) = drag.turning {
        if moved && let Some(at) = response.interact_pointer_pos() {
            turn_to(st, cam, at, rect, offset);
        }
        return true;
    }
    if !st.view.edit_points {
        drag.dragged_point = None;
        return false;
    }
    let Some(name) = drag.dragged_point.clone() else {
        return false;
    };
    if moved && let Some(at) = response.interact_pointer_pos() {
        let free = ui.input(|i| i.modifiers.alt);
        let to = if free {
            cam.to_world(at, rect)
        } else {
            snapped(st, cam, &name, at, rect)
        };
        let current = point_position(st, &name);
        if current.is_none_or(|c| (c[0] - to[0]).hypot(c[1] - to[1]) > 1e-12) {
            st.edit(SceneEdit::MovePoint { name, to_m: to });
        }
    }
    true
}

/// A point of the driver link (not its pivot) within [`GRAB_PT`] of `at`: the angle
/// between that point's direction from the pivot and the input angle, which the drag
/// keeps.
fn driver_handle(st: &AppState, cam: &Camera, at: Pos2, rect: Rect) -> Option<f64> {
    let m = st.session.mechanism();
    let pose = st.session.pose();
    let pivot_point = m.revolutes[m.driver.pivot].point;
    let pivot = pose.points[pivot_point].position;
    m.links[m.driver.link]
        .points
        .iter()
        .map(|&(p, _)| p)
        .filter(|&p| p != pivot_point)
        .map(|p| {
            let q = pose.points[p].position;
            (cam.to_screen([q.x, q.y], rect).distance(at), q)
        })
        .filter(|(d, _)| *d <= GRAB_PT)
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, q)| (q.y - pivot.y).atan2(q.x - pivot.x) - st.session.input_rad())
}

/// Turns the driver so that its grabbed point points at `at`.
fn turn_to(st: &mut AppState, cam: &Camera, at: Pos2, rect: Rect, offset: f64) {
    let m = st.session.mechanism();
    let pivot = st.session.pose().points[m.revolutes[m.driver.pivot].point].position;
    let w = cam.to_world(at, rect);
    let pointed = (w[1] - pivot.y).atan2(w[0] - pivot.x) - offset;
    // The turn nearest the current angle: a range such as 242°..326° is reached from
    // atan2's (-180°, 180°] without a jump.
    let now = st.session.input_rad();
    let step = (pointed - now + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU)
        - std::f64::consts::PI;
    st.edit(SceneEdit::Input {
        deg: (now + step).to_degrees(),
    });
}

/// The joint within [`GRAB_PT`] of `at`, the nearest.
fn joint_near(st: &AppState, cam: &Camera, at: Pos2, rect: Rect) -> Option<String> {
    let m = st.session.mechanism();
    let pose = st.session.pose();
    st.session
        .topology()
        .joint_points
        .iter()
        .map(|&p| {
            let q = pose.points[p].position;
            (cam.to_screen([q.x, q.y], rect).distance(at), p)
        })
        .filter(|(d, _)| *d <= GRAB_PT)
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, p)| m.points[p].name.clone())
}

fn point_position(st: &AppState, name: &str) -> Option<[f64; 2]> {
    let p = st.session.mechanism().point_index(name)?;
    let q = st.session.pose().points[p].position;
    Some([q.x, q.y])
}

/// The pointer's world place on the grid, then into line with any other joint whose
/// x or y is within [`ALIGN_PT`].
fn snapped(st: &AppState, cam: &Camera, name: &str, at: Pos2, rect: Rect) -> [f64; 2] {
    let w = cam.to_world(at, rect);
    let mut to = [
        (w[0] / GRID_M).round() * GRID_M,
        (w[1] / GRID_M).round() * GRID_M,
    ];
    let m = st.session.mechanism();
    let pose = st.session.pose();
    for &p in &st.session.topology().joint_points {
        if m.points[p].name == name {
            continue;
        }
        let q = pose.points[p].position;
        let s = cam.to_screen([q.x, q.y], rect);
        if (s.x - at.x).abs() <= ALIGN_PT {
            to[0] = q.x;
        }
        if (s.y - at.y).abs() <= ALIGN_PT {
            to[1] = q.y;
        }
    }
    to
}
