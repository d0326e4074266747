//! The flywheel tab of the plot pane: the energy method on the scene's cycle. The
//! torque the load asks for at the nominal speed beside its mean (what a motor gives),
//! the work surplus W(φ) of that mean with its largest and smallest values marked, and
//! the figures: mean torque and power, ΔW_max and the flywheel J_F = ΔW_max/(ω² δ);
//! and Wittenbauer's energy–inertia diagram (the surplus against the reduced inertia).

use eframe::egui;
use egui_plot::{HLine, Line, PlotPoints, Points, VLine};
use linkage::machine::FlywheelSizing;
use linkage_diagram::numbers::{si, significant};

use crate::i18n::tr;
use crate::session::curves::FLYWHEEL_DELTA;
use crate::ui::plot_axes::{self, Axis, AxisTitle, Unit};

/// The figures in one line, then the two plots side by side (stacked when narrow).
pub fn flywheel_plots(
    ui: &mut egui::Ui,
    key: (&str, u64),
    sized: &FlywheelSizing,
    cursor_deg: f64,
) {
    ui.label(figures(sized));
    let torque: Vec<[f64; 2]> = sized
        .cycle
        .iter()
        .map(|c| [c.angle_rad.to_degrees(), c.torque_n_m])
        .collect();
    let surplus: Vec<[f64; 2]> = sized
        .cycle
        .iter()
        .map(|c| [c.angle_rad.to_degrees(), c.surplus_j])
        .collect();
    // Wittenbauer's energy–inertia diagram: the surplus against the reduced inertia,
    // a closed curve over the cycle.
    let mut wittenbauer: Vec<[f64; 2]> = sized
        .cycle
        .iter()
        .map(|c| [c.reduced_inertia_kg_m2, c.surplus_j])
        .collect();
    wittenbauer.extend(wittenbauer.first().copied());
    let extremes = [
        [sized.angle_of_max_rad.to_degrees(), sized.surplus_max_j],
        [sized.angle_of_min_rad.to_degrees(), sized.surplus_min_j],
    ];
    let torque = plot_axes::series(Axis::new("T", Unit::Si("N·m")), &torque);
    let surplus = plot_axes::series(Axis::new("W", Unit::Si("J")), &surplus);
    let wittenbauer = plot_axes::series(Axis::new("W", Unit::Si("J")), &wittenbauer);
    let extremes: Vec<[f64; 2]> = extremes
        .iter()
        .map(|&[x, y]| [x, y * surplus.factor])
        .collect();
    let mean = sized.mean_torque_n_m * torque.factor;
    let crank_title = AxisTitle::degrees(tr!("plot.crank_axis"));
    let inertia_title = AxisTitle::plain(tr!("plot.reduced_inertia_axis"));
    crate::ui::plot_layout::side_by_side(ui, 3, |ui, which, height| {
        let key = (key, "flywheel", which);
        match which {
            0 => plot_axes::plot(key, height, &crank_title, &torque.title).show(ui, |p| {
                p.line(Line::new(
                    tr!("plot.load_torque"),
                    PlotPoints::from(torque.points.clone()),
                ));
                p.hline(HLine::new(tr!("plot.motor_mean"), mean));
                p.vline(VLine::new(tr!("plot.now"), cursor_deg));
            }),
            1 => plot_axes::plot(key, height, &crank_title, &surplus.title).show(ui, |p| {
                p.line(Line::new("W", PlotPoints::from(surplus.points.clone())));
                p.points(
                    Points::new(tr!("plot.extremes"), PlotPoints::from(extremes.clone()))
                        .radius(4.0),
                );
                p.vline(VLine::new(tr!("plot.now"), cursor_deg));
            }),
            _ => plot_axes::plot(key, height, &inertia_title, &wittenbauer.title).show(ui, |p| {
                p.line(Line::new(
                    tr!("plot.wittenbauer"),
                    PlotPoints::from(wittenbauer.points.clone()),
                ));
            }),
        };
    });
}

/// The energy method's figures, in two short lines; with a drive, a third: the
/// rotor's and train's inertia at the crank and the flywheel still to fit.
fn figures(s: &FlywheelSizing) -> String {
    let lines = tr!(
        "plot.flywheel_figures",
        torque = si(s.mean_torque_n_m, "N·m"),
        power = si(s.mean_power_w, "W"),
        work = si(s.work_range_j, "J"),
        delta = FLYWHEEL_DELTA,
        flywheel = significant(s.flywheel_kg_m2, 4),
        max = significant(s.reduced_inertia_kg_m2.max, 4),
        mean = significant(s.reduced_inertia_kg_m2.mean, 4)
    );
    match s.flywheel_to_add_on_motor_kg_m2 {
        Some(on_motor) if s.drive_inertia_kg_m2 > 0.0 => {
            let drive = tr!(
                "plot.flywheel_beside_drive",
                drive = significant(s.drive_inertia_kg_m2, 4),
                crank = significant(s.flywheel_to_add_kg_m2, 4),
                motor = significant(on_motor, 4)
            );
            format!("{lines}\n{drive}")
        }
        _ => lines,
    }
}
