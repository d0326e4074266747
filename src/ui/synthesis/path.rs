//! The synthesis window's path tab: targets placed by clicking on its canvas,
//! dragged there, or typed and pasted as CSV; the search runs off the frame with a
//! progress bar, the best curve so far drawn live, stop and continue; the designs
//! found are listed by their largest miss, each with its two cognates (the other
//! four-bars that trace the same curve), and the one chosen opens as a scene or
//! replaces the current one (undo-able), as the other tabs' designs do.

use eframe::egui;
use egui_plot::{Line, Plot, PlotPoint, PlotPoints, Points, Text};
use linkage::synthesis::path::{PathDesign, PathLinkage};

use crate::i18n::tr;
use crate::synthesis::path_inputs::{Member, PathInputs, design_of, member_of, turns_with};
use crate::synthesis::path_job::PathJob;
use crate::ui::control_map::{ControlKind, ControlMap};
use crate::ui::synthesis::design::{Chosen, design_view};

/// Milliseconds of search per frame in the browser.
pub const SLICE_MS: f64 = 6.0;
/// How near the pointer must come to a target to take it, points.
const GRAB_PX: f32 = 12.0;

/// The tab's state besides its inputs.
#[derive(Default)]
pub struct PathTab {
    /// The targets as the text field shows them.
    csv: String,
    /// Why the text field's rows were not taken.
    csv_error: Option<linkage::synthesis::rows::RowError>,
    /// The search, once started.
    pub job: Option<PathJob>,
    /// Why the search did not start.
    refused: Option<String>,
    /// The design chosen in the list, and which of its family.
    chosen: (usize, Member),
    /// The target being dragged on the canvas.
    dragging: Option<usize>,
}

impl PathTab {
    /// Why the last Search did not start, if it did not.
    pub fn refused(&self) -> Option<&str> {
        self.refused.as_deref()
    }
}

/// The tab; returns what to do with the chosen design, if asked.
pub fn show(
    ui: &mut egui::Ui,
    controls: &mut ControlMap,
    inputs: &mut PathInputs,
    tab: &mut PathTab,
) -> Option<Chosen> {
    if let Some(job) = tab.job.as_mut().filter(|j| j.is_running()) {
        job.poll(SLICE_MS);
        ui.ctx().request_repaint();
    }
    if tab.csv.is_empty() && !inputs.targets.is_empty() {
        tab.csv = inputs.to_csv();
    }
    targets(ui, controls, inputs, tab);
    constraints(ui, inputs);
    search_buttons(ui, controls, inputs, tab);
    designs(ui, controls, tab)
}

fn targets(
    ui: &mut egui::Ui,
    controls: &mut ControlMap,
    inputs: &mut PathInputs,
    tab: &mut PathTab,
) {
    if ui.checkbox(&mut inputs.timed, tr!("path.timed")).changed() {
        tab.csv = inputs.to_csv();
    }
    // Live, the best so far; once stopped, the four-bar chosen in the list.
    let leader = tab.job.as_ref().and_then(|j| {
        let shot = j.snapshot();
        let (design, member) = tab.chosen;
        let chosen = shot
            .designs
            .get(design)
            .filter(|_| !j.is_running())
            .and_then(|d| member_of(d, member));
        chosen.or(shot.leader.as_ref().map(|d| &d.linkage)).cloned()
    });
    if canvas(ui, controls, inputs, tab, leader.as_ref()) {
        tab.csv = inputs.to_csv();
        tab.csv_error = None;
    }
    let label = if inputs.timed {
        tr!("path.targets_timed")
    } else {
        tr!("path.targets")
    };
    ui.label(&label);
    // Scrolled past six rows, so that twenty targets leave Search in sight.
    let r = egui::ScrollArea::vertical()
        .id_salt("path targets text")
        .max_height(6.0 * ui.text_style_height(&egui::TextStyle::Monospace) + 8.0)
        .show(ui, |ui| {
            ui.add(
                egui::TextEdit::multiline(&mut tab.csv)
                    .desired_rows(4)
                    .desired_width(f32::INFINITY)
                    .code_editor(),
            )
        })
        .inner;
    r.widget_info(|| {
        egui::WidgetInfo::labeled(egui::accesskit::Role::MultilineTextInput, true, &label)
    });
    if r.changed() {
        tab.csv_error = inputs.read_csv(&tab.csv).err();
    }
    if let Some(why) = &tab.csv_error {
        let why = linkage_diagram::refusal::rows(crate::ui::words::lang(), why);
        ui.colored_label(ui.visuals().error_fg_color, why);
    }
    let clear = ui.button(tr!("path.clear"));
    controls.note(ui, ControlKind::FileButton, "Clear targets", &clear);
    if clear.clicked() {
        inputs.targets.clear();
        tab.csv.clear();
    }
}

