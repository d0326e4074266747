//! The App: the session (the mechanism and everything derived from it), the view
//! settings, and the panels laid out around the GPU-drawn mechanism view.

use eframe::egui;

use crate::render::Renderer;
use crate::render::build::{Layers, VectorScales};
use crate::render::shape::SharedShapes;
use crate::render::view::Camera;
use crate::session::{SceneEdit, Session};
use crate::ui;

/// Scene opened at start when the URL names none.
pub const DEFAULT_SCENE: &str = "die_cutter";

/// Which plot the plot pane shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlotTab {
    /// Output displacement, velocity and acceleration against crank angle.
    Output,
    /// Transmission angle against crank angle.
    Transmission,
    /// Input torque and force amplification (kinetostatic scenes).
    Torque,
    /// omega-phi, omega-t and phi-t of the dynamic run.
    Motion,
    /// J(q) and M(q) (dynamic scenes).
    ReducedModel,
}

/// Smoothed CPU cost of a frame's work, µs.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrameCost {
    /// Solver: the pose, polygons and shapes of the frame.
    pub solver_us: f64,
    /// The whole `ui` call: solver, panels, plots and layout (not the GPU).
    pub frame_us: f64,
}

impl FrameCost {
    fn add(&mut self, solver_us: f64, frame_us: f64) {
        // Exponential average over about 30 frames: steady enough to read.
        let k = if self.frame_us == 0.0 {
            1.0
        } else {
            1.0 / 30.0
        };
        self.solver_us += k * (solver_us - self.solver_us);
        self.frame_us += k * (frame_us - self.frame_us);
    }
}

/// CPU time of the frames in which an edit landed: what a user dragging a slider
/// waits for (the frame's `ui` call: the edit, the panels and plots; not the GPU),
/// and of the edits alone (what `cargo bench --bench edit` measures natively).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct EditTiming {
    /// Frames that carried at least one edit.
    pub frames: u64,
    /// The last such frame, ms.
    pub last_ms: f64,
    /// The slowest such frame, ms.
    pub max_ms: f64,
    /// The last such frame's edits applied to the session, ms.
    pub last_edit_ms: f64,
    /// The slowest such frame's edits, ms.
    pub max_edit_ms: f64,
}

impl EditTiming {
    fn add(&mut self, frame_ms: f64, edit_ms: f64) {
        self.frames += 1;
        self.last_ms = frame_ms;
        self.max_ms = self.max_ms.max(frame_ms);
        self.last_edit_ms = edit_ms;
        self.max_edit_ms = self.max_edit_ms.max(edit_ms);
    }
}

/// Everything the panels read and change.
pub struct AppState {
    /// The mechanism being viewed.
    pub session: Session,
    /// The view camera.
    pub camera: Camera,
    /// Fit the view at the next frame (after opening a scene or on request).
    pub fit_pending: bool,
    /// Overlays on the mechanism.
    pub layers: Layers,
    /// Whether the animation runs.
    pub playing: bool,
    /// Animation speed, times real time.
    pub speed: f64,
    /// Plot pane tab.
    pub plot_tab: PlotTab,
    /// Vector scales of the last drawn frame.
    pub scales: VectorScales,
    /// Frame cost.
    pub cost: FrameCost,
    /// A line about the last file action (saved, exported, failed).
    pub status: Option<String>,
    /// File prompts and uploads.
    pub files: ui::files::Files,
    /// Show measured CPU times (off in snapshot tests, whose pixels must repeat).
    pub show_timings: bool,
    /// Where this frame's controls are (tests drive the app through it).
    pub controls: ui::control_map::ControlMap,
    /// How long the frames that carried an edit took.
    pub edit_timing: EditTiming,
    /// The mechanism the view drew last: its generation and input angle, rad (UI
    /// tests check that an edit shows in the frame that makes it).
    pub view_drawn: Option<(u64, f64)>,
    /// The edits the panels asked for and not yet applied ([`AppState::apply_edits`]).
    pub edits: Vec<SceneEdit>,
    /// Time spent applying this frame's edits so far, ms.
    pub edit_ms: f64,
    /// Counts scenes opened (a frame that opens one is an edit frame).
    pub opened: u64,
    /// The polygon term under the pointer last frame (in a figure or its table row).
    pub polygon_hover: Option<linkage::polygon::Symbol>,
    /// Whether the polygon pane takes half the window.
    pub polygons_wide: bool,
    /// The equation being constructed step by step, and the step.
    pub construction: ui::construction::ConstructionView,
    /// A scene waiting to replace one with unsaved edits, until the user says so.
    pub pending_open: Option<Box<Session>>,
    /// A new drawing waiting, likewise.
    pub pending_drawing: bool,
    /// Whether dragging in the view moves points (else it pans).
    pub edit_points: bool,
    /// The point being dragged, by name.
    pub dragged_point: Option<String>,
    /// While the driver is turned by hand: its grabbed point's angle from the input.
    pub turning: Option<f64>,
    /// The mechanism being drawn, while the drawing tools are out.
    pub builder: Option<crate::builder::Builder>,
    /// The synthesis window, while open.
    pub synthesis: Option<ui::synthesis::SynthesisView>,
    /// The arrangement of the panels for the screen, and the sheet's tab.
    pub layout: ui::layout::LayoutState,
}

