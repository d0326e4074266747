//! The flywheel tab of the plot pane: the energy method on the scene's cycle. The
//! torque the load asks for at the nominal speed beside its mean (what a motor gives),
//! the work surplus W(φ) of that mean with its largest and smallest values marked, and
//! the figures: mean torque and power, ΔW_max and the flywheel J_F = ΔW_max/(ω² δ);
//! and Wittenbauer's energy–inertia diagram (the surplus against the reduced inertia).

use eframe::egui;
use egui_plot::{HLine, Line, Plot, PlotPoints, Points, VLine};
use linkage::machine::FlywheelSizing;

use crate::session::curves::FLYWHEEL_DELTA;

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
    let extremes = vec![
        [sized.angle_of_max_rad.to_degrees(), sized.surplus_max_j],
        [sized.angle_of_min_rad.to_degrees(), sized.surplus_min_j],
    ];
    crate::ui::plot_layout::side_by_side(ui, 3, |ui, which, height| {
        let plot = Plot::new((key, "flywheel", which))
            .height(height)
            .x_axis_label("crank angle (deg)")
            .allow_scroll(false);
        if which == 0 {
            plot.y_axis_label("T (N·m)").show(ui, |p| {
                p.line(Line::new(
                    "the load's torque",
                    PlotPoints::from(torque.clone()),
                ));
                p.hline(HLine::new("mean: the motor's", sized.mean_torque_n_m));
                p.vline(VLine::new("now", cursor_deg));
            });
        } else if which == 2 {
            let plot = Plot::new((key, "flywheel", which))
                .height(height)
                .x_axis_label("J_red (kg·m²)")
                .y_axis_label("W (J)")
                .allow_scroll(false);
            plot.show(ui, |p| {
                p.line(Line::new(
                    "energy–inertia (Wittenbauer)",
                    PlotPoints::from(wittenbauer.clone()),
                ));
            });
        } else {
            plot.y_axis_label("W (J)").show(ui, |p| {
                p.line(Line::new("W", PlotPoints::from(surplus.clone())));
                p.points(
                    Points::new("largest and smallest", PlotPoints::from(extremes.clone()))
                        .radius(4.0),
                );
                p.vline(VLine::new("now", cursor_deg));
            });
        }
    });
}

/// The energy method's figures, in two short lines.
fn figures(s: &FlywheelSizing) -> String {
    format!(
        "mean torque {:.4e} N·m · mean power {:.4e} W · ΔW_max {:.4e} J\n\
         flywheel for δ = {FLYWHEEL_DELTA}: J_F = {:.4e} kg·m² (the mechanism's own: up to {:.3e}, mean {:.3e} kg·m²)",
        s.mean_torque_n_m,
        s.mean_power_w,
        s.work_range_j,
        s.flywheel_kg_m2,
        s.reduced_inertia_kg_m2.max,
        s.reduced_inertia_kg_m2.mean,
    )
}
