//! The gear lab's train view on screen: the train chosen among the shipped ones,
//! its inputs' speeds on sliders, every member's speed and ratio in a table in the
//! members' colours, the carriers' converted-train (Willis) ratios and the planetary
//! assembly checks; the canvas, drawn by the GPU pass, names each member with its
//! speed at its shaft's free end and each gear with its teeth.

use eframe::egui::{self, Align2, Color32, FontId};
use linkage::gears::train_file::StageKind;
use linkage::gears::{AssemblyCheck, TrainSolution};
use linkage_diagram::numbers::significant;
use linkage_diagram::train_schematic::{Schematic, schematic};

use crate::catalog::TRAINS;
use crate::gear_lab::GearLab;
use crate::i18n::tr;
use crate::render::train_shapes::{build_train, member_colour};
use crate::train_view::TrainView;
use crate::ui::gear_canvas::Canvas;
use crate::ui::gear_pair::halo_text;

/// The inputs' speeds the sliders reach, rpm (either way).
const INPUT_RPM: f64 = 3000.0;

/// The train view's controls and numbers.
pub fn panel(ui: &mut egui::Ui, lab: &mut GearLab) {
    ui.label(tr!("gear.train_how"));
    choose(ui, &mut lab.train);
    let view = &mut lab.train;
    if !view.file.notes.is_empty() {
        ui.small(view.file.notes.clone());
    }
    for index in 0..view.file.inputs.len() {
        let input = &view.file.inputs[index];
        let text = tr!("gear.train_input", member = input.member.clone());
        let mut rpm = input.rpm;
        ui.add(
            egui::Slider::new(&mut rpm, -INPUT_RPM..=INPUT_RPM)
                .step_by(1.0)
                .text(text),
        );
        view.set_input_rpm(index, rpm);
    }
    let slowed = view.solve().ok().map(TrainView::slowed);
    ui.horizontal(|ui| {
        crate::ui::gear_canvas::play_button(ui, lab);
        if let Some(slowed) = slowed.filter(|&times| times > 1.0) {
            ui.label(tr!("gear.train_slowed", times = significant(slowed, 3)));
        }
    });
    match lab.train.solve() {
        Ok(s) => numbers(ui, &lab.train, s),
        Err(e) => {
            let why = linkage_diagram::refusal::train(crate::ui::words::lang(), e);
            ui.colored_label(ui.visuals().error_fg_color, why);
        }
    }
}

/// The shipped trains, by their names.
fn choose(ui: &mut egui::Ui, view: &mut TrainView) {
    let name_of = |k: usize| {
        TRAINS
            .get(k)
            .and_then(|t| linkage::gears::train_file::TrainFile::from_ron(t.text).ok())
            .map_or_else(String::new, |f| f.name)
    };
    let mut choice = view.choice;
    let label = ui.label(tr!("gear.train_choose"));
    egui::ComboBox::from_id_salt("gear train")
        .selected_text(view.file.name.clone())
        .width(ui.available_width() - 8.0)
        .show_ui(ui, |ui| {
            for k in 0..TRAINS.len() {
                ui.selectable_value(&mut choice, k, name_of(k));
            }
        })
        .response
        .labelled_by(label.id);
    if choice != view.choice {
        let camera = view.camera;
        *view = TrainView::of(choice);
        view.camera = camera;
    }
}

fn rgb(c: [f32; 4]) -> Color32 {
    let [r, g, b, _] = c.map(|v| (v * 255.0).round() as u8);
    Color32::from_rgb(r, g, b)
}