/// The canvas: targets, the best curve so far and its linkage; a click adds a
/// target, a drag moves one. Returns whether the targets changed.
fn canvas(
    ui: &mut egui::Ui,
    controls: &mut ControlMap,
    inputs: &mut PathInputs,
    tab: &mut PathTab,
    leader: Option<&PathLinkage>,
) -> bool {
    let shown = Plot::new("path synthesis canvas")
        .data_aspect(1.0)
        .height(260.0)
        .allow_drag(false)
        .allow_boxed_zoom(false)
        .allow_double_click_reset(false)
        .show(ui, |p| {
            if let Some(d) = leader {
                for piece in d.curve(360) {
                    let mm: PlotPoints<'_> =
                        piece.iter().map(|q| [q[0] * 1e3, q[1] * 1e3]).collect();
                    p.line(Line::new(tr!("path.coupler_curve"), mm).width(1.5));
                }
                if let Some(bars) = linkage_lines(d) {
                    p.line(Line::new(tr!("path.linkage"), bars).width(2.5));
                }
            }
            let at: PlotPoints<'_> = inputs.targets.iter().map(|t| t.at_mm).collect();
            p.points(Points::new(tr!("path.target_points"), at).radius(5.0));
            for (i, t) in inputs.targets.iter().enumerate() {
                let [x, y] = t.at_mm;
                p.text(
                    Text::new("", PlotPoint::new(x, y), format!("  {}", i + 1))
                        .anchor(egui::Align2::LEFT_BOTTOM),
                );
            }
            let screen: Vec<egui::Pos2> = inputs
                .targets
                .iter()
                .map(|t| p.screen_from_plot(PlotPoint::new(t.at_mm[0], t.at_mm[1])))
                .collect();
            (p.response().clone(), p.pointer_coordinate(), screen)
        });
    let (response, pointer, screen) = shown.inner;
    controls.note(ui, ControlKind::SynthesisCanvas, "path targets", &response);
    for (i, at) in screen.iter().enumerate() {
        let rect = egui::Rect::from_center_size(*at, egui::vec2(2.0 * GRAB_PX, 2.0 * GRAB_PX));
        let shown = response.rect.contains(*at) && ui.clip_rect().contains(*at);
        controls.note_rect(
            ControlKind::SynthesisTarget,
            &format!("target {}", i + 1),
            rect,
            shown,
        );
    }
    let near = |pos: egui::Pos2| {
        screen
            .iter()
            .enumerate()
            .map(|(i, s)| (i, s.distance(pos)))
            .filter(|&(_, d)| d <= GRAB_PX)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(i, _)| i)
    };
    let press = response.interact_pointer_pos();
    let mut changed = false;
    if response.drag_started() {
        tab.dragging = press.and_then(near);
    }
    let held = tab.dragging.zip(pointer.filter(|_| response.dragged()));
    if let Some((t, to)) = held.and_then(|(i, to)| Some((inputs.targets.get_mut(i)?, to))) {
        t.at_mm = [to.x, to.y];
        changed = true;
    }
    if response.drag_stopped() {
        tab.dragging = None;
    }
    if let Some(to) = pointer.filter(|_| response.clicked() && press.and_then(near).is_none()) {
        inputs.add([to.x, to.y]);
        changed = true;
    }
    changed
}

/// The linkage where its coupler point meets the first target: A-B-C-D and the
/// coupler triangle B-P-C, mm.
fn linkage_lines(d: &PathLinkage) -> Option<PlotPoints<'static>> {
    let theta = d.crank_deg.first()?.to_radians();
    let pins = d.linkage().pins_at(theta)?;
    let mm = |v: linkage::Vec2| [v.x * 1e3, v.y * 1e3];
    let a = d.pivot_a.map(|v| v * 1e3);
    let dd = d.pivot_d.map(|v| v * 1e3);
    Some(
        vec![
            a,
            mm(pins.b),
            mm(pins.p),
            mm(pins.c),
            mm(pins.b),
            mm(pins.c),
            dd,
        ]
        .into(),
    )
}

