//! The gear-cutting lab on screen: its controls in the side pane (teeth, module,
//! shift and pressure angle on sliders, the roll with Play, the gear's circles and
//! tooth thickness, whether it is undercut and the least shift that cures it, the
//! way back to the mechanism), and the canvas the GPU pass draws it on, with the
//! circles named beside it.

use eframe::egui::{self, Align2, Color32, FontId, Sense};
use linkage::gears::Gear;
use linkage_diagram::numbers::significant;

use crate::gear_lab::{GearLab, LabMode};
use crate::i18n::tr;
use crate::render::Renderer;
use crate::render::gear_shapes::{BACKGROUND, bounds, build_gear_lab, undercut_segments};
use crate::render::shape::SharedShapes;
use crate::state::AppState;
use crate::ui::gear_canvas::Canvas;

/// The lab's controls and numbers.
pub fn panel(ui: &mut egui::Ui, st: &mut AppState) {
    let Some(lab) = st.gear_lab.as_mut() else {
        return;
    };
    ui.heading(tr!("gear.title"));
    if ui.button(tr!("gear.back")).clicked() {
        st.gear_lab = None;
        st.commands.fit = true;
        return;
    }
    ui.horizontal(|ui| {
        ui.selectable_value(&mut lab.mode, LabMode::Cutting, tr!("gear.mode_cutting"));
        ui.selectable_value(&mut lab.mode, LabMode::Pair, tr!("gear.mode_pair"));
        ui.selectable_value(&mut lab.mode, LabMode::Train, tr!("gear.mode_train"));
    });
    match lab.mode {
        LabMode::Pair => return pair_panel(ui, lab),
        LabMode::Train => return crate::ui::gear_train::panel(ui, lab),
        LabMode::Cutting => {}
    }
    ui.label(tr!("gear.how"));
    gear_sliders(ui, lab, [tr!("gear.teeth"), tr!("gear.shift")]);
    ui.horizontal(|ui| {
        crate::ui::gear_canvas::play_button(ui, lab);
        ui.add(egui::Slider::new(&mut lab.roll, 0.0..=1.0).text(tr!("gear.roll")));
    });
    match lab.gear() {
        Ok(g) => {
            let least = g.least_shift_without_undercut();
            if GearLab::undercut(&g) && ui.button(tr!("gear.use_least_shift")).clicked() {
                // Rounded up to the slider's step, so that it clears the limit.
                lab.shift = (least * 100.0).ceil() / 100.0;
            }
            numbers(ui, &g);
        }
        Err(e) => {
            ui.colored_label(ui.visuals().error_fg_color, e.to_string());
        }
    }
}

/// The pair's view: the lab's gear as the pinion, the wheel's numbers, the turn.
fn pair_panel(ui: &mut egui::Ui, lab: &mut GearLab) {
    ui.label(tr!("gear.pair_how"));
    gear_sliders(
        ui,
        lab,
        [tr!("gear.pinion_teeth"), tr!("gear.pinion_shift")],
    );
    crate::ui::gear_pair::controls(ui, lab);
    match lab.pair() {
        Ok(pair) => crate::ui::gear_pair::numbers(ui, &pair),
        Err(e) => {
            ui.colored_label(ui.visuals().error_fg_color, e.to_string());
        }
    }
}

/// The gear's teeth, module, shift and pressure angle; `names` the teeth's and the
/// shift's (the pinion's z₁ and x₁ in the pair).
fn gear_sliders(ui: &mut egui::Ui, lab: &mut GearLab, names: [String; 2]) {
    let [teeth, shift] = names;
    ui.add(egui::Slider::new(&mut lab.teeth, 6..=80).text(teeth));
    ui.add(
        egui::Slider::new(&mut lab.module_mm, 1.0..=20.0)
            .step_by(0.5)
            .text(tr!("gear.module")),
    );
    ui.add(
        egui::Slider::new(&mut lab.shift, -1.0..=1.0)
            .step_by(0.01)
            .text(shift),
    );
    ui.add(
        egui::Slider::new(&mut lab.pressure_angle_deg, 14.5..=25.0)
            .step_by(0.5)
            .text(tr!("gear.pressure_angle")),
    );
}

/// The gear's circles, its tooth thickness, and undercut or not.
fn numbers(ui: &mut egui::Ui, g: &Gear) {
    let mm = |m: f64| significant(m * 1e3, 5);
    ui.separator();
    ui.label(tr!(
        "gear.circles",
        d = mm(2.0 * g.pitch_radius_m),
        db = mm(2.0 * g.base_radius_m),
        da = mm(2.0 * g.tip_radius_m),
        df = mm(2.0 * g.root_radius_m)
    ));
    ui.label(tr!(
        "gear.thickness",
        s = mm(g.tooth_thickness_m),
        e = mm(g.space_width_m)
    ));
    let least = significant(g.least_shift_without_undercut(), 3);
    if GearLab::undercut(g) {
        ui.colored_label(
            Color32::from_rgb(190, 40, 30),
            tr!(
                "gear.undercut",
                x = significant(g.spec.shift, 3),
                least = least
            ),
        );
    } else {
        ui.label(tr!("gear.no_undercut", least = least));
    }
    if g.is_pointed() {
        ui.colored_label(Color32::from_rgb(190, 40, 30), tr!("gear.pointed"));
    }
    if let Some(s) = g.thin_tip_m() {
        let least = linkage::gears::LEAST_TIP_THICKNESS_MODULES * g.spec.module_m;
        ui.colored_label(
            Color32::from_rgb(190, 40, 30),
            tr!("gear.thin_tip", s = mm(s), least = mm(least)),
        );
    }
    ui.label(tr!("gear.legend"));
}