impl AppState {
    /// State over `session`, paused, fitted at the first frame.
    pub fn new(session: Session) -> Self {
        Self {
            session,
            camera: Camera::default(),
            fit_pending: true,
            layers: Layers::default(),
            playing: false,
            speed: 1.0,
            plot_tab: PlotTab::Output,
            scales: VectorScales::default(),
            cost: FrameCost::default(),
            status: None,
            files: ui::files::Files::default(),
            show_timings: true,
            controls: ui::control_map::ControlMap::default(),
            edit_timing: EditTiming::default(),
            view_drawn: None,
            edits: Vec::new(),
            edit_ms: 0.0,
            opened: 0,
            polygon_hover: None,
            polygons_wide: false,
            construction: Default::default(),
            pending_open: None,
            pending_drawing: false,
            edit_points: false,
            dragged_point: None,
            turning: None,
            builder: None,
            synthesis: None,
            layout: Default::default(),
        }
    }

    /// Asks for `edit` to the session: the panels ask while they are laid out, and
    /// the app applies the edits between panels, so that no panel sees the session
    /// change under it.
    pub fn edit(&mut self, edit: SceneEdit) {
        self.edits.push(edit);
    }

    /// Applies the edits asked for, in order, and adds their time to the frame's.
    pub fn apply_edits(&mut self) {
        if self.edits.is_empty() {
            return;
        }
        let started = web_time::Instant::now();
        for edit in std::mem::take(&mut self.edits) {
            self.session.apply(edit);
        }
        self.edit_ms += started.elapsed().as_secs_f64() * 1e3;
    }

    /// Replaces the session (a new scene), keeping the view settings.
    pub fn open(&mut self, session: Session) {
        if self.session.is_dirty() {
            // The user says first whether the unsaved edits may go
            // (`ui::scene_picker::discard_question`).
            self.pending_open = Some(Box::new(session));
            return;
        }
        self.open_now(session);
    }

    /// Opens `session` whatever the current one holds.
    pub fn open_now(&mut self, session: Session) {
        self.pending_open = None;
        self.builder = None;
        // Edits asked of the old scene mean nothing to the new one.
        self.edits.clear();
        self.session = session;
        self.opened += 1;
        self.fit_pending = true;
        self.playing = false;
        if !ui::plots::tab_available(self.plot_tab, &self.session) {
            self.plot_tab = PlotTab::Output;
        }
    }
}

/// The Linkage Lab application.
pub struct LinkageApp {
    /// The state the panels work on (public for UI tests).
    pub state: AppState,
    shapes: SharedShapes,
    renderer: Option<Renderer>,
    frames_drawn: u64,
    exit_after_frames: Option<u64>,
    #[cfg(target_arch = "wasm32")]
    url: crate::web::UrlSync,
    #[cfg(target_arch = "wasm32")]
    fragment_watch: crate::web::FragmentWatch,
    #[cfg(target_arch = "wasm32")]
    drawing_store: crate::web::DrawingStore,
}