/// Every member's speed and ratio, the Willis ratios, the assembly checks.
fn numbers(ui: &mut egui::Ui, view: &TrainView, s: &TrainSolution) {
    ui.separator();
    let held: Vec<&str> = view.held().collect();
    if held.is_empty() {
        ui.label(tr!("gear.train_dof", dof = s.dof));
    } else {
        ui.label(tr!(
            "gear.train_dof_held",
            free = s.dof.saturating_sub(held.len()),
            held = held.join(", "),
            dof = s.dof
        ));
    }
    let first = view.file.inputs.first().map(|i| i.member.clone());
    egui::Grid::new("train speeds")
        .striped(true)
        .show(ui, |ui| {
            ui.strong(tr!("gear.train_member"));
            ui.strong(tr!("gear.train_speed"));
            ui.strong(match &first {
                Some(f) => tr!("gear.train_ratio", input = f.clone()),
                None => String::new(),
            });
            ui.end_row();
            for (k, m) in s.speeds_rpm.iter().enumerate() {
                let colour = rgb(member_colour(k)).gamma_multiply(0.8);
                ui.colored_label(colour, egui::RichText::new(&m.member).strong());
                ui.label(significant(m.rpm, 5));
                let ratio = first.as_ref().and_then(|f| s.ratio(f, &m.member));
                ui.label(
                    ratio
                        .filter(|r| r.is_finite())
                        .map_or("—".into(), |r| significant(r, 5)),
                );
                ui.end_row();
            }
        });
    for w in &s.willis {
        ui.label(tr!(
            "gear.train_willis",
            carrier = w.carrier.clone(),
            from = w.from.clone(),
            to = w.to.clone(),
            ratio = significant(w.ratio, 5)
        ));
    }
    for check in &s.assembly {
        let (text, holds) = assembly_words(check);
        if holds {
            ui.label(tr!("gear.train_met", check = text));
        } else {
            ui.colored_label(
                Color32::from_rgb(190, 40, 30),
                tr!("gear.train_not_met", check = text),
            );
        }
    }
    ui.label(tr!("gear.train_legend"));
}

/// An assembly condition in the user's words, and whether it holds.
fn assembly_words(check: &AssemblyCheck) -> (String, bool) {
    match check {
        AssemblyCheck::Coaxial {
            carrier,
            distances_modules,
            holds,
        } => {
            let list: Vec<String> = distances_modules
                .iter()
                .map(|d| significant(*d, 4))
                .collect();
            (
                tr!(
                    "gear.train_coaxial",
                    carrier = carrier.clone(),
                    distances = list.join(", ")
                ),
                *holds,
            )
        }
        AssemblyCheck::EqualSpacing {
            carrier,
            planets,
            value,
            holds,
        } => (
            tr!(
                "gear.train_spacing",
                carrier = carrier.clone(),
                k = planets,
                value = significant(*value, 4)
            ),
            *holds,
        ),
        AssemblyCheck::Neighbours {
            carrier,
            planets,
            clearance_modules,
            holds,
        } => (
            tr!(
                "gear.train_neighbours",
                carrier = carrier.clone(),
                k = planets,
                gap = significant(*clearance_modules, 3)
            ),
            *holds,
        ),
    }
}

/// The train on the lab's canvas: the schematic, each member's name and speed, each
/// gear's teeth.
pub fn draw(canvas: &Canvas<'_>, lab: &mut GearLab) {
    let view = &mut lab.train;
    let (painter, rect) = (canvas.painter, canvas.rect);
    let s = schematic(&view.file);
    // The names stand outside the shafts' ends: room for them either side.
    if rect.width() > 1.0 && rect.height() > 1.0 {
        let room = egui::vec2((0.2 * rect.width()).min(130.0), 16.0);
        view.camera.fit_within(s.bounds, rect, rect.shrink2(room));
    }
    let view = &*view;
    let solved = view.solve().ok();
    let held: Vec<bool> = view
        .file
        .members
        .iter()
        .map(|m| view.held().any(|h| h == m.name))
        .collect();
    if let Ok(mut list) = canvas.shapes.lock() {
        build_train(&mut list, &s, &view.angles, &held, &view.camera);
    }
    canvas.paint(&view.camera);
    names(painter, rect, view, &s, solved);
}

