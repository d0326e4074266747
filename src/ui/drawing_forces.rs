//! The drawing's force elements in the side panel, where the drawing computes forces
//! (kinetostatics or dynamics): each spring's stiffness and free length, each
//! damper's coefficient, each point force's vector and when it acts, and a button to
//! remove each. The Spring, Damper and Force tools place them on the canvas.

use eframe::egui;
use linkage::Vec2;
use linkage::drawing::Drawing;
use linkage::scene::{ForceWhen, Models};

use crate::command::Command;
use crate::drawing::edit::{DrawingEdit, Element};
use crate::i18n::tr;
use crate::state::AppState;

/// The springs, dampers and point forces, each editable.
pub fn panel(ui: &mut egui::Ui, st: &mut AppState) {
    let Some(b) = st.drawing.as_ref() else {
        return;
    };
    let drawing = b.drawing();
    let none =
        drawing.springs.is_empty() && drawing.dampers.is_empty() && drawing.forces.is_empty();
    if drawing.models == Models::Kinematics || none {
        return;
    }
    let mut edits = Vec::new();
    ui.separator();
    ui.strong(tr!("draw.force_elements"));
    egui::Grid::new("drawing force elements")
        .num_columns(5)
        .show(ui, |ui| {
            springs(ui, drawing, &mut edits);
            dampers(ui, drawing, &mut edits);
            forces(ui, drawing, &mut edits);
        });
    for e in edits {
        st.push(Command::Drawing(e));
    }
}

fn ends(drawing: &Drawing, a: usize, b: usize) -> String {
    format!("{}–{}", drawing.points[a].name, drawing.points[b].name)
}

/// A stiffness in N/m, and a free length: unstretched as drawn, or typed (in the
/// drawing's length unit).
fn springs(ui: &mut egui::Ui, drawing: &Drawing, edits: &mut Vec<DrawingEdit>) {
    let unit = drawing.length_unit.to_metres();
    let unit_label = crate::session::unit_label_of(drawing.length_unit);
    for (i, s) in drawing.springs.iter().enumerate() {
        ui.label(tr!("draw.spring", ends = ends(drawing, s.a, s.b)));
        let mut k = s.k_n_per_m;
        let stiffness = ui.add(
            egui::DragValue::new(&mut k)
                .range(0.0..=1e9)
                .speed(0.01 * s.k_n_per_m.max(1.0))
                .suffix(" N/m"),
        );
        let mut as_drawn = s.free_length_m.is_none();
        let drawn_length = (drawing.points[s.a].at - drawing.points[s.b].at).norm();
        let toggled = ui
            .checkbox(&mut as_drawn, tr!("draw.free_as_drawn"))
            .changed();
        let mut free = s.free_length_m.unwrap_or(drawn_length) / unit;
        let typed = !as_drawn
            && ui
                .add(
                    egui::DragValue::new(&mut free)
                        .range(0.0..=1e9)
                        .speed(0.5)
                        .suffix(format!(" {unit_label}")),
                )
                .changed();
        if as_drawn {
            ui.label("");
        }
        if stiffness.changed() || toggled || typed {
            edits.push(DrawingEdit::SetSpring {
                spring: i,
                k_n_per_m: k,
                free_length_m: (!as_drawn).then_some(free * unit),
            });
        }
        remove(ui, Element::Spring(i), edits);
        ui.end_row();
    }
}

/// A coefficient in N·s/m.
fn dampers(ui: &mut egui::Ui, drawing: &Drawing, edits: &mut Vec<DrawingEdit>) {
    for (i, d) in drawing.dampers.iter().enumerate() {
        ui.label(tr!("draw.damper", ends = ends(drawing, d.a, d.b)));
        let mut c = d.c_n_s_per_m;
        if ui
            .add(
                egui::DragValue::new(&mut c)
                    .range(0.0..=1e9)
                    .speed(0.01 * d.c_n_s_per_m.max(1.0))
                    .suffix(" N s/m"),
            )
            .changed()
        {
            edits.push(DrawingEdit::SetDamper {
                damper: i,
                c_n_s_per_m: c,
            });
        }
        ui.label("");
        ui.label("");
        remove(ui, Element::Damper(i), edits);
        ui.end_row();
    }
}

/// The force's x and y, N, and whether it acts only on the working stroke (while
/// its point moves against it, as a cutting force does).
fn forces(ui: &mut egui::Ui, drawing: &Drawing, edits: &mut Vec<DrawingEdit>) {
    for (i, f) in drawing.forces.iter().enumerate() {
        ui.label(tr!("draw.force_at", point = drawing.points[f.point].name));
        let (mut x, mut y) = (f.force_n.x, f.force_n.y);
        let mut working = f.when == ForceWhen::WorkingStroke;
        let speed = 0.01 * f.force_n.norm().max(10.0);
        let xr = ui.add(
            egui::DragValue::new(&mut x)
                .speed(speed)
                .prefix("x ")
                .suffix(" N"),
        );
        let yr = ui.add(
            egui::DragValue::new(&mut y)
                .speed(speed)
                .prefix("y ")
                .suffix(" N"),
        );
        let wr = ui
            .checkbox(&mut working, tr!("draw.working_only"))
            .on_hover_text(tr!("draw.working_only_hint"));
        if xr.changed() || yr.changed() || wr.changed() {
            edits.push(DrawingEdit::SetForce {
                force: i,
                force_n: Vec2::new(x, y),
                when: if working {
                    ForceWhen::WorkingStroke
                } else {
                    ForceWhen::Always
                },
            });
        }
        remove(ui, Element::Force(i), edits);
        ui.end_row();
    }
}

fn remove(ui: &mut egui::Ui, element: Element, edits: &mut Vec<DrawingEdit>) {
    if ui.button(tr!("draw.remove")).clicked() {
        edits.push(DrawingEdit::DeleteElement(element));
    }
}
