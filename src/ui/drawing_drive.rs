//! The drawing's drive in the side panel, where the drawing computes forces: the
//! motor (none, a constant torque, a linear induction-motor line, or a table of
//! torque against speed), the gear ratio (or the scene's train, shown), the rotor's
//! inertia and a flywheel on the crank or the motor shaft. Each change is one edit, checked as the scene checks it.

use eframe::egui;
use linkage::SceneProblem;
use linkage::model::DriveTrain;
use linkage::scene::{DriveSpec, DriveTrainSpec, Models, MotorSpec, Shaft};
use linkage_diagram::numbers::significant;

use crate::command::Command;
use crate::drawing::edit::DrawingEdit;
use crate::i18n::tr;
use crate::state::AppState;

/// Which characteristic the motor has, for the chooser.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    None,
    Constant,
    Linear,
    Table,
}

impl Kind {
    const ALL: [Self; 4] = [Self::None, Self::Constant, Self::Linear, Self::Table];

    fn of(drive: Option<&DriveSpec>) -> Self {
        match drive.map(|d| &d.motor) {
            None => Self::None,
            Some(MotorSpec::Constant { .. }) => Self::Constant,
            Some(MotorSpec::Linear { .. }) => Self::Linear,
            Some(MotorSpec::Table { .. }) => Self::Table,
        }
    }

    fn label(self) -> String {
        match self {
            Self::None => tr!("drive.none"),
            Self::Constant => tr!("drive.constant"),
            Self::Linear => tr!("drive.linear"),
            Self::Table => tr!("drive.table"),
        }
    }

    /// A first motor of this kind, to edit from.
    fn motor(self) -> Option<MotorSpec> {
        match self {
            Self::None => None,
            Self::Constant => Some(MotorSpec::Constant { torque_n_m: 100.0 }),
            Self::Linear => Some(MotorSpec::Linear {
                no_load_rpm: 1500.0,
                rated_torque_n_m: 100.0,
                rated_rpm: 1450.0,
            }),
            Self::Table => Some(MotorSpec::Table {
                points: vec![(0.0, 200.0), (1450.0, 100.0), (1500.0, 0.0)],
            }),
        }
    }
}

/// The drive's editor, shown where the drawing computes forces.
pub fn panel(ui: &mut egui::Ui, st: &mut AppState) {
    let Some(b) = st.drawing.as_ref() else {
        return;
    };
    if b.drawing().models == Models::Kinematics {
        return;
    }
    let before = b.drawing().drive.clone();
    let mut drive = before.clone();
    ui.separator();
    ui.strong(tr!("drive.heading"));
    let kind = Kind::of(drive.as_ref());
    let mut chosen = kind;
    egui::ComboBox::from_label(tr!("drive.motor"))
        .selected_text(kind.label())
        .show_ui(ui, |ui| {
            for k in Kind::ALL {
                ui.selectable_value(&mut chosen, k, k.label());
            }
        });
    if chosen != kind {
        drive = chosen.motor().map(|motor| DriveSpec {
            motor,
            gear_ratio: drive.as_ref().map_or(1.0, |d| d.gear_ratio),
            train: drive.as_ref().and_then(|d| d.train.clone()),
            motor_inertia_kg_m2: drive.as_ref().map_or(0.0, |d| d.motor_inertia_kg_m2),
            flywheel_kg_m2: drive.as_ref().map_or(0.0, |d| d.flywheel_kg_m2),
            flywheel_on: drive.as_ref().map_or(Shaft::Crank, |d| d.flywheel_on),
        });
    }
    if let Some(d) = drive.as_mut() {
        motor(ui, &mut d.motor);
        gear_and_flywheel(ui, d);
    }
    if drive != before {
        st.push(Command::Drawing(DrawingEdit::SetDrive(drive)));
    }
}

/// A number with its unit.
fn number(ui: &mut egui::Ui, label: &str, value: &mut f64, unit: &str) {
    let speed = 0.01 * value.abs().max(1.0);
    ui.horizontal(|ui| {
        // The name first: it names the value for screen readers.
        let name = ui.label(label);
        ui.add(egui::DragValue::new(value).speed(speed).suffix(unit))
            .labelled_by(name.id);
    });
}

fn motor(ui: &mut egui::Ui, m: &mut MotorSpec) {
    match m {
        MotorSpec::Constant { torque_n_m } => number(ui, &tr!("drive.torque"), torque_n_m, " N·m"),
        MotorSpec::Linear {
            no_load_rpm,
            rated_torque_n_m,
            rated_rpm,
        } => {
            number(ui, &tr!("drive.no_load_speed"), no_load_rpm, " rpm");
            number(ui, &tr!("drive.rated_torque"), rated_torque_n_m, " N·m");
            number(ui, &tr!("drive.rated_speed"), rated_rpm, " rpm");
        }
        MotorSpec::Table { points } => table(ui, points),
    }
}

/// The table's rows, in rising speed; a row can be added after the last or removed.
fn table(ui: &mut egui::Ui, points: &mut Vec<(f64, f64)>) {
    let mut remove = None;
    egui::Grid::new("motor table")
        .num_columns(3)
        .show(ui, |ui| {
            let speed = ui.strong(tr!("drive.speed"));
            let torque_head = ui.strong(tr!("drive.torque"));
            ui.end_row();
            for (i, (rpm, torque)) in points.iter_mut().enumerate() {
                ui.add(egui::DragValue::new(rpm).speed(1.0).suffix(" rpm"))
                    .labelled_by(speed.id);
                ui.add(egui::DragValue::new(torque).speed(0.5).suffix(" N·m"))
                    .labelled_by(torque_head.id);
                if ui.small_button(tr!("draw.remove")).clicked() {
                    remove = Some(i);
                }
                ui.end_row();
            }
        });
    if let Some(i) = remove.filter(|_| points.len() > 1) {
        points.remove(i);
    }
    if ui.button(tr!("drive.add_row")).clicked() {
        let last = points.last().copied().unwrap_or((0.0, 0.0));
        points.push((last.0 + 100.0, last.1));
    }
}

fn gear_and_flywheel(ui: &mut egui::Ui, d: &mut DriveSpec) {
    match &d.train {
        // The train sets the ratio: shown, not edited here (it is edited in its file).
        Some(spec) => train_line(ui, spec),
        None => number(ui, &tr!("drive.gear_ratio"), &mut d.gear_ratio, ""),
    }
    number(
        ui,
        &tr!("drive.rotor_inertia"),
        &mut d.motor_inertia_kg_m2,
        " kg·m²",
    );
    number(ui, &tr!("drive.flywheel"), &mut d.flywheel_kg_m2, " kg·m²");
    ui.horizontal(|ui| {
        ui.label(tr!("drive.flywheel_on"));
        ui.radio_value(&mut d.flywheel_on, Shaft::Crank, tr!("drive.on_crank"));
        ui.radio_value(&mut d.flywheel_on, Shaft::Motor, tr!("drive.on_motor"));
    });
}

/// The drive's train: its name, its ratio and its inertia at the crank, or why it
/// cannot drive the crank.
fn train_line(ui: &mut egui::Ui, spec: &DriveTrainSpec) {
    match DriveTrain::from_spec(spec) {
        Ok(t) => ui.label(tr!(
            "drive.train",
            name = t.name,
            ratio = significant(t.ratio.abs(), 4),
            inertia = significant(t.inertia_at_crank_kg_m2, 4)
        )),
        Err(p) => ui.colored_label(
            ui.visuals().error_fg_color,
            linkage_diagram::refusal::scene(super::words::lang(), &SceneProblem::DriveTrain(p)),
        ),
    };
}
