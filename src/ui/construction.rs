//! Construction mode: one vector equation built step by step as the textbook does —
//! the known terms head to tail, the unknowns' direction lines, their crossing — with
//! what each step fixes written under the figure. All steps share the last one's
//! scale, so the figure grows in place as the student steps through it.

use eframe::egui::{self, Color32, Stroke, Vec2};
use linkage::polygon::Quantity;
use linkage_diagram::Rect;
use linkage_diagram::construction::{DirectionLine, construct};
use linkage_diagram::label::Label;
use linkage_diagram::layout::LaidPolygon;

use crate::i18n::tr;
use crate::state::AppState;
use crate::ui::polygon_paint::{INK, Paper, pos};
use crate::ui::typeset::{galley, job};

/// Which equation is being constructed, and how far.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ConstructionView {
    /// Index into the position's equations.
    pub equation: usize,
    /// Steps shown (0-based index of the last one shown).
    pub step: usize,
}

const LINE: Color32 = Color32::from_rgb(120, 60, 160);

impl ConstructionView {
    /// The construction section of the polygon pane.
    pub fn ui(&mut self, ui: &mut egui::Ui, st: &AppState, figure_height: f32) {
        let equations = st.session.polygons();
        if equations.is_empty() {
            ui.weak(tr!("construct.none"));
            return;
        }
        let view = self;
        view.equation = view.equation.min(equations.len() - 1);
        let eq = &equations[view.equation];
        let ink = ui.visuals().text_color();
        egui::ComboBox::from_label(tr!("construct.equation"))
            .selected_text(job(&Label::of_equation(eq), 14.0, ink))
            .width(ui.available_width() - 80.0)
            .show_ui(ui, |ui| {
                for (i, e) in equations.iter().enumerate() {
                    if ui
                        .selectable_label(
                            i == view.equation,
                            job(&Label::of_equation(e), 14.0, ink),
                        )
                        .clicked()
                    {
                        view.equation = i;
                        view.step = 0;
                    }
                }
            });
        let m = st.session.mechanism();
        let joint_names = m
            .joint_points()
            .into_iter()
            .map(|p| m.points[p].name.as_str());
        let pole = linkage_diagram::polygon_figure::pole_name(eq.kind, joint_names);
        let crossing = eq.lhs.first().map_or("x".to_string(), |t| {
            let prime = if eq.kind == Quantity::Velocity {
                ""
            } else {
                "'"
            };
            format!("{}{prime}", t.symbol.point.to_lowercase())
        });
        let steps = match construct(eq, &pole, &crossing) {
            Ok(steps) => steps,
            Err(e) => {
                let why = linkage_diagram::refusal::construction(crate::ui::words::lang(), &e);
                ui.colored_label(ui.visuals().warn_fg_color, why);
                return;
            }
        };
        view.step = view.step.min(steps.len() - 1);
        ui.horizontal(|ui| {
            if ui
                .add_enabled(view.step > 0, egui::Button::new(tr!("construct.back")))
                .clicked()
            {
                view.step -= 1;
            }
            ui.label(tr!(
                "construct.step",
                step = view.step + 1,
                of = steps.len()
            ));
            if ui
                .add_enabled(
                    view.step + 1 < steps.len(),
                    egui::Button::new(tr!("construct.next")),
                )
                .clicked()
            {
                view.step += 1;
            }
        });
        let Some(last) = steps.last() else {
            return;
        };
        let step = &steps[view.step];
        draw_step(ui, step, last.figure.extent(), figure_height);
        ui.label(job(&step.says, 14.0, ink));
    }
}

fn draw_step(
    ui: &mut egui::Ui,
    step: &linkage_diagram::construction::Step,
    fit: Rect,
    height: f32,
) {
    let paper = Paper::new(ui, height);
    let laid = paper.lay_out(&step.figure, Some(fit));
    if laid.px_per_unit <= 0.0 {
        return;
    }
    let (painter, rect) = (&paper.painter, paper.rect);
    for line in &step.lines {
        direction_line(painter, &laid, line, rect);
    }
    crate::ui::polygon_paint::draw(painter, step.figure.unit(), &laid, None, INK);
}

/// A direction line across the pane, dashed, named near where it enters the figure.
fn direction_line(
    painter: &egui::Painter,
    laid: &LaidPolygon,
    line: &DirectionLine,
    rect: egui::Rect,
) {
    let through = pos(laid.to_px(line.through));
    // y flips on screen.
    let d = Vec2::new(line.direction[0] as f32, -(line.direction[1] as f32));
    let reach = rect.size().length();
    painter.extend(egui::Shape::dashed_line(
        &[through - d * reach, through + d * reach],
        Stroke::new(1.2, LINE),
        7.0,
        4.0,
    ));
    let g = galley(painter, &line.label, 13.0, LINE);
    painter.galley(through + d * 40.0 + Vec2::new(4.0, -14.0), g, LINE);
}