impl LinkageApp {
    /// Creates the app over the default scene (on the web, the URL's scene; on the
    /// desktop, `start.scene`).
    pub fn new(cc: &eframe::CreationContext<'_>, start: crate::StartOptions) -> Self {
        cc.egui_ctx.set_fonts(crate::fonts::definitions());
        let renderer = Renderer::install(cc);
        let session = match start.scene.as_deref().map(Session::open_builtin) {
            Some(Ok(s)) => (s, None),
            Some(Err(e)) => {
                log::error!("{e}; opening the default scene");
                initial_session()
            }
            None => initial_session(),
        };
        let (session, why_not) = session;
        let mut state = AppState::new(session);
        state.status = why_not;
        state.playing = start.play;
        #[cfg(target_arch = "wasm32")]
        match crate::web::stored_drawing() {
            Some(Ok(sketch)) => ui::drawing::resume(&mut state, sketch),
            Some(Err(why)) => state.status = Some(why),
            None => {}
        }
        #[cfg(not(target_arch = "wasm32"))]
        if let Some(path) = &start.file {
            ui::files::open_path(&mut state, path);
        }
        Self {
            state,
            shapes: SharedShapes::default(),
            renderer,
            frames_drawn: 0,
            exit_after_frames: start.exit_after_frames,
            #[cfg(target_arch = "wasm32")]
            url: crate::web::UrlSync::default(),
            #[cfg(target_arch = "wasm32")]
            fragment_watch: crate::web::FragmentWatch::default(),
            #[cfg(target_arch = "wasm32")]
            drawing_store: crate::web::DrawingStore::default(),
        }
    }

    /// Whether the GPU renderer is installed (else the view says so).
    pub fn has_gpu(&self) -> bool {
        self.renderer.is_some()
    }
}

/// CPU a frame may take before it draws, ms: a 60 Hz frame leaves the rest of its
/// 16.7 ms to tessellation and the GPU.
const FRAME_BUDGET_MS: f64 = 10.0;

/// The least a dynamic run computed on this thread advances in a frame without an
/// edit, ms: slow frames still let it finish.
const MIN_RUN_SLICE_MS: f64 = 1.0;

/// Ctrl+Z (Cmd+Z on a Mac) undoes; Ctrl+Shift+Z and Ctrl+Y redo.
fn undo_shortcuts(ui: &egui::Ui, st: &mut AppState) {
    use egui::{Key, KeyboardShortcut, Modifiers};
    let redo = [
        KeyboardShortcut::new(Modifiers::COMMAND | Modifiers::SHIFT, Key::Z),
        KeyboardShortcut::new(Modifiers::COMMAND, Key::Y),
    ];
    // The shift variant first: Ctrl+Z also matches Ctrl+Shift+Z logically.
    if redo
        .iter()
        .any(|k| ui.ctx().input_mut(|i| i.consume_shortcut(k)))
    {
        ui::drawing::redo_any(st);
    } else if ui
        .ctx()
        .input_mut(|i| i.consume_shortcut(&KeyboardShortcut::new(Modifiers::COMMAND, Key::Z)))
    {
        ui::drawing::undo_any(st);
    }
}

/// What a frame does after its panels: in a frame that carried no edit, the analyses
/// the panels showed out of date, and the dynamic run for what is left of the frame's
/// budget; in a frame that carried one, neither (what the edit made out of date
/// follows in the next frame). Returns whether more frames are needed.
fn follow_up(session: &mut Session, edited: bool, frame_started: web_time::Instant) -> bool {
    if edited {
        // A new run has just started: nothing to take from it yet.
        return true;
    }
    let caught_up = session.catch_up();
    let spent_ms = frame_started.elapsed().as_secs_f64() * 1e3;
    let slice_ms = (FRAME_BUDGET_MS - spent_ms).max(MIN_RUN_SLICE_MS);
    session.poll_run(slice_ms) || caught_up
}

/// The scene the app starts on, and why it is not the one asked for, if it is not.
#[cfg(not(target_arch = "wasm32"))]
fn initial_session() -> (Session, Option<String>) {
    (open_or_explain(DEFAULT_SCENE), None)
}