/// Each member's name and speed at its shaft's free end (above a hollow shaft's
/// end), then the gears' names.
fn names(
    painter: &egui::Painter,
    rect: egui::Rect,
    view: &TrainView,
    s: &Schematic,
    solved: Option<&TrainSolution>,
) {
    let font = FontId::proportional(13.0);
    let mut placed: Vec<egui::Rect> = Vec::new();
    for l in &s.members {
        let Some(end) = l.label_at else { continue };
        let member = &view.file.members[l.member].name;
        let text = match solved.and_then(|sol| sol.speed_rpm(member)) {
            Some(rpm) => tr!(
                "gear.train_member_speed",
                member = member.clone(),
                rpm = significant(rpm, 4)
            ),
            None => member.clone(),
        };
        let at = view.camera.to_screen(end, rect);
        let (align, offset) = if l.hollow {
            (Align2::CENTER_BOTTOM, egui::vec2(0.0, -8.0))
        } else if l.label_left {
            (Align2::RIGHT_CENTER, egui::vec2(-6.0, 0.0))
        } else {
            (Align2::LEFT_CENTER, egui::vec2(6.0, 0.0))
        };
        let colour = rgb(member_colour(l.member))
            .gamma_multiply(0.75)
            .to_opaque();
        let size = painter
            .layout_no_wrap(text.clone(), font.clone(), colour)
            .size();
        placed.push(align.anchor_size(at + offset, size));
        halo_text(painter, at + offset, align, &text, &font, colour);
    }
    gear_names(painter, rect, view, s, &mut placed);
}

/// Each gear's name and teeth beside its block's top: right of it, else left,
/// else beside its bottom, whichever first clears the names in `placed`.
fn gear_names(
    painter: &egui::Painter,
    rect: egui::Rect,
    view: &TrainView,
    s: &Schematic,
    placed: &mut Vec<egui::Rect>,
) {
    let small = FontId::proportional(12.0);
    for b in &s.blocks {
        let Some(g) = b.gear.and_then(|g| view.file.gears.get(g)) else {
            continue;
        };
        let text = tr!("gear.train_teeth", gear = g.name.clone(), z = g.teeth);
        let size = painter
            .layout_no_wrap(text.clone(), small.clone(), Color32::BLACK)
            .size();
        let outer = if b.internal {
            b.radius + s.unit
        } else {
            b.radius
        };
        let (top, bottom) = (b.centres_y[0] + outer, b.centres_y[0] - outer);
        // Clear of a frame's hatch above the block.
        let (right, left) = (
            b.x + b.half_width + 0.6 * s.unit,
            b.x - b.half_width - 0.6 * s.unit,
        );
        let screen = |p: [f64; 2]| view.camera.to_screen(p, rect);
        let tries = [
            (
                screen([right, top]) + egui::vec2(3.0, 2.0),
                Align2::LEFT_BOTTOM,
            ),
            (
                screen([left, top]) + egui::vec2(-3.0, 2.0),
                Align2::RIGHT_BOTTOM,
            ),
            (
                screen([right, bottom]) + egui::vec2(3.0, -2.0),
                Align2::LEFT_TOP,
            ),
            (
                screen([left, bottom]) + egui::vec2(-3.0, -2.0),
                Align2::RIGHT_TOP,
            ),
        ];
        let free = |(at, align): &(egui::Pos2, Align2)| {
            let r = align.anchor_size(*at, size);
            !placed.iter().any(|p| p.intersects(r))
        };
        let (at, align) = tries.iter().copied().find(free).unwrap_or(tries[0]);
        placed.push(align.anchor_size(at, size));
        halo_text(painter, at, align, &text, &small, Color32::from_gray(40));
    }
    // Each belt or chain named with its ratio beside its run's middle.
    for run in &s.runs {
        let Some(stage) = view.file.stages.get(run.stage) else {
            continue;
        };
        let ratio = significant(stage.ratio, 4);
        let text = match stage.kind {
            StageKind::Belt => tr!("gear.train_belt", ratio = ratio),
            StageKind::Chain => tr!("gear.train_chain", ratio = ratio),
        };
        let middle = [run.x + s.unit, 0.5 * (run.y[0] + run.y[1])];
        let at = view.camera.to_screen(middle, rect) + egui::vec2(4.0, 0.0);
        halo_text(
            painter,
            at,
            Align2::LEFT_CENTER,
            &text,
            &small,
            Color32::from_gray(40),
        );
    }
}
