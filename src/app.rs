//! The App: the session (the mechanism and everything derived from it), the view
//! settings, and the panels laid out around the GPU-drawn mechanism view.

use eframe::egui;

use crate::command::Command;
use crate::render::Renderer;
use crate::render::shape::SharedShapes;
use crate::session::Session;
use crate::state::{AppState, DEFAULT_SCENE};
use crate::ui;
use crate::ui::control_map::ControlKind;

/// What `logic` measured and saw before the panels, for the frame's accounts.
struct FrameStart {
    /// When the frame began.
    started: web_time::Instant,
    /// Scenes opened and edits made before it (a frame that changes them carried an
    /// edit).
    edits_before: (u64, u64),
    /// The solver's part of it so far (the animation's step), µs.
    solver_us: f64,
}

/// The Linkage Lab application.
pub struct LinkageApp {
    /// The state the panels work on (public for UI tests).
    pub state: AppState,
    /// The panels' own state (public for UI tests).
    pub panels: ui::panels::Panels,
    shapes: SharedShapes,
    renderer: Option<Renderer>,
    frame_start: Option<FrameStart>,
    frames_drawn: u64,
    exit_after_frames: Option<u64>,
    #[cfg(target_arch = "wasm32")]
    url: crate::web::UrlSync,
    #[cfg(target_arch = "wasm32")]
    fragment_watch: crate::web::FragmentWatch,
    #[cfg(target_arch = "wasm32")]
    drawing_store: crate::web::DrawingStore,
    /// The Chinese face, fetched once Chinese text is shown.
    #[cfg(target_arch = "wasm32")]
    cjk_font: crate::web_font::CjkFont,
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
        state.language = start.language;
        state.remember_choices = start.remember_choices;
        // Natively the command line's file sets the file dialog's folder.
        #[cfg_attr(target_arch = "wasm32", allow(unused_mut))]
        let mut panels = ui::panels::Panels::default();
        state.status = why_not;
        state.play.playing = start.play;
        #[cfg(target_arch = "wasm32")]
        match crate::web::stored_drawing() {
            Some(Ok(drawing)) => {
                state.push(Command::ResumeDrawing(Box::new(drawing)));
                state.apply_commands();
            }
            Some(Err(why)) => state.status = Some(why),
            None => {}
        }
        #[cfg(target_arch = "wasm32")]
        if let Some((key, student)) = crate::exercise_desk::exercise_link(&crate::web::fragment()) {
            state.open_exercise_link(&key, student.as_deref());
            state.apply_commands();
        }
        #[cfg(not(target_arch = "wasm32"))]
        if let Some(path) = &start.file {
            panels.files.open_path(&mut state, path);
        }
        Self {
            state,
            panels,
            shapes: SharedShapes::default(),
            renderer,
            frame_start: None,
            frames_drawn: 0,
            exit_after_frames: start.exit_after_frames,
            #[cfg(target_arch = "wasm32")]
            url: crate::web::UrlSync::default(),
            #[cfg(target_arch = "wasm32")]
            fragment_watch: crate::web::FragmentWatch::default(),
            #[cfg(target_arch = "wasm32")]
            drawing_store: crate::web::DrawingStore::default(),
            #[cfg(target_arch = "wasm32")]
            cjk_font: crate::web_font::CjkFont::watch(&cc.egui_ctx),
        }
    }

    /// Carries out the commands that reach past the model to the panels: the
    /// synthesis window opened or closed. Taken right after the top bar that gives
    /// them, before the panels are laid out, so that a window opens in that frame.
    fn take_app_commands(&mut self) {
        if std::mem::take(&mut self.state.commands.toggle_synthesis) {
            self.panels.synthesis.toggle();
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
fn undo_shortcuts(ctx: &egui::Context, st: &mut AppState) {
    use egui::{Key, KeyboardShortcut, Modifiers};
    let redo = [
        KeyboardShortcut::new(Modifiers::COMMAND | Modifiers::SHIFT, Key::Z),
        KeyboardShortcut::new(Modifiers::COMMAND, Key::Y),
    ];
    // The shift variant first: Ctrl+Z also matches Ctrl+Shift+Z logically.
    if redo
        .iter()
        .any(|k| ctx.input_mut(|i| i.consume_shortcut(k)))
    {
        st.push(Command::Redo);
    } else if ctx
        .input_mut(|i| i.consume_shortcut(&KeyboardShortcut::new(Modifiers::COMMAND, Key::Z)))
    {
        st.push(Command::Undo);
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
    // An exercise's link opens the desk (`LinkageApp::new`) over the default scene.
    let exercise = crate::exercise_desk::exercise_link(&fragment).is_some();
    match crate::session::url_state::open(&st) {
        Ok(s) => (s, None),
        Err(e) if fragment.len() > 1 && !exercise => {
            log::warn!("the link's scene did not open: {e}");
            (
                open_or_explain(DEFAULT_SCENE),
                Some(crate::i18n::tr!(
                    "file.link_failed",
                    why = e.words(crate::ui::words::lang())
                )),
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
                let view = ui::sheet::show(ui, &mut self.state, &mut self.panels, false);
                let mut ui = ui.new_child(egui::UiBuilder::new().max_rect(view));
                *solver_us += self.panels.viewport.ui(
                    &mut ui,
                    &mut self.state,
                    &self.shapes,
                    self.renderer.as_ref(),
                );
            });
            return;
        }
        ui::report::strip(ui, &self.state);
        self.controls_pane(ui, |ui, st| {
            ui::controls::panel(ui, st);
            ui.separator();
            ui::accuracy::panel(ui, st);
        });
        // The controls' edits land before the polygons, plots and view are laid out,
        // so that all of them show the edit in this frame.
        self.state.apply_commands();
        self.polygon_and_plot_panes(ui);
        egui::CentralPanel::default_margins().show(ui, |ui| {
            *solver_us +=
                self.panels
                    .viewport
                    .ui(ui, &mut self.state, &self.shapes, self.renderer.as_ref());
        });
    }

    /// The controls pane on the left, scrolled, within its limits
    /// ([`ui::panel_budget`]); at its least width while the polygons are enlarged.
    fn controls_pane(
        &mut self,
        ui: &mut egui::Ui,
        contents: impl FnOnce(&mut egui::Ui, &mut AppState),
    ) {
        let window = ui.ctx().content_rect().size();
        let limits = ui::panel_budget::controls(ui.available_rect_before_wrap(), window);
        let layout = self.state.layout;
        let pane = if layout.polygons_wide && self.state.drawing.is_none() {
            egui::Panel::left(layout.panel_id("controls")).exact_size(limits.range.min)
        } else {
            egui::Panel::left(layout.panel_id("controls"))
                .default_size(limits.default)
                .size_range(limits.range)
        };
        let shown = pane.show(ui, |ui| {
            // Vertically: a row wider than the pane widens it up to its limit, past
            // which egui clips the left pane at its right edge (a right pane would
            // run off the window: the polygons scroll both ways).
            egui::ScrollArea::vertical().show(ui, |ui| contents(ui, &mut self.state));
        });
        self.state
            .controls
            .note_rect(ControlKind::Pane, "controls", shown.response.rect, true);
    }

    /// The polygon pane on the right and the plot pane below the view, each within
    /// what the panes before it left the view ([`ui::panel_budget`]); each scrolls
    /// inside itself, so that what it holds never pushes the view away.
    fn polygon_and_plot_panes(&mut self, ui: &mut egui::Ui) {
        let window = ui.ctx().content_rect().size();
        let layout = self.state.layout;
        let limits = ui::panel_budget::polygons(ui.available_rect_before_wrap(), window);
        // Enlarged, the pane takes all the view's share leaves.
        let polygons = if layout.polygons_wide {
            egui::Panel::right(layout.panel_id("polygons")).exact_size(limits.largest())
        } else {
            egui::Panel::right(layout.panel_id("polygons"))
                .default_size(limits.default)
                .size_range(limits.range)
        };
        let shown = polygons.show(ui, |ui| self.panels.polygons.ui(ui, &mut self.state));
        let controls = &mut self.state.controls;
        controls.note_rect(ControlKind::Pane, "polygons", shown.response.rect, true);
        let limits = ui::panel_budget::plots(ui.available_rect_before_wrap(), window);
        let shown = egui::Panel::bottom(layout.panel_id("plots"))
            .default_size(limits.default)
            .size_range(limits.range)
            .show(ui, |ui| self.panels.plots.ui(ui, &mut self.state));
        let controls = &mut self.state.controls;
        controls.note_rect(ControlKind::Pane, "plots", shown.response.rect, true);
    }

    /// The gear-cutting lab in place of the mechanism: its controls in the side pane
    /// (on a phone or tablet, above the canvas), the canvas in the middle.
    fn gear_lab_panels(&mut self, ui: &mut egui::Ui) {
        if self.state.layout.compact() {
            egui::Panel::top(self.state.layout.panel_id("gear lab"))
                .resizable(true)
                .default_size(ui.available_height() * 0.4)
                .show(ui, |ui| {
                    egui::ScrollArea::vertical()
                        .show(ui, |ui| ui::gear_lab::panel(ui, &mut self.state));
                });
        } else {
            self.controls_pane(ui, ui::gear_lab::panel);
        }
        egui::CentralPanel::default_margins().show(ui, |ui| {
            ui::gear_lab::canvas(ui, &mut self.state, &self.shapes, self.renderer.as_ref());
        });
    }

    /// An exercise open: its pane at the side (on a phone or tablet, above), the
    /// mechanism (or the cam) in the middle; nothing of the analyses.
    fn exercise_panels(&mut self, ui: &mut egui::Ui, solver_us: &mut f64) {
        if self.state.layout.compact() {
            // The questions need room: half the screen, at least.
            let half = ui.available_height() * 0.5;
            egui::Panel::top(self.state.layout.panel_id("exercise"))
                .resizable(true)
                .default_size(half)
                .min_size(half)
                .show(ui, |ui| {
                    egui::ScrollArea::vertical()
                        .show(ui, |ui| ui::exercise::panel(ui, &mut self.state));
                });
        } else {
            self.controls_pane(ui, ui::exercise::panel);
        }
        self.state.apply_commands();
        egui::CentralPanel::default_margins().show(ui, |ui| {
            if ui::exercise_cam::show(ui, &self.state) {
                return;
            }
            *solver_us +=
                self.panels
                    .viewport
                    .ui(ui, &mut self.state, &self.shapes, self.renderer.as_ref());
        });
    }

    /// While drawing: the tools beside the drawing; the report, plots and polygons
    /// once the drawing is a mechanism.
    fn drawing_panels(&mut self, ui: &mut egui::Ui) {
        if self.state.layout.compact() {
            egui::CentralPanel::default_margins().show(ui, |ui| {
                let view = ui::sheet::show(ui, &mut self.state, &mut self.panels, true);
                let mut ui = ui.new_child(egui::UiBuilder::new().max_rect(view));
                ui::drawing_canvas::show(
                    &mut ui,
                    &mut self.state,
                    &mut self.panels.viewport.camera,
                    &self.shapes,
                    self.renderer.as_ref(),
                );
            });
            return;
        }
        let complete = self
            .state
            .drawing
            .as_ref()
            .is_some_and(|b| b.problem.is_none());
        if complete {
            ui::report::strip(ui, &self.state);
        }
        self.controls_pane(ui, ui::drawing_panel::panel);
        // The tools' edits land before the canvas and the panes are laid out, as the
        // controls' do in the viewer.
        self.state.apply_commands();
        if complete {
            self.polygon_and_plot_panes(ui);
        }
        egui::CentralPanel::default_margins().show(ui, |ui| {
            ui::drawing_canvas::show(
                ui,
                &mut self.state,
                &mut self.panels.viewport.camera,
                &self.shapes,
                self.renderer.as_ref(),
            );
        });
    }
}

impl eframe::App for LinkageApp {
    /// The frame's work before any panel is laid out: the screen's arrangement, the
    /// animation's step, the keyboard, dropped files, a changed address, and the
    /// commands the panels left that only the app can carry out.
    fn logic(&mut self, ctx: &egui::Context, frame: &mut eframe::Frame) {
        let started = web_time::Instant::now();
        let st = &mut self.state;
        if st.layout.update(ctx) {
            // A phone turned, a window resized past the breakpoint: the view changed
            // shape.
            st.commands.fit = true;
        }
        st.timing.edit_ms = 0.0;
        let edits_before = (st.timing.opened, st.session.edit_count());
        st.controls.clear();
        let dt = f64::from(ctx.input(|i| i.stable_dt)).min(0.1);
        if st.play.playing {
            st.session.advance(dt, st.play.speed);
            ctx.request_repaint();
        }
        if let Some(lab) = st.gear_lab.as_mut().filter(|lab| lab.playing) {
            lab.advance(dt);
            ctx.request_repaint();
        }
        let solver_us = started.elapsed().as_secs_f64() * 1e6;
        // Space plays and pauses, Ctrl+Z undoes, Ctrl+Shift+Z or Ctrl+Y redoes, unless
        // a text field has the keyboard (it has its own undo).
        if !ctx.egui_wants_keyboard_input() {
            if ctx.input(|i| i.key_pressed(egui::Key::Space)) {
                st.play.playing = !st.play.playing;
            }
            undo_shortcuts(ctx, st);
        }
        self.panels.files.take_dropped(ctx, st);
        self.panels.files.take_requested(ctx, st, frame);
        #[cfg(target_arch = "wasm32")]
        {
            self.fragment_watch.install(ctx);
            if self.fragment_watch.take() {
                crate::web::follow_fragment(&mut self.state, &mut self.url);
            }
        }
        self.frame_start = Some(FrameStart {
            started,
            edits_before,
            solver_us,
        });
    }

    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        let FrameStart {
            started,
            edits_before,
            mut solver_us,
        } = self.frame_start.take().unwrap_or_else(|| FrameStart {
            started: web_time::Instant::now(),
            edits_before: (self.state.timing.opened, self.state.session.edit_count()),
            solver_us: 0.0,
        });
        // Every word of this frame in the language chosen (`tr!` reads it).
        crate::i18n::set_language(self.state.language);
        ui::scene_picker::top_bar(ui, &mut self.state, &mut self.panels.files, frame);
        self.take_app_commands();
        if self.state.exercise.is_some() {
            self.exercise_panels(ui, &mut solver_us);
        } else if self.state.gear_lab.is_some() {
            self.gear_lab_panels(ui);
        } else if self.state.drawing.is_some() {
            self.drawing_panels(ui);
        } else {
            self.viewer_panels(ui, &mut solver_us);
        }
        self.panels.synthesis.ui(ui.ctx(), &mut self.state);
        ui::files::drop_hint(ui.ctx());
        // What the panels after the view asked for (the polygons' and plots' own
        // controls, the shortcuts) shows next frame, which `follow_up` asks for.
        self.state.apply_commands();

        let edited = (self.state.timing.opened, self.state.session.edit_count()) != edits_before;
        if !edited && !ui.input(|i| i.pointer.any_down()) {
            // A slider let go: its drag is one undo step.
            self.state.session.end_gesture();
        }
        let applied = std::mem::take(&mut self.state.commands.applied);
        if follow_up(&mut self.state.session, edited, started) || applied {
            ui.ctx().request_repaint();
        }
        let frame_us = started.elapsed().as_secs_f64() * 1e6;
        if self.frames_drawn > 0 {
            // The first frame lays out every glyph and builds the pipelines: a cost
            // paid once, which an average over frames would carry for hundreds.
            self.state.timing.cost.add(solver_us, frame_us);
        }
        if edited {
            let edit_ms = self.state.timing.edit_ms;
            self.state.timing.edit_timing.add(frame_us * 1e-3, edit_ms);
        }
        #[cfg(target_arch = "wasm32")]
        self.end_web_frame(ui.ctx());
        self.frames_drawn += 1;
        if let Some(n) = self.exit_after_frames {
            // egui repaints only on input: a smoke run has to ask for every frame.
            ui.ctx().request_repaint();
            if self.frames_drawn == n {
                // Printed, not logged: the smoke run reads it without a logger.
                println!(
                    "{} frames, mean CPU per frame {:.1} us (solver {:.1} us)",
                    self.frames_drawn,
                    self.state.timing.cost.frame_us,
                    self.state.timing.cost.solver_us
                );
                ui.ctx().send_viewport_cmd(egui::ViewportCommand::Close);
            }
        }
    }
}

#[cfg(target_arch = "wasm32")]
impl LinkageApp {
    /// What the page keeps in step with the app at the end of each frame: the URL,
    /// the stored drawing, the Chinese face, the controls the browser test reads, and
    /// on the first frame the time it was drawn.
    fn end_web_frame(&mut self, ctx: &egui::Context) {
        // While an exercise is open the address stays the exercise's link.
        if self.state.exercise.is_none()
            && let Some(why) = self.url.update(&self.state.session, self.state.language)
        {
            self.state.status = Some(why);
        }
        self.drawing_store.update(self.state.drawing.as_ref());
        self.cjk_font.update(ctx);
        crate::web::publish_controls(
            &self.state,
            &self.panels.viewport.camera,
            self.panels.synthesis.view(),
            self.frames_drawn + 1,
            self.renderer.is_some(),
        );
        if self.frames_drawn == 0 {
            // The browser test reads this line to measure the time to first frame.
            let now = web_sys::window()
                .and_then(|w| w.performance())
                .map_or(f64::NAN, |p| p.now());
            log::info!("linkage-lab first frame at {now:.0} ms");
        }
    }
}
