//! The top bar: scene picker, file actions, view toggles, the language.

use std::sync::OnceLock;

use eframe::egui;

use crate::catalog::{BUILTIN_SCENES, BuiltinScene};
use crate::command::Command;
use crate::i18n::{Language, tr};
use crate::session::{SceneSource, Session};
use crate::state::AppState;
use crate::ui::control_map::ControlKind;
use crate::ui::files::Files;

/// Display names of the shipped scenes (their `name` field), read once.
fn names() -> &'static [String] {
    static NAMES: OnceLock<Vec<String>> = OnceLock::new();
    NAMES.get_or_init(|| BUILTIN_SCENES.iter().map(BuiltinScene::name).collect())
}

/// The top bar: on a desktop screen every action in a row; on a phone or tablet the
/// scene, undo, redo and fit, with the rest in a menu.
pub fn top_bar(ui: &mut egui::Ui, st: &mut AppState, files: &mut Files, frame: &eframe::Frame) {
    egui::Panel::top("scene_bar").show(ui, |ui| {
        if st.exercise.is_some() {
            exercise_bar(ui, st, files);
        } else if st.layout.compact() {
            compact_bar(ui, st, files, frame);
        } else {
            wide_bar(ui, st, files, frame);
        }
    });
    files.prompt_window(ui.ctx(), st);
    crate::ui::course_window::window(ui.ctx(), st, files, frame);
    discard_question(ui.ctx(), st);
}

/// Every action in rows that do not move: each button is always there (Undo and
/// Redo greyed when there is nothing to take back), "(edited)" has its place kept
/// while the scene is as opened, and the status line is in the report strip. So an
/// edit changes nothing in the bar's layout, and a field being typed into keeps its
/// place and its keystrokes.
fn wide_bar(ui: &mut egui::Ui, st: &mut AppState, files: &mut Files, frame: &eframe::Frame) {
    ui.horizontal_wrapped(|ui| {
        ui.strong(tr!("app.name"));
        // The file buttons come before the scene's name, whose width varies, so that
        // they stay in place whichever scene is open.
        files.ui(ui, st, frame);
        crate::ui::course_window::button(ui, st);
        scene_picker(ui, st, 300.0);
        new_menu(ui, st);
        synthesis_button(ui, st);
        if ui.button(tr!("top.reset_edits")).clicked() {
            st.edit(crate::session::SceneEdit::Reset);
        }
        history_buttons(ui, st);
        edited_mark(ui, st);
        view_buttons(ui, st);
        // The mechanism view's overlays do nothing in the gear lab, which replaces it.
        if st.gear_lab.is_none() {
            view_toggles(ui, st);
        }
        language_switch(ui, st);
    });
}

/// While an exercise is open: the app's name, closing the exercise, fitting the
/// view and the language; no file, analysis or overlay that would show an answer.
fn exercise_bar(ui: &mut egui::Ui, st: &mut AppState, files: &mut Files) {
    // The desk's task sheet is a file action: its dialog's answer comes here.
    files.take_dialog_answers(st);
    ui.horizontal_wrapped(|ui| {
        ui.strong(tr!("app.name"));
        let close = ui.button(tr!("exercise.close"));
        st.controls
            .note(ui, ControlKind::Exercise, "close the exercise", &close);
        if close.clicked() {
            st.exercise = None;
        }
        if ui.button(tr!("top.fit_view")).clicked() {
            st.commands.fit = true;
        }
        language_switch(ui, st);
    });
}

/// "Fit view" and "Reset layout".
fn view_buttons(ui: &mut egui::Ui, st: &mut AppState) {
    if ui.button(tr!("top.fit_view")).clicked() {
        st.commands.fit = true;
    }
    let reset = ui
        .button(tr!("top.reset_layout"))
        .on_hover_text(tr!("top.reset_layout_hint"));
    st.controls
        .note(ui, ControlKind::ResetLayout, "Reset layout", &reset);
    if reset.clicked() {
        st.layout.reset();
        st.commands.fit = true;
    }
}

