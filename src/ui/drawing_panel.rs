//! The side panel while drawing: the tools, what the drawing still lacks (with its
//! Grübler count), Done, every point's coordinates to type, names to change, the
//! output link, the input speed, each slider's guide and its direction, the masses,
//! force elements and drive.

use eframe::egui;
use linkage::Vec2;

use crate::command::Command;
use crate::drawing::edit::{Body, DrawingEdit, Named};
use crate::drawing::{DrawingEditor, Tool};
use crate::i18n::tr;
use crate::state::AppState;
use crate::ui::control_map::ControlKind;
use linkage::scene::{Models, Speed};

/// Draws the panel; its edits go to the drawing.
pub fn panel(ui: &mut egui::Ui, st: &mut AppState) {
    let Some(b) = st.drawing.as_ref() else {
        return;
    };
    ui.heading(tr!("draw.heading"));
    let mut chosen = None;
    ui.horizontal_wrapped(|ui| {
        for tool in Tool::ALL {
            let r = ui.selectable_label(b.tool == tool, crate::ui::words::tool_name(tool));
            st.controls
                .note(ui, ControlKind::DrawTool, tool.label(), &r);
            if r.clicked() {
                chosen = Some(tool);
            }
        }
    });
    ui.label(egui::RichText::new(crate::ui::words::tool_hint(b.tool)).weak());
    ui.separator();
    status(ui, st);
    ui.separator();
    let action = actions(ui, st);
    ui.separator();
    points(ui, st);
    ui.separator();
    model(ui, st);
    links(ui, st);
    sliders(ui, st);
    crate::ui::drawing_bodies::panel(ui, st);
    crate::ui::drawing_forces::panel(ui, st);
    crate::ui::drawing_drive::panel(ui, st);
    if let (Some(tool), Some(b)) = (chosen, st.drawing.as_mut()) {
        b.tool = tool;
        b.pending = None;
    }
    if action {
        st.push(Command::FinishDrawing);
    }
}

/// The mobility and what is missing, or that the drawing is a mechanism.
fn status(ui: &mut egui::Ui, st: &AppState) {
    let Some(b) = st.drawing.as_ref() else {
        return;
    };
    let m = b.drawing().mobility();
    ui.label(tr!(
        "draw.mobility",
        moving = m.moving,
        joints = m.revolutes + m.prismatics,
        dof = m.dof()
    ));
    match &b.problem {
        Some(why) => {
            let why = crate::ui::words::drawing_problem(why, b.drawing().length_unit);
            ui.colored_label(egui::Color32::from_rgb(150, 90, 0), why)
        }
        None => ui.colored_label(egui::Color32::from_rgb(20, 110, 40), tr!("draw.complete")),
    };
    if let Some(why) = &b.refusal {
        ui.colored_label(egui::Color32::DARK_RED, why.words(crate::ui::words::lang()));
    }
}

/// "Done" (once the drawing is a mechanism): back to the viewer over it. Returns
/// whether it was clicked.
fn actions(ui: &mut egui::Ui, st: &mut AppState) -> bool {
    let Some(b) = st.drawing.as_ref() else {
        return false;
    };
    let done = ui.add_enabled(b.problem.is_none(), egui::Button::new(tr!("draw.done")));
    st.controls.note(ui, ControlKind::DrawTool, "Done", &done);
    done.clicked()
}

/// Every point with its coordinates (mm) to type, and whether it is a ground pivot.
fn points(ui: &mut egui::Ui, st: &mut AppState) {
    let Some(b) = st.drawing.as_mut() else {
        return;
    };
    let unit = b.drawing().length_unit.to_metres();
    let mut edits = Vec::new();
    ui.strong(tr!("draw.points"));
    egui::Grid::new("drawing points")
        .num_columns(4)
        .show(ui, |ui| {
            for p in 0..b.drawing().points.len() {
                name_cell(ui, b, Named::Point(p), &mut edits);
                let point = &b.drawing().points[p];
                let mut xy = [point.at.x / unit, point.at.y / unit];
                let mut changed = false;
                for v in &mut xy {
                    changed |= ui
                        .add(egui::DragValue::new(v).speed(1.0).suffix(" mm"))
                        .changed();
                }
                let mut ground = point.ground;
                if ui.checkbox(&mut ground, tr!("draw.ground")).changed() {
                    edits.push(DrawingEdit::SetGround { point: p, ground });
                }
                if changed {
                    let to = Vec2::new(xy[0] * unit, xy[1] * unit);
                    edits.push(DrawingEdit::MovePoint { point: p, to });
                }
                ui.end_row();
            }
        });
    for e in edits {
        st.push(Command::Drawing(e));
    }
}

/// Every link's name, which one is the output for the time ratio, and the input
/// speed.
fn links(ui: &mut egui::Ui, st: &mut AppState) {
    let Some(b) = st.drawing.as_mut() else {
        return;
    };
    let mut edits = Vec::new();
    ui.strong(tr!("draw.links"));
    egui::Grid::new("drawing links")
        .num_columns(4)
        .show(ui, |ui| {
            // Without a pick, the scene's output is its last link: slider blocks come
            // after the links, so with sliders it is the last block (none of these).
            let drawing = b.drawing();
            let output = drawing.output.or_else(|| {
                (drawing.sliders.is_empty() && !drawing.links.is_empty())
                    .then(|| drawing.links.len() - 1)
            });
            let masses = drawing.models != Models::Kinematics;
            for l in 0..b.drawing().links.len() {
                name_cell(ui, b, Named::Link(l), &mut edits);
                let role = if b.drawing().driver == Some(l) {
                    tr!("draw.input")
                } else {
                    String::new()
                };
                ui.label(role);
                if ui.radio(output == Some(l), tr!("draw.output")).clicked() {
                    edits.push(DrawingEdit::SetOutput(Some(l)));
                }
                if masses {
                    mass_cell(ui, Body::Link(l), b.drawing().links[l].mass_kg, &mut edits);
                }
                ui.end_row();
            }
        });
    // Shown in rpm whatever the scene wrote; an edit writes rpm.
    let mut rpm = match b.drawing().speed {
        Speed::Rpm(rpm) => rpm,
        Speed::RadPerSecond(w) => w * 60.0 / std::f64::consts::TAU,
    };
    ui.horizontal(|ui| {
        ui.label(tr!("draw.input_speed"));
        if ui
            .add(egui::DragValue::new(&mut rpm).speed(1.0).suffix(" rpm"))
            .changed()
        {
            edits.push(DrawingEdit::SetSpeedRpm(rpm));
        }
    });
    for e in edits {
        st.push(Command::Drawing(e));
    }
}

