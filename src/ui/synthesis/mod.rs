//! The synthesis window: design a linkage from requirements and open it as the
//! scene. Crank-rocker from rocker length, swing and time ratio K; the die cutter's
//! toggle six-bar from stroke H, K and L; a function generator through precision
//! points (Freudenstein); a four-bar through three positions of a body (centre
//! points). Each shows its design table; "Open as scene" opens it (asking first
//! over unsaved edits), unsaved. The designs are closed form: computed on the click.

pub mod design;
pub mod fields;
pub mod figure;
pub mod path;

use eframe::egui;

use crate::i18n::tr;
use crate::session::SceneEdit;
use crate::session::{SceneSource, Session};
use crate::state::AppState;
use crate::synthesis::{Design, SynthError, SynthInputs, SynthKind};
use crate::ui::control_map::ControlKind;
pub use crate::ui::synthesis::design::{Chosen, design_view};
use crate::ui::synthesis::fields::number;
use crate::ui::synthesis::path::PathTab;

/// The window's inputs and its last design.
#[derive(Default)]
pub struct SynthesisView {
    /// What to design, from what.
    pub inputs: SynthInputs,
    /// The last design, or why there is none.
    pub result: Option<Result<Design, SynthError>>,
    /// The path tab's search and canvas.
    pub path: PathTab,
}

/// The synthesis window: its inputs and results while open, nothing while closed.
#[derive(Default)]
pub struct SynthesisWindow {
    view: Option<SynthesisView>,
}

impl SynthesisWindow {
    /// Opens the window (with fresh inputs) or closes it.
    pub fn toggle(&mut self) {
        self.view = match self.view.take() {
            Some(_) => None,
            None => Some(SynthesisView::default()),
        };
    }

    /// Whether the window is open.
    pub fn is_open(&self) -> bool {
        self.view.is_some()
    }

    /// The open window's inputs and results.
    pub fn view(&self) -> Option<&SynthesisView> {
        self.view.as_ref()
    }

    /// The open window's inputs and results, to change.
    pub fn view_mut(&mut self) -> Option<&mut SynthesisView> {
        self.view.as_mut()
    }

    /// Shows the window while it is open; a design chosen in it is opened or put in
    /// place through the state's commands.
    pub fn ui(&mut self, ctx: &egui::Context, st: &mut AppState) {
        if let Some(view) = self.view.take() {
            self.view = window(ctx, st, view);
        }
    }
}

/// The open window for one frame; the view back while it stays open.
fn window(
    ctx: &egui::Context,
    st: &mut AppState,
    mut view: SynthesisView,
) -> Option<SynthesisView> {
    let mut open = true;
    let mut chosen = None;
    let screen = ctx.content_rect();
    // On a phone the window is the screen's width; elsewhere beside the controls.
    let compact = st.layout.compact();
    let width = if compact {
        screen.width() - 16.0
    } else {
        460.0
    };
    let at = if compact {
        egui::pos2(8.0, 8.0)
    } else {
        egui::pos2(320.0, 80.0)
    };
    egui::Window::new(tr!("synth.title"))
        .open(&mut open)
        .default_pos(at)
        .max_width(screen.width() - 16.0)
        .show(ctx, |ui| {
            ui.horizontal_wrapped(|ui| {
                for kind in SynthKind::ALL {
                    let tab = ui.selectable_label(view.inputs.kind == kind, kind_shown(kind));
                    st.controls
                        .note(ui, ControlKind::SynthesisTab, kind.label(), &tab);
                    if tab.clicked() {
                        view.inputs.kind = kind;
                        view.result = None;
                    }
                }
            });
            ui.separator();
            // Inputs, a figure and a design table: taller than a laptop's window
            // for some designs, so the window scrolls.
            let room = ui.ctx().content_rect().height() - 160.0;
            chosen = egui::ScrollArea::vertical()
                .max_height(room)
                .min_scrolled_height(room.min(640.0))
                .show(ui, |ui| {
                    ui.set_min_width(width);
                    tab(ui, st, &mut view)
                })
                .inner;
        });
    if let Some(Chosen::Replace(scene)) = chosen {
        st.edit(SceneEdit::Replace(Box::new(scene)));
    } else if let Some(Chosen::Open(scene)) = chosen {
        // A design is not an edit: it opens as it came out of the synthesis (whose
        // window keeps the inputs that make it again), so it asks nothing when the
        // user goes on to another scene.
        match Session::open_scene(SceneSource::File("synthesized.ron".into()), scene) {
            Ok(session) => st.open(session),
            Err(e) => view.result = Some(Err(SynthError::DoesNotSolve(e))),
        }
    }
    open.then_some(view)
}

/// The chosen tab's inputs, design and result; returns what to do with a design.
fn tab(ui: &mut egui::Ui, st: &mut AppState, view: &mut SynthesisView) -> Option<Chosen> {
    if view.inputs.kind == SynthKind::Path {
        return crate::ui::synthesis::path::show(
            ui,
            &mut st.controls,
            &mut view.inputs.path,
            &mut view.path,
        );
    }
    inputs(ui, &mut view.inputs);
    let design = ui.button(tr!("synth.design"));
    st.controls
        .note(ui, ControlKind::FileButton, "Design", &design);
    if design.clicked() {
        view.result = Some(crate::synthesis::design(&view.inputs));
    }
    result(ui, st, view)
}

/// The inputs of the design chosen.
fn inputs(ui: &mut egui::Ui, view: &mut SynthInputs) {
    match view.kind {
        SynthKind::CrankRocker => {
            let [cd, swing, k] = &mut view.rocker;
            number(ui, cd, &tr!("synth.rocker_cd"), 1.0);
            number(ui, swing, &tr!("synth.swing"), 0.1);
            number(ui, k, &tr!("synth.time_ratio"), 0.01);
        }
        SynthKind::DieCutter => {
            let [h, k, l, rpm] = &mut view.die;
            number(ui, h, &tr!("synth.stroke"), 0.5);
            number(ui, k, &tr!("synth.time_ratio"), 0.01);
            number(ui, l, &tr!("synth.l"), 1.0);
            number(ui, rpm, &tr!("synth.crank_speed"), 1.0);
        }
        SynthKind::Function => {
            crate::ui::synthesis::figure::function_inputs(ui, view);
            number(
                ui,
                &mut view.function_ground_mm,
                &tr!("synth.ground_ad"),
                1.0,
            );
        }
        // Shown by `synthesis_path`.
        SynthKind::Path => {}
        SynthKind::Motion => crate::ui::synthesis::figure::motion_inputs(ui, view),
    }
}

/// The design table, or why there is none; returns what to do with it when asked.
fn result(ui: &mut egui::Ui, st: &mut AppState, view: &SynthesisView) -> Option<Chosen> {
    match &view.result {
        None => None,
        Some(Err(why)) => {
            ui.colored_label(
                ui.visuals().error_fg_color,
                why.words(crate::ui::words::lang()),
            );
            None
        }
        Some(Ok(design)) => design_view(ui, &mut st.controls, design),
    }
}

/// A design's tab in the app's language.
fn kind_shown(kind: SynthKind) -> String {
    match kind {
        SynthKind::CrankRocker => tr!("synth.tab_crank_rocker"),
        SynthKind::DieCutter => tr!("synth.tab_die_cutter"),
        SynthKind::Function => tr!("synth.tab_function"),
        SynthKind::Motion => tr!("synth.tab_motion"),
        SynthKind::Path => tr!("synth.tab_path"),
    }
}
