//! Where each control a user can touch is on screen this frame, by kind and label.
//! Tests drive the app through it as a user would, with pointer events at these
//! places: kittest natively, and in the browser the page reads it through
//! `window.wasmBindings.linkage_lab_controls()`. The panels fill it as they draw.

use eframe::egui;
use serde::Serialize;

/// The kinds of control; every kind a scene offers is exercised by the tests.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum ControlKind {
    /// Play / pause.
    Play,
    /// The crank-angle slider.
    Crank,
    /// The playback time of a dynamic run.
    RunTime,
    /// A pin-to-pin length.
    Length,
    /// A spring constant.
    Spring,
    /// A link mass.
    Mass,
    /// An assembly-branch toggle.
    Branch,
    /// The integrator menu.
    Integrator,
    /// One method in the open integrator menu.
    IntegratorItem,
    /// The integrator's tolerance or step.
    Tolerance,
    /// The scene picker.
    ScenePicker,
    /// One scene in the open picker.
    SceneItem,
    /// An overlay checkbox of the mechanism view (vectors, traces, instant centres).
    Layer,
    /// A file button of the top bar (open, save, export).
    FileButton,
    /// A cam panel control: a segment's law or angle, the lift, the roller, an export.
    Cam,
    /// The polygon pane's enlarge / narrower button.
    PolygonLayout,
    /// Undo or redo.
    History,
    /// One template in the open New… menu.
    TemplateItem,
    /// A drawing tool (Pivot, Link, ...) or action (Done, Undo, ...).
    DrawTool,
    /// A tab of the synthesis window (crank-rocker, ..., path).
    SynthesisTab,
    /// The path tab's canvas, where a click places a target.
    SynthesisCanvas,
    /// A target on the path tab's canvas (a drag moves it).
    SynthesisTarget,
    /// A tab of the sheet that holds the panels on a phone or tablet.
    SheetTab,
    /// A tab of the plot pane.
    PlotTab,
    /// "Reset layout": the panes back to their default sizes.
    ResetLayout,
    /// The language switch of the top bar.
    Language,
    /// A section of a pane that opens and closes (the polygons' vector equations,
    /// the construction).
    Section,
    /// A pane of the desktop arrangement (controls, polygons, plots) or the
    /// sheet of the compact ones, by its rectangle: its edge is what a user drags.
    Pane,
    /// The top bar's menu on a phone or tablet (the file actions, New…, views).
    Menu,
    /// A polygon figure by its box; in view where at least half of it shows.
    Figure,
    /// A control of the exercise desk: the student number, an answer, a button.
    Exercise,
}

/// One control as drawn this frame.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ControlEntry {
    /// What it is.
    pub kind: ControlKind,
    /// Its label as shown.
    pub label: String,
    /// Its rectangle in points: [min x, min y, max x, max y].
    pub rect: [f32; 4],
    /// Whether all of it is inside its panel's visible area (else scroll first).
    pub visible: bool,
}

/// The controls of one frame.
#[derive(Clone, Debug, Default, Serialize)]
pub struct ControlMap {
    /// In drawing order.
    pub entries: Vec<ControlEntry>,
    /// The mechanism view's rectangle in points, [min x, min y, max x, max y]: where
    /// a drag moves points or pans.
    pub view: Option<[f32; 4]>,
}

impl ControlMap {
    /// Forgets the last frame's controls.
    pub fn clear(&mut self) {
        self.view = None;
        self.entries.clear();
    }

    /// Notes a control drawn in `ui` with response `r`.
    pub fn note(&mut self, ui: &egui::Ui, kind: ControlKind, label: &str, r: &egui::Response) {
        self.note_rect(kind, label, r.rect, ui.clip_rect().contains_rect(r.rect));
    }

    /// Notes a control by its rectangle (one drawn in a popup whose `Ui` is gone).
    pub fn note_rect(&mut self, kind: ControlKind, label: &str, rect: egui::Rect, visible: bool) {
        self.entries.push(ControlEntry {
            kind,
            label: label.to_owned(),
            rect: [rect.min.x, rect.min.y, rect.max.x, rect.max.y],
            visible,
        });
    }

    /// The controls of `kind`, in drawing order.
    pub fn of_kind(&self, kind: ControlKind) -> impl Iterator<Item = &ControlEntry> {
        self.entries.iter().filter(move |e| e.kind == kind)
    }

    /// The map as JSON for the browser test.
    pub fn to_json(&self) -> String {
        // Only plain strings, numbers and booleans: serialising cannot fail.
        serde_json::to_string(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }
}