fn compact_bar(ui: &mut egui::Ui, st: &mut AppState, files: &mut Files, frame: &eframe::Frame) {
    // On a tablet lying down everything shares one row; on a phone the scene's name
    // takes the rest of the first (its frame and arrow take about 32 points more)
    // and undo, redo and fit go below.
    let one_row = ui.available_width() >= 700.0;
    ui.horizontal(|ui| {
        let menu = ui.menu_button(tr!("top.menu"), |ui| {
            files.ui(ui, st, frame);
            crate::ui::course_window::button(ui, st);
            new_menu(ui, st);
            synthesis_button(ui, st);
            if ui.button(tr!("top.reset_edits")).clicked() {
                st.edit(crate::session::SceneEdit::Reset);
            }
            let reset = ui.button(tr!("top.reset_layout"));
            st.controls
                .note(ui, ControlKind::ResetLayout, "Reset layout", &reset);
            if reset.clicked() {
                st.layout.reset();
                st.commands.fit = true;
            }
            ui.separator();
            if st.gear_lab.is_none() {
                view_toggles(ui, st);
                ui.separator();
            }
            language_switch(ui, st);
        });
        st.controls
            .note(ui, ControlKind::Menu, "Menu", &menu.response);
        let room = ui.available_width();
        let width = if one_row {
            (room - 330.0).min(480.0)
        } else {
            room - 32.0
        };
        scene_picker(ui, st, width);
        if one_row {
            history_and_status(ui, st);
        }
    });
    if !one_row {
        ui.horizontal_wrapped(|ui| history_and_status(ui, st));
    }
}

/// Undo, redo, fit and "(edited)" (the status line is shown in the view).
fn history_and_status(ui: &mut egui::Ui, st: &mut AppState) {
    history_buttons(ui, st);
    if ui.button(tr!("top.fit_view")).clicked() {
        st.commands.fit = true;
    }
    edited_mark(ui, st);
}

/// The scene picker, `width` wide; labelled "Scene" beside it on a desktop screen,
/// for screen readers alone on a phone (where the width is the scene name's).
fn scene_picker(ui: &mut egui::Ui, st: &mut AppState, width: f32) {
    let labelled = !st.layout.compact();
    let current = match st.session.source() {
        SceneSource::Builtin(key) => BUILTIN_SCENES
            .iter()
            .position(|b| b.key == key)
            .map_or_else(|| key.clone(), |i| names()[i].clone()),
        // A template, a synthesised design or a file: the scene's own name (the
        // file's name is what Save proposes).
        SceneSource::File(_) => st.session.scene().name.clone(),
    };
    let mut chosen = None;
    let mut items = Vec::new();
    let combo = if labelled {
        egui::ComboBox::from_label(tr!("top.scene"))
    } else {
        egui::ComboBox::from_id_salt("Scene")
    };
    // The list's height: on a phone, where its names wrap, all of it unless the
    // screen is shorter (egui's default shows about eight lines, then scrolls).
    let height = ui.ctx().content_rect().height() * 0.8;
    let picker = combo
        .selected_text(current)
        .width(width)
        .height(height)
        .truncate()
        .show_ui(ui, |ui| {
            if !labelled {
                fit_the_screen(ui);
            }
            // A popup's first frame is a sizing pass, laid out away from where it
            // will be drawn: its rects are not where a click lands.
            let placed = !ui.is_sizing_pass();
            for (b, name) in BUILTIN_SCENES.iter().zip(names()) {
                let r = ui.selectable_label(false, name);
                let visible = placed && ui.clip_rect().contains_rect(r.rect);
                items.push((name, r.rect, visible));
                if r.clicked() {
                    chosen = Some(b.key);
                }
            }
        });
    let picker = picker.response;
    if !labelled {
        picker.widget_info(|| {
            egui::WidgetInfo::labeled(egui::accesskit::Role::ComboBox, true, "Scene")
        });
    }
    st.controls
        .note(ui, ControlKind::ScenePicker, "Scene", &picker);
    for (name, rect, visible) in items {
        st.controls
            .note_rect(ControlKind::SceneItem, name, rect, visible);
    }
    if let Some(key) = chosen {
        match Session::open_builtin(key) {
            Ok(s) => st.open(s),
            Err(e) => st.status = Some(e.words(crate::ui::words::lang())),
        }
    }
}

/// On a phone the scenes' names are wider than the screen: the list wraps them
/// within it (a popup is kept on the screen, but not made narrower).
fn fit_the_screen(ui: &mut egui::Ui) {
    let margin = 2.0 * ui.style().spacing.window_margin.sum().x;
    ui.set_max_width(ui.ctx().content_rect().width() - margin);
    ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Wrap);
}

