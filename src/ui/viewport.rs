//! The mechanism view: pan (drag), zoom (wheel or pinch, about the pointer), fit on
//! request; the GPU draws the shapes, egui adds the point labels, the vector legend
//! and the message when an edit was refused.

use eframe::egui::{self, Align2, FontId, Sense};

use crate::i18n::tr;
use crate::render::Renderer;
use crate::render::build::{VectorScales, build};
use crate::render::shape::SharedShapes;
use crate::render::view::Camera;
use crate::session::words::length;
use crate::state::AppState;
use crate::ui::label_place::{Obstacles, place_clear_of};
use crate::ui::point_drag::PointDrag;

/// Room a pin's and a ground pivot's symbols take around the pin, points: a fit
/// keeps the mechanism's box this far inside the view.
const SYMBOL_ROOM: f32 = 28.0;

/// The view's own state: where it looks, what it drew, and the point being dragged.
#[derive(Clone, Debug, Default)]
pub struct Viewport {
    /// The view camera.
    pub camera: Camera,
    /// Vector scales of the last drawn frame.
    pub scales: VectorScales,
    /// The mechanism the view drew last: its generation and input angle, rad (UI
    /// tests check that an edit shows in the frame that makes it).
    pub drawn: Option<(u64, f64)>,
    /// A joint dragged, or the driver turned by hand.
    pub drag: PointDrag,
    /// What the camera was last fitted to: the view's rectangle, the mechanism's
    /// box and the legend's height. Until the user pans or zooms, a change of any
    /// fits anew (a length edited, a pane widened, the window resized).
    fitted_to: Option<(egui::Rect, [f64; 4], f32)>,
    /// The part of the view the legend (top) and the message (bottom) covered last
    /// frame, points: the fit keeps the mechanism clear of them.
    overlay: [f32; 2],
    /// Where the joints' names went last frame (tests check they cover no pin).
    pub labels: Vec<(String, egui::Rect)>,
}

/// Pans the camera by a drag (where `pan`) or two fingers, and zooms it by the wheel
/// about the pointer or by a pinch about the fingers' centre.
pub fn navigate(
    ui: &egui::Ui,
    response: &egui::Response,
    rect: egui::Rect,
    camera: &mut Camera,
    pan: bool,
) {
    // Two or more fingers on the view: their centre pans and their spread zooms about
    // it. egui would zoom about its pointer (the first finger) and pan by that
    // finger's drag: the picture would slide away under the pinch.
    if let Some(touch) = ui.input(|i| i.multi_touch())
        && rect.contains(touch.center_pos)
    {
        camera.pan(touch.translation_delta);
        if (touch.zoom_delta - 1.0).abs() > 1e-6 {
            camera.zoom_at(f64::from(touch.zoom_delta), touch.center_pos, rect);
        }
        return;
    }
    if pan && response.dragged() {
        camera.pan(response.drag_delta());
    }
    if response.hovered() {
        let (zoom, scroll, pointer) = ui.input(|i| {
            (
                i.zoom_delta(),
                i.smooth_scroll_delta.y,
                i.pointer.hover_pos(),
            )
        });
        let factor = f64::from(zoom) * (f64::from(scroll) / 400.0).exp();
        if let Some(p) = pointer
            && (factor - 1.0).abs() > 1e-6
        {
            camera.zoom_at(factor, p, rect);
        }
    }
}

impl Viewport {
    /// Draws the view with `renderer` (`None`: a message says there is no GPU); returns
    /// the µs spent building its shapes.
    pub fn ui(
        &mut self,
        ui: &mut egui::Ui,
        st: &mut AppState,
        shapes: &SharedShapes,
        renderer: Option<&Renderer>,
    ) -> f64 {
        let (rect, response) = ui.allocate_exact_size(ui.available_size(), Sense::click_and_drag());
        st.controls.view = Some([rect.min.x, rect.min.y, rect.max.x, rect.max.y]);
        self.fit(ui, rect, st);
        let moving_point =
            crate::ui::point_drag::handle(ui, &response, rect, st, &self.camera, &mut self.drag);
        // A dragged point or a crank turned by hand shows where the pointer is now.
        st.apply_commands();
        navigate(ui, &response, rect, &mut self.camera, !moving_point);
        if response.double_clicked() {
            st.commands.fit = true;
        }

        let ppp = ui.ctx().pixels_per_point();
        let view = self.camera.uniform(rect, ppp);
        let started = web_time::Instant::now();
        if let Ok(mut list) = shapes.lock() {
            let ([x0, y1], [x1, y0]) = (
                self.camera.to_world(rect.left_top(), rect),
                self.camera.to_world(rect.right_bottom(), rect),
            );
            self.scales = build(
                &mut list,
                &st.session,
                &self.camera,
                st.view.layers,
                f64::from(view.m_per_px),
                [x0, y0, x1, y1],
            );
        }
        let build_us = started.elapsed().as_secs_f64() * 1e6;
        self.drawn = Some((st.session.generation(), st.session.input_rad()));

        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 0.0, egui::Color32::from_rgb(246, 246, 242));
        paint_shapes(&painter, rect, view, shapes, renderer);