/// The scene the page's URL fragment names (or carries), else the default one with
/// the reason shown: a link is user input.
#[cfg(target_arch = "wasm32")]
fn initial_session() -> (Session, Option<String>) {
    let fragment = crate::web::fragment();
    let st = crate::session::url_state::decode(&fragment);
    match crate::session::url_state::open(&st) {
        Ok(s) => (s, None),
        Err(e) if fragment.len() > 1 => {
            log::warn!("the link's scene did not open: {e}");
            (
                open_or_explain(DEFAULT_SCENE),
                Some(format!("the link's scene did not open: {e}")),
            )
        }
        Err(_) => (open_or_explain(DEFAULT_SCENE), None),
    }
}

/// Opens a shipped scene; the shipped scenes are tested to open, so failure is a
/// broken build, which the first scene in the catalog stands in for.
fn open_or_explain(key: &str) -> Session {
    Session::open_builtin(key)
        .or_else(|e| {
            log::error!("{e}");
            Session::open_builtin(crate::catalog::BUILTIN_SCENES[0].key)
        })
        .unwrap_or_else(|e| panic!("no shipped scene opens: {e}"))
}

impl LinkageApp {
    /// The viewer: report strip, controls, polygons, plots and the mechanism view
    /// (on a phone or tablet, the view and a sheet of tabs).
    fn viewer_panels(&mut self, ui: &mut egui::Ui, solver_us: &mut f64) {
        if self.state.layout.compact() {
            egui::CentralPanel::default_margins().show(ui, |ui| {
                let view = ui::sheet::show(ui, &mut self.state, false);
                let mut ui = ui.new_child(egui::UiBuilder::new().max_rect(view));
                *solver_us += ui::viewport::show(
                    &mut ui,
                    &mut self.state,
                    &self.shapes,
                    self.renderer.as_ref(),
                );
            });
            return;
        }
        ui::report::strip(ui, &self.state);
        egui::Panel::left("controls")
            .default_size(290.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| {
                    ui::controls::panel(ui, &mut self.state);
                    ui.separator();
                    ui::accuracy::panel(ui, &mut self.state);
                });
            });
        // The controls' edits land before the polygons, plots and view are laid out,
        // so that all of them show the edit in this frame.
        self.state.apply_edits();
        let polygons = egui::Panel::right("polygons").default_size(360.0);
        // Enlarged, the polygons share the room beside the controls equally with the
        // mechanism.
        let polygons = if self.state.polygons_wide {
            polygons.exact_size(0.5 * ui.available_width())
        } else {
            polygons
        };
        polygons.show(ui, |ui| {
            egui::ScrollArea::vertical().show(ui, |ui| ui::polygons::panel(ui, &mut self.state));
        });
        egui::Panel::bottom("plots")
            .default_size(230.0)
            .show(ui, |ui| ui::plots::panel(ui, &mut self.state));
        egui::CentralPanel::default_margins().show(ui, |ui| {
            *solver_us +=
                ui::viewport::show(ui, &mut self.state, &self.shapes, self.renderer.as_ref());
        });
    }

    /// While drawing: the tools beside the drawing; the report, plots and polygons
    /// once the drawing is a mechanism.
    fn drawing_panels(&mut self, ui: &mut egui::Ui) {
        if self.state.layout.compact() {
            egui::CentralPanel::default_margins().show(ui, |ui| {
                let view = ui::sheet::show(ui, &mut self.state, true);
                let mut ui = ui.new_child(egui::UiBuilder::new().max_rect(view));
                ui::builder_canvas::show(
                    &mut ui,
                    &mut self.state,
                    &self.shapes,
                    self.renderer.as_ref(),
                );
            });
            return;
        }
        let complete = self
            .state
            .builder
            .as_ref()
            .is_some_and(|b| b.problem.is_none());
        if complete {
            ui::report::strip(ui, &self.state);
        }
        egui::Panel::left("controls")
            .default_size(290.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical()
                    .show(ui, |ui| ui::builder_panel::panel(ui, &mut self.state));
            });
        if complete {
            egui::Panel::right("polygons")
                .default_size(360.0)
                .show(ui, |ui| {
                    egui::ScrollArea::vertical()
                        .show(ui, |ui| ui::polygons::panel(ui, &mut self.state));
                });
            egui::Panel::bottom("plots")
                .default_size(230.0)
                .show(ui, |ui| ui::plots::panel(ui, &mut self.state));
        }
        egui::CentralPanel::default_margins().show(ui, |ui| {
            ui::builder_canvas::show(ui, &mut self.state, &self.shapes, self.renderer.as_ref());
        });
    }
}