fn synthesis_button(ui: &mut egui::Ui, st: &mut AppState) {
    let synthesis = ui.button(tr!("top.synthesis"));
    st.controls
        .note(ui, ControlKind::FileButton, "Synthesis…", &synthesis);
    if synthesis.clicked() {
        st.commands.toggle_synthesis = true;
    }
}

/// "(edited)" while the scene has unsaved edits; its place kept while it has none,
/// so that the bar does not move when the first edit lands.
fn edited_mark(ui: &mut egui::Ui, st: &AppState) {
    let text = tr!("top.edited");
    let size = egui::WidgetText::from(text.as_str())
        .into_galley(
            ui,
            Some(egui::TextWrapMode::Extend),
            f32::INFINITY,
            egui::TextStyle::Body,
        )
        .size();
    let dirty = st.session.is_dirty();
    let label = egui::Label::new(if dirty { text } else { String::new() });
    ui.add_sized(size, label).on_hover_text(if dirty {
        tr!("top.edited_hint")
    } else {
        tr!("top.unedited_hint")
    });
}

/// The language of the app's words: English or 中文, remembered for the next run.
fn language_switch(ui: &mut egui::Ui, st: &mut AppState) {
    let mut chosen = st.language;
    let combo = egui::ComboBox::from_id_salt("language")
        .selected_text(chosen.own_name())
        .show_ui(ui, |ui| {
            for language in Language::ALL {
                ui.selectable_value(&mut chosen, language, language.own_name());
            }
        });
    let r = combo.response.on_hover_text(tr!("language.switch"));
    st.controls.note(ui, ControlKind::Language, "Language", &r);
    if chosen != st.language {
        st.language = chosen;
        if st.remember_choices {
            crate::language_pref::remember(chosen);
        }
    }
}

/// "move points" and the overlays of the view.
fn view_toggles(ui: &mut egui::Ui, st: &mut AppState) {
    let edit = ui
        .checkbox(&mut st.view.edit_points, tr!("view.move_points"))
        .on_hover_text(tr!("view.move_points_hint"));
    st.controls
        .note(ui, ControlKind::Layer, "move points", &edit);
    // The control map keeps the English names: the tests' handles in any language.
    for (on, id, label) in [
        (
            &mut st.view.layers.velocities,
            "v vectors",
            tr!("view.v_vectors"),
        ),
        (
            &mut st.view.layers.accelerations,
            "a vectors",
            tr!("view.a_vectors"),
        ),
        (&mut st.view.layers.traces, "traces", tr!("view.traces")),
        (
            &mut st.view.layers.centres,
            "instant centres",
            tr!("view.centres"),
        ),
    ] {
        let r = ui.checkbox(on, label);
        st.controls.note(ui, ControlKind::Layer, id, &r);
    }
}

/// The shipped exercises' titles (their files' `name`), read once.
fn exercise_names() -> &'static [String] {
    static NAMES: OnceLock<Vec<String>> = OnceLock::new();
    NAMES.get_or_init(|| {
        let title = |text: &str| {
            ron::from_str::<crate::exercise::ExerciseFile>(text)
                .map_or_else(|e| e.to_string(), |f| f.name)
        };
        crate::catalog::EXERCISES
            .iter()
            .map(|e| title(e.text))
            .collect()
    })
}

/// Display names of the templates, read once.
fn template_names() -> &'static [String] {
    static NAMES: OnceLock<Vec<String>> = OnceLock::new();
    NAMES.get_or_init(|| {
        crate::catalog::TEMPLATES
            .iter()
            .map(BuiltinScene::name)
            .collect()
    })
}

/// Undo and Redo: of the drawing while drawing, else of the scene's edits.
fn history_buttons(ui: &mut egui::Ui, st: &mut AppState) {
    let (can_undo, can_redo) = match &st.drawing {
        Some(b) => (b.can_undo(), b.can_redo()),
        None => (st.session.can_undo(), st.session.can_redo()),
    };
    let undo = ui
        .add_enabled(can_undo, egui::Button::new(tr!("top.undo")))
        .on_hover_text(tr!("top.undo_keys"));
    st.controls.note(ui, ControlKind::History, "Undo", &undo);
    let redo = ui
        .add_enabled(can_redo, egui::Button::new(tr!("top.redo")))
        .on_hover_text(tr!("top.redo_keys"));
    st.controls.note(ui, ControlKind::History, "Redo", &redo);
    if undo.clicked() {
        st.push(Command::Undo);
    }
    if redo.clicked() {
        st.push(Command::Redo);
    }
}