        self.labels = point_labels(&painter, rect, st, &self.camera, self.scales);
        if st.view.layers.centres {
            crate::ui::centres::overlay(&painter, rect, st, &self.camera);
        }
        self.overlay = legend(&painter, rect, st, self.scales);
        build_us
    }

    /// Fits the camera when asked, or when the view's rectangle or the mechanism's
    /// box changed and the user has not panned or zoomed since the last fit: once a
    /// slider or a pane is let go (while it is dragged the link grows in the view
    /// that was). A joint dragged in the view never refits it: the joint stays
    /// under the pointer. The mechanism is fitted below the legend and above the
    /// message.
    fn fit(&mut self, ui: &egui::Ui, rect: egui::Rect, st: &mut AppState) {
        if rect.width() <= 1.0 || rect.height() <= 1.0 {
            return;
        }
        let bounds = st.session.curves().bounds_m;
        let key = (rect, bounds, self.overlay[0]);
        if self.drag.active() {
            self.fitted_to = Some(key);
        }
        let changed = self.fitted_to != Some(key);
        let gesture = ui.input(|i| i.pointer.any_down());
        if st.commands.fit || (changed && !self.camera.by_hand && !gesture) {
            // Below the legend, above the message, and clear of the edges by the
            // size of a ground pivot's symbol (drawn in points around its pin).
            let [top, bottom] = self.overlay;
            let inner = egui::Rect::from_min_max(
                rect.min + egui::vec2(0.0, top),
                rect.max - egui::vec2(0.0, bottom),
            )
            .shrink(SYMBOL_ROOM);
            self.camera.fit_within(bounds, rect, inner);
            self.fitted_to = Some(key);
            st.commands.fit = false;
        }
    }
}

/// Where point `p` of the pose shows in the view; `None` when not finite.
fn on_screen(
    pose: &linkage::Solution,
    camera: &Camera,
    rect: egui::Rect,
    p: linkage::PointId,
) -> Option<egui::Pos2> {
    let q = pose.points[p].position;
    (q.x.is_finite() && q.y.is_finite()).then(|| camera.to_screen([q.x, q.y], rect))
}

/// What the names keep clear of: the pins, the links (a segment between each two
/// joints of a link), the ground symbols, the springs' coils and the arrows.
fn name_obstacles(
    st: &AppState,
    camera: &Camera,
    rect: egui::Rect,
    scales: VectorScales,
) -> Obstacles {
    let pose = st.session.pose();
    let m = st.session.mechanism();
    let topology = st.session.topology();
    let screen = |p| on_screen(pose, camera, rect, p);
    let mut obstacles = Obstacles {
        pins: topology
            .joint_points
            .iter()
            .filter_map(|&p| screen(p))
            .collect(),
        pin_radius: (crate::render::build::PIN_SHARE * m.size_m * camera.points_per_m) as f32,
        ..Obstacles::default()
    };
    for joints in &topology.link_joints {
        for (k, &a) in joints.iter().enumerate() {
            for &b in &joints[k + 1..] {
                if let (Some(a), Some(b)) = (screen(a), screen(b)) {
                    obstacles.segments.push([a, b]);
                }
            }
        }
    }
    ground_obstacles(&mut obstacles, st, camera, rect);
    // The springs' coils, along the line between their ends.
    for sp in &st.session.scene().forces.springs {
        let end = |name: &str| m.point_index(name).and_then(screen);
        if let (Some(a), Some(b)) = (end(&sp.a), end(&sp.b)) {
            obstacles.segments.push([a, b]);
        }
    }
    arrow_obstacles(&mut obstacles, st, camera, rect, scales);
    obstacles
}

