//! Each massive link's body in the side panel, where the drawing computes forces: a
//! uniform body (its centroid at the mean of its points, a bar's or a triangle's
//! inertia), or its own centroid and inertia typed, as a real part has.

use eframe::egui;
use linkage::Vec2;
use linkage::scene::Models;

use crate::command::Command;
use crate::drawing::edit::DrawingEdit;
use crate::i18n::tr;
use crate::state::AppState;

/// One row per link with a mass: "uniform", or its centroid (x, y) and inertia.
pub fn panel(ui: &mut egui::Ui, st: &mut AppState) {
    let Some(b) = st.drawing.as_ref() else {
        return;
    };
    let drawing = b.drawing();
    let massive: Vec<usize> = (0..drawing.links.len())
        .filter(|&l| drawing.links[l].mass_kg.is_some())
        .collect();
    if drawing.models == Models::Kinematics || massive.is_empty() {
        return;
    }
    let unit = drawing.length_unit.to_metres();
    let unit_label = crate::session::unit_label_of(drawing.length_unit);
    let mut edits = Vec::new();
    ui.separator();
    ui.strong(tr!("draw.bodies"));
    egui::Grid::new("drawing bodies")
        .num_columns(5)
        .show(ui, |ui| {
            for l in massive {
                let link = &drawing.links[l];
                let Some((centroid, inertia)) = drawing.body(l) else {
                    continue;
                };
                ui.label(&link.name);
                let mut uniform = link.centroid.is_none() && link.inertia_kg_m2.is_none();
                let toggled = ui
                    .checkbox(&mut uniform, tr!("draw.uniform"))
                    .on_hover_text(tr!("draw.uniform_hint"))
                    .changed();
                let (mut x, mut y, mut i) = (centroid.x / unit, centroid.y / unit, inertia);
                let mut typed = false;
                if uniform {
                    ui.label("");
                    ui.label("");
                    ui.label("");
                } else {
                    for (v, axis) in [(&mut x, "x "), (&mut y, "y ")] {
                        let r = egui::DragValue::new(v)
                            .speed(0.5)
                            .prefix(axis)
                            .suffix(format!(" {unit_label}"));
                        typed |= ui.add(r).changed();
                    }
                    let r = egui::DragValue::new(&mut i)
                        .range(0.0..=1e9)
                        .speed(1e-3 * inertia.max(1e-6))
                        .suffix(" kg m²");
                    typed |= ui.add(r).changed();
                }
                if toggled || typed {
                    edits.push(DrawingEdit::SetBody {
                        link: l,
                        centroid: (!uniform).then(|| Vec2::new(x * unit, y * unit)),
                        inertia_kg_m2: (!uniform).then_some(i),
                    });
                }
                ui.end_row();
            }
        });
    for e in edits {
        st.push(Command::Drawing(e));
    }
}