fn constraints(ui: &mut egui::Ui, inputs: &mut PathInputs) {
    ui.horizontal(|ui| {
        ui.checkbox(&mut inputs.crank_turns, tr!("path.crank_turns"));
        ui.checkbox(&mut inputs.one_branch, tr!("path.one_branch"));
        ui.add_enabled(
            !inputs.timed,
            egui::Checkbox::new(&mut inputs.any_order, tr!("path.any_order")),
        );
    });
    ui.horizontal(|ui| {
        let name = ui.label(tr!("path.least_mu"));
        ui.add(
            egui::DragValue::new(&mut inputs.min_transmission_deg)
                .range(0.0..=89.0)
                .speed(0.5),
        )
        .labelled_by(name.id);
        let name = ui.label(tr!("path.seed"));
        ui.add(egui::DragValue::new(&mut inputs.seed))
            .labelled_by(name.id);
    });
    ui.horizontal(|ui| {
        let name = ui.label(tr!("path.tolerance"));
        ui.add(
            egui::DragValue::new(&mut inputs.tolerance)
                .range(1e-9..=0.1)
                .speed(1e-6)
                .custom_formatter(|v, _| format!("{v:.0e}")),
        )
        .labelled_by(name.id);
    });
}

fn search_buttons(
    ui: &mut egui::Ui,
    controls: &mut ControlMap,
    inputs: &PathInputs,
    tab: &mut PathTab,
) {
    let running = tab.job.as_ref().is_some_and(PathJob::is_running);
    ui.horizontal(|ui| {
        let search = ui.add_enabled(!running, egui::Button::new(tr!("path.search")));
        controls.note(ui, ControlKind::FileButton, "Search", &search);
        if search.clicked() {
            match inputs.search() {
                Ok(s) => {
                    tab.job = Some(PathJob::start(s));
                    tab.refused = None;
                    tab.chosen = (0, 0);
                }
                Err(why) => {
                    tab.refused = Some(crate::ui::words::refusal(
                        &why,
                        linkage::scene::LengthUnit::Metre,
                    ))
                }
            }
        }
        if let Some(job) = tab.job.as_mut() {
            let (id, label) = if running {
                ("Stop", tr!("path.stop"))
            } else {
                ("Continue", tr!("path.continue"))
            };
            let b = ui.button(label);
            controls.note(ui, ControlKind::FileButton, id, &b);
            if b.clicked() && running {
                job.stop();
            } else if b.clicked() {
                job.resume(cfg!(target_arch = "wasm32"));
            }
        }
    });
    if let Some(why) = &tab.refused {
        ui.colored_label(ui.visuals().error_fg_color, why);
    }
    if let Some(job) = &tab.job {
        let p = job.snapshot().progress;
        let best = if p.best_relative_error.is_finite() {
            tr!("path.best", miss = format!("{:.1e}", p.best_relative_error))
        } else {
            tr!("path.none_yet")
        };
        let done = if p.done {
            tr!("path.done")
        } else {
            String::new()
        };
        ui.add(egui::ProgressBar::new(p.fraction() as f32).text(tr!(
            "path.progress",
            evaluations = p.evaluations,
            best = best,
            solutions = p.solutions,
            done = done
        )));
    }
}

fn designs(ui: &mut egui::Ui, controls: &mut ControlMap, tab: &mut PathTab) -> Option<Chosen> {
    let found: &[PathDesign] = tab.job.as_ref().map_or(&[], |j| &j.snapshot().designs);
    if found.is_empty() {
        return None;
    }
    ui.separator();
    for (i, d) in found.iter().enumerate() {
        let text = tr!(
            "path.design",
            n = i + 1,
            miss = format!("{:.1e}", d.relative_error),
            summary = summary(&d.linkage)
        );
        if ui.selectable_label(tab.chosen == (i, 0), text).clicked() {
            tab.chosen = (i, 0);
        }
        for (k, c) in d.cognates.iter().enumerate() {
            let text = tr!(
                "path.cognate",
                n = k + 1,
                turns = turns_with(c.turns_with, false),
                summary = summary(&c.linkage)
            );
            let row = ui.selectable_label(tab.chosen == (i, k + 1), text);
            controls.note(
                ui,
                ControlKind::FileButton,
                &format!("cognate {}.{}", i + 1, k + 1),
                &row,
            );
            if row.clicked() {
                tab.chosen = (i, k + 1);
            }
        }
    }
    let (design, member) = tab.chosen;
    let shown = found.get(design).and_then(|d| design_of(d, member));
    let design = shown.or_else(|| design_of(found.first()?, 0))?;
    design_view(ui, controls, &design)
}

/// A four-bar in a few words: its class, whether its crank turns, its least
/// transmission angle.
fn summary(l: &PathLinkage) -> String {
    let mu = l
        .min_transmission_deg
        .map_or_else(String::new, |m| format!(", μ ≥ {m:.0}°"));
    let crank = if l.crank_turns {
        tr!("path.crank_turns_short")
    } else {
        tr!("path.crank_rocks")
    };
    format!("{}, {crank}{mu}", l.grashof)
}
