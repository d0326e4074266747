//! The machine's tabs of the plot pane: the real speed through the cycle with the
//! scene's drive (ω against φ and against t, the nominal speed marked, and the run-up
//! from rest to it), and the
//! shaking force on the frame before and after the crank's counterweight (its polar
//! diagram, as the textbooks draw it, and its size against the crank angle).

use eframe::egui;
use egui_plot::{HLine, Line, PlotPoints, Points, VLine};
use linkage::machine::{Shaking, SteadyState};
use linkage_diagram::numbers::{Prefix, si, significant};

use crate::i18n::tr;
use crate::session::curves::ShakingCurves;
use crate::ui::plot_axes::{self, Axis, AxisTitle, Unit};

/// The steady state's figures, then ω–φ and ω–t side by side.
pub fn steady_plots(
    ui: &mut egui::Ui,
    key: (&str, u64),
    st: &SteadyState,
    run_up: Option<&[[f64; 2]]>,
    nominal_rad_s: f64,
    cursor_deg: f64,
) {
    let n = |v: f64| significant(v, 4);
    ui.label(tr!(
        "plot.steady_figures",
        max = n(st.max_rad_s),
        min = n(st.min_rad_s),
        mean = n(st.mean_rad_s),
        nominal = n(nominal_rad_s),
        delta = n(st.delta),
        period = n(st.period_s)
    ));
    let by_angle: Vec<[f64; 2]> = st
        .cycle
        .iter()
        .map(|p| [p.angle_rad.to_degrees(), p.speed_rad_s])
        .collect();
    let by_time: Vec<[f64; 2]> = st.cycle.iter().map(|p| [p.t_s, p.speed_rad_s]).collect();
    let from_rest: Vec<[f64; 2]> = run_up.map(<[_]>::to_vec).unwrap_or_default();
    let plots = if from_rest.is_empty() { 2 } else { 3 };
    crate::ui::plot_layout::side_by_side(ui, plots, |ui, which, height| {
        let (x_label, name, data) = match which {
            0 => (
                AxisTitle::degrees(tr!("plot.crank_axis")),
                tr!("plot.steady_line"),
                &by_angle,
            ),
            1 => (AxisTitle::plain("t (s)"), tr!("plot.steady_line"), &by_time),
            _ => (
                AxisTitle::plain(tr!("plot.from_rest_axis")),
                tr!("plot.run_up_line"),
                &from_rest,
            ),
        };
        let y_label = AxisTitle::plain("ω (rad/s)");
        plot_axes::plot((key, "steady", which), height, &x_label, &y_label).show(ui, |p| {
            p.line(Line::new(name, PlotPoints::from(data.clone())));
            p.hline(HLine::new(tr!("plot.nominal"), nominal_rad_s));
            if which == 0 {
                p.vline(VLine::new(tr!("plot.now"), cursor_deg));
            }
        });
    });
}

/// The counterweight and the peak and rms before and after, then the polar diagram
/// and |F| against the crank angle.
pub fn shaking_plots(ui: &mut egui::Ui, key: (&str, u64), sc: &ShakingCurves, cursor_deg: f64) {
    let c = &sc.counterweight;
    ui.label(tr!(
        "plot.counterweight_figures",
        mr = significant(c.mass_radius_kg_m, 4),
        angle = significant(c.angle_rad.to_degrees(), 4),
        peak_without = si(sc.before.peak_force_n, "N"),
        peak_with = si(sc.after.peak_force_n, "N"),
        rms_without = si(sc.before.rms_force_n, "N"),
        rms_with = si(sc.after.rms_force_n, "N")
    ));
    // Both diagrams in the prefix of the larger force, the same on both axes.
    let prefix = Prefix::for_magnitude(sc.before.peak_force_n.max(sc.after.peak_force_n));
    let k = prefix.factor;
    let polar = |s: &Shaking| -> Vec<[f64; 2]> {
        let mut pts: Vec<[f64; 2]> = s
            .cycle
            .iter()
            .map(|p| [p.force_n[0] * k, p.force_n[1] * k])
            .collect();
        pts.extend(pts.first().copied());
        pts
    };
    let size = |s: &Shaking| -> Vec<[f64; 2]> {
        s.cycle
            .iter()
            .map(|p| {
                [
                    p.angle_rad.to_degrees(),
                    k * p.force_n[0].hypot(p.force_n[1]),
                ]
            })
            .collect()
    };
    let now = nearest(&sc.before, cursor_deg).map(|[x, y]| [x * k, y * k]);
    let force = |name: &str| plot_axes::title(Axis::new(name, Unit::Si("N")), prefix);
    crate::ui::plot_layout::side_by_side(ui, 2, |ui, which, height| {
        if which == 0 {
            plot_axes::plot(
                (key, "shaking", which),
                height,
                &force("F_x"),
                &force("F_y"),
            )
            .data_aspect(1.0)
            .show(ui, |p| {
                p.line(Line::new(
                    tr!("plot.without"),
                    PlotPoints::from(polar(&sc.before)),
                ));
                p.line(Line::new(
                    tr!("plot.with_counterweight"),
                    PlotPoints::from(polar(&sc.after)),
                ));
                if let Some(f) = now {
                    p.points(Points::new(tr!("plot.now"), PlotPoints::from(vec![f])).radius(4.0));
                }
            });
        } else {
            let key = (key, "shaking", which);
            let x_title = AxisTitle::degrees(tr!("plot.crank_axis"));
            plot_axes::plot(key, height, &x_title, &force("|F|")).show(ui, |p| {
                p.line(Line::new(
                    tr!("plot.without"),
                    PlotPoints::from(size(&sc.before)),
                ));
                p.line(Line::new(
                    tr!("plot.with_counterweight"),
                    PlotPoints::from(size(&sc.after)),
                ));
                p.vline(VLine::new(tr!("plot.now"), cursor_deg));
            });
        }
    });
}

/// The force of the cycle's position nearest `deg` (on a full turn).
fn nearest(s: &Shaking, deg: f64) -> Option<[f64; 2]> {
    let gap = |a: f64| {
        let d = (a.to_degrees() - deg).rem_euclid(360.0);
        d.min(360.0 - d)
    };
    s.cycle
        .iter()
        .min_by(|a, b| gap(a.angle_rad).total_cmp(&gap(b.angle_rad)))
        .map(|p| p.force_n)
}
