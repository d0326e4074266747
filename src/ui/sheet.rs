//! The sheet of tabs that holds the panels on a phone or tablet (and in a small
//! window): controls, polygons, plots, report and accuracy, one at a time, each
//! scrolled, beside or under the mechanism view (`layout.rs`).

use eframe::egui;

use crate::state::AppState;
use crate::ui::control_map::ControlKind;
use crate::ui::layout::{SheetTab, VIEW_SHARE};
use crate::ui::panels::Panels;

/// Lays out the sheet in its part of `ui`'s area and returns the rest, the view's.
/// The sheet comes first so that the controls' edits land before the view is drawn
/// (they are applied here): the view shows them in the same frame.
pub fn show(
    ui: &mut egui::Ui,
    st: &mut AppState,
    panels: &mut Panels,
    drawing: bool,
) -> egui::Rect {
    let area = ui.available_rect_before_wrap();
    let screen = ui.ctx().content_rect().size();
    let share = VIEW_SHARE;
    let (view, sheet) = st.layout.arrangement.split(area, screen, share);
    st.controls
        .note_rect(ControlKind::Pane, "sheet", sheet, true);
    let mut ui = ui.new_child(
        egui::UiBuilder::new()
            .max_rect(sheet)
            .layout(egui::Layout::top_down(egui::Align::Min)),
    );
    tabs(&mut ui, st, drawing);
    ui.separator();
    page(&mut ui, st, panels, drawing);
    st.apply_commands();
    view
}

/// Whether a tab has anything to show: while drawing, only once the drawing is a
/// mechanism (the report, polygons, plots and accuracy are of the mechanism).
fn available(st: &AppState, drawing: bool, tab: SheetTab) -> bool {
    let complete = st.drawing.as_ref().is_none_or(|b| b.problem.is_none());
    tab == SheetTab::Controls || !drawing || complete
}

fn tabs(ui: &mut egui::Ui, st: &mut AppState, drawing: bool) {
    if !available(st, drawing, st.layout.tab) {
        st.layout.tab = SheetTab::Controls;
    }
    ui.horizontal_wrapped(|ui| {
        // Five tabs in a row on a phone 390 points wide: less padding than a button.
        ui.spacing_mut().button_padding.x = 7.0;
        ui.spacing_mut().item_spacing.x = 4.0;
        for tab in SheetTab::ALL {
            if !available(st, drawing, tab) {
                continue;
            }
            let label = if drawing && tab == SheetTab::Controls {
                crate::i18n::tr!("tab.drawing")
            } else {
                tab.shown()
            };
            let r = ui.selectable_label(st.layout.tab == tab, label);
            st.controls.note(ui, ControlKind::SheetTab, tab.label(), &r);
            if r.clicked() {
                st.layout.tab = tab;
            }
        }
    });
}

/// The tab's page: the polygons and the plots scroll inside themselves (their
/// figures fit what the sheet shows of them), the others in the sheet's scroll.
fn page(ui: &mut egui::Ui, st: &mut AppState, panels: &mut Panels, drawing: bool) {
    let scrolled = |ui: &mut egui::Ui, page: &mut dyn FnMut(&mut egui::Ui)| {
        egui::ScrollArea::vertical()
            .auto_shrink(false)
            .show(ui, |ui| page(ui));
    };
    match st.layout.tab {
        SheetTab::Controls if drawing => {
            scrolled(ui, &mut |ui| crate::ui::drawing_panel::panel(ui, st));
        }
        SheetTab::Controls => scrolled(ui, &mut |ui| crate::ui::controls::panel(ui, st)),
        SheetTab::Polygons => panels.polygons.ui(ui, st),
        SheetTab::Plots => panels.plots.ui(ui, st),
        SheetTab::Report => scrolled(ui, &mut |ui| crate::ui::report::page(ui, st)),
        SheetTab::Accuracy => scrolled(ui, &mut |ui| crate::ui::accuracy::panel(ui, st)),
    }
}