/// The canvas: the blank, the cutter and its trace, drawn by the GPU pass.
pub fn canvas(
    ui: &mut egui::Ui,
    st: &mut AppState,
    shapes: &SharedShapes,
    renderer: Option<&Renderer>,
) {
    let (rect, _) = ui.allocate_exact_size(ui.available_size(), Sense::hover());
    let Some(lab) = st.gear_lab.as_mut() else {
        return;
    };
    let painter = ui.painter_at(rect);
    let [r, g, b, _] = BACKGROUND.map(|c| (c * 255.0).round() as u8);
    painter.rect_filled(rect, 0.0, Color32::from_rgb(r, g, b));
    let pixels_per_point = ui.ctx().pixels_per_point();
    let canvas = Canvas {
        painter: &painter,
        rect,
        shapes,
        renderer,
        pixels_per_point,
    };
    match lab.mode {
        LabMode::Pair => crate::ui::gear_pair::draw(ui, &canvas, lab),
        LabMode::Train => crate::ui::gear_train::draw(&canvas, lab),
        LabMode::Cutting => cutting(ui, &canvas, lab),
    }
}

/// The cutting view: the blank, the cutter and its trace, the circles' names.
fn cutting(ui: &egui::Ui, canvas: &Canvas<'_>, lab: &mut GearLab) {
    let (painter, rect) = (canvas.painter, canvas.rect);
    let Ok(g) = lab.gear() else {
        return;
    };
    if rect.width() > 1.0 && rect.height() > 1.0 {
        lab.camera.fit(bounds(&g), rect);
    }
    let undercut = undercut_of(ui, &g);
    if let Ok(mut list) = canvas.shapes.lock() {
        build_gear_lab(&mut list, lab, &g, &undercut, &lab.camera);
    }
    canvas.paint(&lab.camera);
    names(painter, rect, lab, &g);
}

/// The circles' names outside the tip circle, below the centre (where the cutter
/// never comes and nothing is cut), each with a leader to its circle; N1's beside it.
fn names(painter: &egui::Painter, rect: egui::Rect, lab: &GearLab, g: &Gear) {
    let font = FontId::proportional(13.0);
    let outside = g.tip_radius_m + 1.5 * g.spec.module_m;
    for (radius, name, colour, angle) in [
        (
            g.pitch_radius_m,
            tr!("gear.pitch_circle"),
            Color32::from_rgb(25, 128, 50),
            235.0_f64,
        ),
        (
            g.base_radius_m,
            tr!("gear.base_circle"),
            Color32::from_rgb(190, 90, 25),
            305.0,
        ),
    ] {
        let (sin, cos) = angle.to_radians().sin_cos();
        let on = lab.camera.to_screen([radius * cos, radius * sin], rect);
        let label = lab.camera.to_screen([outside * cos, outside * sin], rect);
        painter.line_segment([on, label], egui::Stroke::new(1.0, colour));
        let align = if cos < 0.0 {
            Align2::RIGHT_TOP
        } else {
            Align2::LEFT_TOP
        };
        painter.text(label, align, name, font.clone(), colour);
    }
    if let Some(&phi) = lab.positions(g).last() {
        let n1 = crate::render::gear_shapes::limit_point(g, phi);
        let at = lab.camera.to_screen(n1, rect) + egui::vec2(6.0, 2.0);
        painter.text(
            at,
            Align2::LEFT_TOP,
            "N₁",
            font,
            Color32::from_rgb(140, 25, 115),
        );
    }
}

/// The undercut's segments, searched once for each gear and kept in egui's memory
/// while the gear stays the same (the roll moves on every frame of play; the
/// search costs more than the rest of the frame).
fn undercut_of(ui: &egui::Ui, g: &Gear) -> std::sync::Arc<Vec<[[f64; 2]; 2]>> {
    type Kept = (GearKey, std::sync::Arc<Vec<[[f64; 2]; 2]>>);
    let s = g.spec;
    let key: GearKey = (
        s.teeth,
        s.module_m.to_bits(),
        s.shift.to_bits(),
        s.pressure_angle_rad.to_bits(),
    );
    let id = egui::Id::unique("gear_lab::undercut");
    if let Some((kept, segments)) = ui.data(|d| d.get_temp::<Kept>(id))
        && kept == key
    {
        return segments;
    }
    let segments = std::sync::Arc::new(undercut_segments(g));
    ui.data_mut(|d| d.insert_temp::<Kept>(id, (key, segments.clone())));
    segments
}

/// What the undercut depends on: teeth, module, shift and pressure angle, bit for bit.
type GearKey = (u32, u64, u64, u64);