impl eframe::App for LinkageApp {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        let started = web_time::Instant::now();
        if self.state.layout.update(ui.ctx()) {
            // A phone turned, a window resized past the breakpoint: the view changed
            // shape.
            self.state.fit_pending = true;
        }
        self.state.edit_ms = 0.0;
        let edits_before = (self.state.opened, self.state.session.edit_count());
        self.state.controls.clear();
        let dt = f64::from(ui.input(|i| i.stable_dt)).min(0.1);
        let solver_started = web_time::Instant::now();
        if self.state.playing {
            self.state.session.advance(dt, self.state.speed);
            ui.ctx().request_repaint();
        }
        let mut solver_us = solver_started.elapsed().as_secs_f64() * 1e6;
        // Space plays and pauses, Ctrl+Z undoes, Ctrl+Shift+Z or Ctrl+Y redoes, unless
        // a text field has the keyboard (it has its own undo).
        if !ui.ctx().egui_wants_keyboard_input() {
            if ui.input(|i| i.key_pressed(egui::Key::Space)) {
                self.state.playing = !self.state.playing;
            }
            undo_shortcuts(ui, &mut self.state);
        }

        ui::files::take_dropped(ui.ctx(), &mut self.state);
        #[cfg(target_arch = "wasm32")]
        {
            self.fragment_watch.install(ui.ctx());
            if self.fragment_watch.take() {
                crate::web::follow_fragment(&mut self.state, &mut self.url);
            }
        }
        ui::scene_picker::top_bar(ui, &mut self.state, frame);
        if self.state.builder.is_some() {
            self.drawing_panels(ui);
        } else {
            self.viewer_panels(ui, &mut solver_us);
        }
        ui::synthesis::window(ui.ctx(), &mut self.state);
        ui::files::drop_hint(ui.ctx());
        // What the panels after the view asked for (the polygons' and plots' own
        // controls, the shortcuts) shows next frame, which `follow_up` asks for.
        self.state.apply_edits();

        let edited = (self.state.opened, self.state.session.edit_count()) != edits_before;
        if !edited && !ui.input(|i| i.pointer.any_down()) {
            // A slider let go: its drag is one undo step.
            self.state.session.end_gesture();
        }
        if follow_up(&mut self.state.session, edited, started) {
            ui.ctx().request_repaint();
        }
        let frame_us = started.elapsed().as_secs_f64() * 1e6;
        if self.frames_drawn > 0 {
            // The first frame lays out every glyph and builds the pipelines: a cost
            // paid once, which an average over frames would carry for hundreds.
            self.state.cost.add(solver_us, frame_us);
        }
        if edited {
            self.state
                .edit_timing
                .add(frame_us * 1e-3, self.state.edit_ms);
        }
        #[cfg(target_arch = "wasm32")]
        {
            if let Some(why) = self.url.update(&self.state.session) {
                self.state.status = Some(why);
            }
            self.drawing_store.update(self.state.builder.as_ref());
            crate::web::publish_controls(
                &self.state,
                self.frames_drawn + 1,
                self.renderer.is_some(),
            );
        }
        self.frames_drawn += 1;
        #[cfg(target_arch = "wasm32")]
        if self.frames_drawn == 1 {
            // The browser test reads this line to measure the time to first frame.
            let now = web_sys::window()
                .and_then(|w| w.performance())
                .map_or(f64::NAN, |p| p.now());
            log::info!("linkage-lab first frame at {now:.0} ms");
        }
        if let Some(n) = self.exit_after_frames {
            // egui repaints only on input: a smoke run has to ask for every frame.
            ui.ctx().request_repaint();
            if self.frames_drawn == n {
                // Printed, not logged: the smoke run reads it without a logger.
                println!(
                    "{} frames, mean CPU per frame {:.1} us (solver {:.1} us)",
                    self.frames_drawn, self.state.cost.frame_us, self.state.cost.solver_us
                );
                ui.ctx().send_viewport_cmd(egui::ViewportCommand::Close);
            }
        }
    }
}