/// What the drawn scene computes: kinematics, or kinetostatics or dynamics with
/// masses (set per link and block in their rows), gravity and the force elements.
fn model(ui: &mut egui::Ui, st: &mut AppState) {
    let Some(b) = st.drawing.as_ref() else {
        return;
    };
    let (mut models, mut gravity) = (b.drawing().models, b.drawing().gravity);
    let mut edits = Vec::new();
    ui.horizontal(|ui| {
        ui.label(tr!("draw.computes"));
        for (m, label) in [
            (Models::Kinematics, tr!("draw.kinematics")),
            (Models::Kinetostatics, tr!("draw.kinetostatics")),
            (Models::Dynamics, tr!("draw.dynamics")),
        ] {
            if ui.radio_value(&mut models, m, label).changed() {
                edits.push(DrawingEdit::SetModels(models));
            }
        }
    });
    if models != Models::Kinematics && ui.checkbox(&mut gravity, tr!("draw.gravity")).changed() {
        edits.push(DrawingEdit::SetGravity(gravity));
    }
    for e in edits {
        st.push(Command::Drawing(e));
    }
}

/// A body's mass in kg; 0 is massless.
fn mass_cell(ui: &mut egui::Ui, body: Body, kg: Option<f64>, edits: &mut Vec<DrawingEdit>) {
    let mut value = kg.unwrap_or(0.0);
    if ui
        .add(
            egui::DragValue::new(&mut value)
                .range(0.0..=1e6)
                .speed(0.1)
                .suffix(" kg"),
        )
        .changed()
    {
        edits.push(DrawingEdit::SetMass(body, (value > 0.0).then_some(value)));
    }
}

/// Every slider's guide: ground or a link, and its direction (deg).
fn sliders(ui: &mut egui::Ui, st: &mut AppState) {
    let Some(b) = st.drawing.as_ref() else {
        return;
    };
    let drawing = b.drawing();
    if drawing.sliders.is_empty() {
        return;
    }
    let mut edits = Vec::new();
    ui.separator();
    ui.strong(tr!("draw.sliders"));
    egui::Grid::new("drawing sliders")
        .num_columns(3)
        .show(ui, |ui| {
            for (i, s) in drawing.sliders.iter().enumerate() {
                let pin = &drawing.points[s.point].name;
                let name_of =
                    |g: Option<usize>| g.map_or("ground", |l| drawing.links[l].name.as_str());
                let mut guide = s.guide;
                egui::ComboBox::new(("guide", i), tr!("draw.guide_of", pin = pin))
                    .selected_text(name_of(guide))
                    .show_ui(ui, |ui| {
                        let choices = std::iter::once(None).chain(
                            (0..drawing.links.len())
                                .filter(|&l| !drawing.links[l].points.contains(&s.point))
                                .map(Some),
                        );
                        for g in choices {
                            ui.selectable_value(&mut guide, g, name_of(g));
                        }
                    });
                let mut deg = s.angle_rad.to_degrees();
                let turned = ui
                    .add(egui::DragValue::new(&mut deg).speed(1.0).suffix("°"))
                    .changed();
                if guide != s.guide || turned {
                    edits.push(DrawingEdit::SetGuide {
                        slider: i,
                        guide,
                        angle_rad: deg.to_radians(),
                    });
                }
                if drawing.models != Models::Kinematics {
                    mass_cell(ui, Body::Block(i), s.mass_kg, &mut edits);
                }
                ui.end_row();
            }
        });
    for e in edits {
        st.push(Command::Drawing(e));
    }
}

/// A point's or link's name: a button that, clicked, becomes a text field; Enter or
/// leaving the field renames.
fn name_cell(ui: &mut egui::Ui, b: &mut DrawingEditor, what: Named, edits: &mut Vec<DrawingEdit>) {
    let current = match what {
        Named::Point(p) => b.drawing().points[p].name.clone(),
        Named::Link(l) => b.drawing().links[l].name.clone(),
    };
    match &mut b.naming {
        Some((named, text)) if *named == what => {
            let r = ui.add(egui::TextEdit::singleline(text).desired_width(70.0));
            let label = tr!("draw.new_name", current = current);
            r.widget_info(|| {
                egui::WidgetInfo::labeled(egui::accesskit::Role::TextInput, true, &label)
            });
            if !r.has_focus() && !r.lost_focus() {
                r.request_focus();
            }
            if r.lost_focus() {
                if *text != current {
                    edits.push(DrawingEdit::Rename(what, text.clone()));
                }
                b.naming = None;
            }
        }
        _ => {
            if ui
                .button(&current)
                .on_hover_text(tr!("draw.rename_hint"))
                .clicked()
            {
                b.naming = Some((what, current));
            }
        }
    }
}