/// The arrows at the joints, as the view draws them: their shafts and tips.
fn arrow_obstacles(
    obstacles: &mut Obstacles,
    st: &AppState,
    camera: &Camera,
    rect: egui::Rect,
    scales: VectorScales,
) {
    let pose = st.session.pose();
    let layers = st.view.layers;
    for &p in &st.session.topology().joint_points {
        let pm = &pose.points[p];
        for (on, v, scale) in [
            (layers.velocities, pm.velocity, scales.velocity),
            (layers.accelerations, pm.acceleration, scales.acceleration),
        ] {
            let tip = pm.position + v * scale;
            if on && scale > 0.0 && tip.x.is_finite() && tip.y.is_finite() {
                let from = camera.to_screen([pm.position.x, pm.position.y], rect);
                let tip = camera.to_screen([tip.x, tip.y], rect);
                // A still joint's arrow is no arrow: its tip is its pin.
                if from.distance(tip) > 2.0 {
                    obstacles.segments.push([from, tip]);
                    obstacles.tips.push(tip);
                }
            }
        }
    }
}

/// The joints' names beside them, each where it covers no other pin, link, arrow
/// or name ([`label_place`]); returns where each went (tests check them).
fn point_labels(
    painter: &egui::Painter,
    rect: egui::Rect,
    st: &AppState,
    camera: &Camera,
    scales: VectorScales,
) -> Vec<(String, egui::Rect)> {
    let pose = st.session.pose();
    let m = st.session.mechanism();
    let topology = st.session.topology();
    let screen = |p| on_screen(pose, camera, rect, p);
    let mut obstacles = name_obstacles(st, camera, rect, scales);
    let font = FontId::proportional(13.0);
    let ink = egui::Color32::from_gray(30);
    let block = (crate::render::build::block_reach_m(m.size_m) * camera.points_per_m) as f32;
    let named = named_points(st);
    obstacles.points = named
        .iter()
        .filter(|p| topology.joint_points.binary_search(p).is_err())
        .filter_map(|&p| screen(p))
        .collect();
    let mut placed = Vec::new();
    for p in named {
        let Some(at) = screen(p) else {
            continue;
        };
        let name = &m.points[p].name;
        let galley = painter.layout_no_wrap(name.clone(), font.clone(), ink);
        let on_block = m.sliders.iter().any(|sl| sl.point == p);
        let radius = if on_block { block } else { 0.0 };
        let spot = place_clear_of(at, radius, galley.size(), &obstacles);
        painter.galley(spot.min, galley, ink);
        obstacles.names.push(spot);
        placed.push((name.clone(), spot));
    }
    placed
}

/// The points the view names: every joint, every mark on a moving link (a coupler
/// point whose trace is drawn, a centroid, a load's point), and the points the
/// springs, forces and length sliders name (a spring's end on the frame, a guide's
/// point), each once. Before, only the joints: the flipper's coupler points and its
/// spring's ends F and G, and the guides' points H and Q of the sliders "AH" and
/// "O4-Q", named in the controls, were nowhere on the drawing.
fn named_points(st: &AppState) -> Vec<linkage::PointId> {
    let (m, topology) = (st.session.mechanism(), st.session.topology());
    let forces = &st.session.scene().forces;
    let by_forces = forces
        .springs
        .iter()
        .flat_map(|sp| [sp.a.as_str(), sp.b.as_str()])
        .chain(forces.point_forces.iter().map(|f| f.point.as_str()))
        .chain(
            st.session
                .lengths()
                .iter()
                .flat_map(|l| [l.from.as_str(), l.to.as_str()]),
        )
        .filter_map(|name| m.point_index(name));
    let mut points: Vec<linkage::PointId> = Vec::new();
    for p in topology
        .joint_points
        .iter()
        .chain(&topology.marks)
        .copied()
        .chain(by_forces)
    {
        if !points.contains(&p) {
            points.push(p);
        }
    }
    points
}

/// The frame's symbols as the view draws them (`render::build`): each ground
/// pivot's support triangle and hatched base below its pin, and each ground guide's
/// two rails over the slider's travel; a joint's name keeps off them.
fn ground_obstacles(obstacles: &mut Obstacles, st: &AppState, camera: &Camera, rect: egui::Rect) {
    let m = st.session.mechanism();
    let pose = st.session.pose();
    let pin = crate::render::build::PIN_SHARE * m.size_m.max(1e-12);
    let at = |p: linkage::Vec2| camera.to_screen([p.x, p.y], rect);
    for r in m
        .revolutes
        .iter()
        .filter(|r| r.a == m.ground || r.b == m.ground)
    {
        use crate::render::build::{PIVOT_HALF_BASE, PIVOT_HATCH, PIVOT_HEIGHT};
        let c = pose.points[r.point].position;
        let corner = |dx: f64, dy: f64| at(c + linkage::Vec2::new(dx * pin, dy * pin));
        let (l, r) = (
            corner(-PIVOT_HALF_BASE, -PIVOT_HEIGHT),
            corner(PIVOT_HALF_BASE, -PIVOT_HEIGHT),
        );
        // The hatching below the base.
        let down = corner(0.0, -PIVOT_HEIGHT - PIVOT_HATCH) - corner(0.0, -PIVOT_HEIGHT);
        obstacles
            .segments
            .extend([[at(c), l], [at(c), r], [l, r], [l + down, r + down]]);
    }
    for rails in crate::render::build::ground_guide_rails(&st.session) {
        let (a, b, off) = (rails.a, rails.b, rails.off);
        obstacles
            .segments
            .extend([[at(a + off), at(b + off)], [at(a - off), at(b - off)]]);
    }
}