/// The New… menu's item that starts a drawing from nothing.
const EMPTY_DRAWING: &str = "Empty: draw your own";
/// The New… menu's item that opens the gear-cutting lab.
const GEAR_CUTTING: &str = "Gear cutting";
/// The New… menu's item that opens the gear lab on its train view.
const GEAR_TRAINS: &str = "Gear trains";
/// The New… menu's item that turns the open scene into a drawing to edit.
const AS_DRAWING: &str = "This scene as a drawing";

/// "New…": an empty drawing, or a scene started from a template (four-bar, slider-crank, inverted
/// slider-crank, Watt and Stephenson six-bars), named after it, to edit and save.
fn new_menu(ui: &mut egui::Ui, st: &mut AppState) {
    let mut chosen = None;
    let mut empty = false;
    let mut as_drawing = false;
    let menu = ui.menu_button(tr!("top.new"), |ui| {
        empty = menu_item(ui, st, EMPTY_DRAWING, &tr!("top.new_empty"));
        as_drawing = menu_item(ui, st, AS_DRAWING, &tr!("top.new_as_drawing"));
        if menu_item(ui, st, GEAR_CUTTING, &tr!("top.new_gear_cutting")) {
            st.gear_lab = Some(crate::gear_lab::GearLab::default());
        }
        if menu_item(ui, st, GEAR_TRAINS, &tr!("top.new_gear_trains")) {
            st.gear_lab = Some(crate::gear_lab::GearLab {
                mode: crate::gear_lab::LabMode::Train,
                ..crate::gear_lab::GearLab::default()
            });
        }
        ui.menu_button(tr!("exercise.menu"), |ui| {
            for (e, name) in crate::catalog::EXERCISES.iter().zip(exercise_names()) {
                if menu_item(ui, st, e.key, name) {
                    st.open_exercise(e.text);
                }
            }
        });
        for (t, name) in crate::catalog::TEMPLATES.iter().zip(template_names()) {
            if menu_item(ui, st, name, name) {
                chosen = Some(t);
            }
        }
    });
    st.controls
        .note(ui, ControlKind::FileButton, "New…", &menu.response);
    if empty {
        st.push(Command::StartDrawing);
    }
    if as_drawing {
        st.push(Command::DrawCurrent);
    }
    if let Some(t) = chosen {
        match Session::open_text(SceneSource::File(format!("{}.ron", t.key)), t.text) {
            Ok(s) => st.open(s),
            Err(e) => {
                let why = crate::ui::words::refusal(&e, linkage::scene::LengthUnit::Metre);
                st.status = Some(tr!("top.template_failed", name = t.key, why = why));
            }
        }
    }
}

/// One item of the New… menu, `text` on it, noted in the control map as `id`;
/// returns whether it was clicked (the menu then closes).
fn menu_item(ui: &mut egui::Ui, st: &mut AppState, id: &str, text: &str) -> bool {
    let item = ui.button(text);
    // The menu's first frame only sizes it, somewhere else: not clickable yet.
    let placed = !ui.is_sizing_pass() && ui.clip_rect().contains_rect(item.rect);
    st.controls
        .note_rect(ControlKind::TemplateItem, id, item.rect, placed);
    let clicked = item.clicked();
    if clicked {
        ui.close();
    }
    clicked
}

/// Asks before a scene with unsaved edits is replaced by the one waiting.
fn discard_question(ctx: &egui::Context, st: &mut AppState) {
    let Some(next) = st.commands.waiting.as_ref().map(|w| w.describe()) else {
        return;
    };
    let current = st.session.scene().name.clone();
    let mut answer = None;
    egui::Window::new(tr!("unsaved.title"))
        .collapsible(false)
        .resizable(false)
        .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
        .show(ctx, |ui| {
            ui.label(tr!("unsaved.question", current = current, next = next));
            ui.horizontal(|ui| {
                for (id, label, drop) in [
                    ("Drop the edits and open", tr!("unsaved.drop"), true),
                    ("Keep editing", tr!("unsaved.keep"), false),
                ] {
                    let r = ui.button(label);
                    st.controls.note(ui, ControlKind::FileButton, id, &r);
                    if r.clicked() {
                        answer = Some(drop);
                    }
                }
            });
        });
    if let Some(drop_edits) = answer {
        st.push(Command::Answer(drop_edits));
    }
}
