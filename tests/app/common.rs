//! What the UI tests share: the app as a user opens it, in a kittest harness drawing
//! through wgpu (Mesa's lavapipe in CI) with timings hidden so that the pixels
//! repeat, or without a GPU for tests that read state only; and pointer events.

use eframe::egui;
use egui_kittest::Harness;
use linkage_lab::ui::control_map::ControlKind;
use linkage_lab::{LinkageApp, StartOptions};

/// The app at its default scene, 1500×950, before its first frame.
pub fn app_harness() -> Harness<'static, LinkageApp> {
    let mut h = Harness::builder()
        .with_size(egui::vec2(1500.0, 950.0))
        .wgpu()
        .build_eframe(|cc| LinkageApp::new(cc, StartOptions::default()));
    h.state_mut().state.timing.show = false;
    h
}

/// The app at its default scene on a screen of `w` × `h` points (a phone, a
/// tablet, a small window), before its first frame.
pub fn sized_harness(w: f32, h: f32) -> Harness<'static, LinkageApp> {
    let mut h = Harness::builder()
        .with_size(egui::vec2(w, h))
        .wgpu()
        .build_eframe(|cc| LinkageApp::new(cc, StartOptions::default()));
    h.state_mut().state.timing.show = false;
    h
}

/// Runs frames until the app is idle, waiting for a dynamic run computed off the
/// frame as a user waits for it to appear. The run is waited for by its end, not
/// counted in frames: on a busy machine its thread spans more of them.
pub fn settle(h: &mut Harness<'static, LinkageApp>) {
    for _ in 0..100 {
        h.state_mut().state.session.wait_for_run();
        if h.try_run().is_ok() {
            return;
        }
    }
    panic!("the app kept repainting with no run left to wait for");
}

/// The app at its default scene, 1500×950, with no GPU renderer (the view draws no
/// mechanism), after two frames: for tests that read state, not pixels.
pub fn stateful_harness() -> Harness<'static, LinkageApp> {
    stateful_sized_harness(egui::vec2(1500.0, 950.0))
}

/// As [`stateful_harness`], on a screen of `size` points.
pub fn stateful_sized_harness(size: egui::Vec2) -> Harness<'static, LinkageApp> {
    let mut h = Harness::builder()
        .with_size(size)
        .build_eframe(|cc| LinkageApp::new(cc, StartOptions::default()));
    h.run();
    h.run();
    h
}

/// The primary button pressed or released at `at` (no frame run).
fn button(h: &mut Harness<'static, LinkageApp>, at: egui::Pos2, pressed: bool) {
    h.event(egui::Event::PointerButton {
        pos: at,
        button: egui::PointerButton::Primary,
        pressed,
        modifiers: egui::Modifiers::default(),
    });
}

/// The pointer moved to `at`, then pressed (`Some(true)`), released (`Some(false)`)
/// or neither; then frames until the app settles.
pub fn pointer(h: &mut Harness<'static, LinkageApp>, at: egui::Pos2, pressed: Option<bool>) {
    h.event(egui::Event::PointerMoved(at));
    if let Some(pressed) = pressed {
        button(h, at, pressed);
    }
    h.run();
}

/// A press and a release at `at`, each in its own frame (the pointer moved there
/// once: a second move between them, even to the same place, loses egui's click on
/// a menu button), then frames until the app settles: a dynamic run the click
/// started is waited for by its end (on a busy machine its thread spans more frames
/// than `run` allows).
pub fn click(h: &mut Harness<'static, LinkageApp>, at: egui::Pos2) {
    h.event(egui::Event::PointerMoved(at));
    for pressed in [true, false] {
        button(h, at, pressed);
        h.step();
    }
    settle(h);
}

/// A click on the widget named `label`, then frames until the app settles.
pub fn click_label(h: &mut Harness<'static, LinkageApp>, label: &str) {
    use egui_kittest::kittest::Queryable as _;
    h.get_by_label(label).click();
    h.run();
}

/// The synthesis window opened on its tab `tab`.
pub fn synthesis_tab(h: &mut Harness<'static, LinkageApp>, tab: &str) {
    click_label(h, "Synthesis…");
    click_label(h, tab);
}

/// The synthesis window's inputs, to set what a test does not type.
pub fn synthesis_inputs<'h>(
    h: &'h mut Harness<'static, LinkageApp>,
) -> &'h mut linkage_lab::synthesis::SynthInputs {
    &mut h
        .state_mut()
        .panels
        .synthesis
        .view_mut()
        .expect("the synthesis window is open")
        .inputs
}

/// Opens `session` as a user would who answers "drop the edits" when asked: the
/// open and the answer go through the app's one command queue (applied in the next
/// frame); the answer is ignored when nothing was asked.
pub fn open_dropping_edits(
    state: &mut linkage_lab::AppState,
    session: linkage_lab::session::Session,
) {
    use linkage_lab::command::Command;
    state.push(Command::Open(Box::new(session)));
    state.push(Command::Answer(true));
}

/// Every scene file in `assets/scenes` (read from the directory, not listed), in
/// order of name.
pub fn shipped_scene_files() -> Vec<std::path::PathBuf> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/assets/scenes");
    let mut files: Vec<std::path::PathBuf> = std::fs::read_dir(dir)
        .expect("scene dir")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "ron"))
        .collect();
    files.sort();
    assert!(files.len() >= 6, "{files:?}");
    files
}

/// Clicks the control of `kind` labelled `label`, as drawn last frame.
pub fn click_control(h: &mut Harness<'static, LinkageApp>, kind: ControlKind, label: &str) {
    let entry = h
        .state()
        .state
        .controls
        .of_kind(kind)
        .find(|e| e.label == label && e.visible)
        .unwrap_or_else(|| panic!("no {kind:?} {label:?} on screen"))
        .clone();
    let [x0, y0, x1, y1] = entry.rect;
    click(h, egui::pos2(0.5 * (x0 + x1), 0.5 * (y0 + y1)));
}

/// The app at `w`×`h` in `language`, told to panic on a missing glyph, with `item`
/// of the New… menu chosen (the gear lab's views).
pub fn opened_from_new_menu(
    w: f32,
    h: f32,
    language: linkage_lab::i18n::Language,
    item: &str,
) -> Harness<'static, LinkageApp> {
    let mut h = sized_harness(w, h);
    h.ctx
        .set_missing_glyph_policy(egui::MissingGlyphPolicy::Panic);
    h.state_mut().state.language = language;
    settle(&mut h);
    click_control(&mut h, ControlKind::FileButton, "New…");
    settle(&mut h);
    click_control(&mut h, ControlKind::TemplateItem, item);
    settle(&mut h);
    h
}

/// The pointer off the panel and a few frames more, so that a snapshot shows the
/// panel settled and no text under the pointer.
pub fn still(h: &mut Harness<'static, LinkageApp>) {
    h.event(egui::Event::PointerGone);
    for _ in 0..4 {
        h.run();
    }
}