/// The legend at the top left (the crank, the time, the vectors' scales, what a drag
/// does) and a refused edit's message at the bottom left (on a phone or tablet, the
/// last file action's line too); returns the heights they take at the top and the
/// bottom, points.
/// The view's colour, nearly opaque, behind the legend's and the message's text: a
/// mechanism the user zoomed or panned under them stays visible around the text and
/// the text stays readable over it.
fn backdrop(painter: &egui::Painter, text: egui::Rect) {
    let veil = egui::Color32::from_rgba_unmultiplied(246, 246, 242, 220);
    painter.rect_filled(text.expand(3.0), 3.0, veil);
}

fn legend(
    painter: &egui::Painter,
    rect: egui::Rect,
    st: &AppState,
    scales: VectorScales,
) -> [f32; 2] {
    let small = FontId::proportional(12.0);
    let deg = format!("{:.2}", st.session.input_rad().to_degrees());
    let mut legend = tr!("overlay.crank", deg = deg);
    if let Some(t) = st.session.run_time_shown() {
        legend += &format!(", t = {t:.3} s");
    }
    if st.view.layers.velocities && scales.velocity > 0.0 {
        // The arrows' scale in the scene's length unit, as its lengths are written.
        let drawn = length(scales.velocity, st.session.scene().length_unit);
        legend += &format!("\n{}", tr!("overlay.v_scale", drawn = drawn));
    }
    if st.view.layers.accelerations && scales.acceleration > 0.0 {
        let drawn = length(scales.acceleration, st.session.scene().length_unit);
        legend += &format!("\n{}", tr!("overlay.a_scale", drawn = drawn));
    }
    let how = match (st.view.edit_points, st.layout.compact()) {
        (true, _) => tr!("overlay.drag_points"),
        (false, false) => tr!("overlay.mouse"),
        (false, true) => tr!("overlay.touch"),
    };
    legend += &format!("\n{how}");
    let wrap = (rect.width() - 16.0).max(40.0);
    let top = painter.layout(legend, small, egui::Color32::from_gray(60), wrap);
    let top_height = top.size().y + 12.0;
    let at = rect.left_top() + egui::vec2(8.0, 8.0);
    backdrop(painter, egui::Rect::from_min_size(at, top.size()));
    painter.galley(at, top, egui::Color32::from_gray(60));
    let status = st
        .layout
        .compact()
        .then_some(st.status.as_deref())
        .flatten();
    let message = [
        st.session.message_in(crate::ui::words::lang()),
        status.map(str::to_owned),
    ]
    .into_iter()
    .flatten()
    .collect::<Vec<_>>()
    .join("\n");
    if message.is_empty() {
        return [top_height, 0.0];
    }
    let red = egui::Color32::from_rgb(170, 40, 20);
    let bottom = painter.layout(message, FontId::proportional(13.0), red, wrap);
    let bottom_height = bottom.size().y + 12.0;
    let at = rect.left_bottom() + egui::vec2(8.0, -8.0 - bottom.size().y);
    backdrop(painter, egui::Rect::from_min_size(at, bottom.size()));
    painter.galley(at, bottom, red);
    [top_height, bottom_height]
}

/// The GPU-drawn shapes in `rect`, or, without a renderer, a line saying why the view
/// is empty (the mechanism view and the drawing canvas both).
pub fn paint_shapes(
    painter: &egui::Painter,
    rect: egui::Rect,
    view: crate::render::shape::ViewUniform,
    shapes: &SharedShapes,
    renderer: Option<&Renderer>,
) {
    if let Some(renderer) = renderer {
        painter.add(renderer.paint_callback(rect, view, shapes));
    } else {
        painter.text(
            rect.center(),
            Align2::CENTER_CENTER,
            "no GPU renderer: the mechanism view needs a GPU or a CPU adapter",
            FontId::proportional(14.0),
            egui::Color32::DARK_RED,
        );
    }
}
