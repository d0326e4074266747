//! The function and positions tabs' own inputs, and the figures beside a design's
//! table: a function generator's structural error over its range, and a motion
//! generator's construction (positions, poles, centre-point curves, Burmester
//! points, pivots).

use eframe::egui;
use egui_plot::{Legend, Line, Plot, PlotPoints, Points};

use crate::i18n::tr;
use crate::synthesis::function::{Desired, FunctionSpec};
use crate::synthesis::motion::Construction;
use crate::synthesis::{Figure, SynthInputs};
use crate::ui::synthesis::fields::{number, text_area};

/// The function tab: typed precision points, or a function and its ranges.
pub fn function_inputs(ui: &mut egui::Ui, view: &mut SynthInputs) {
    ui.horizontal(|ui| {
        if ui
            .radio(view.function_spec.is_none(), tr!("synth.typed_points"))
            .clicked()
        {
            view.function_spec = None;
        }
        if ui
            .radio(view.function_spec.is_some(), tr!("synth.a_function"))
            .clicked()
            && view.function_spec.is_none()
        {
            view.function_spec = Some(FunctionSpec::default());
        }
    });
    let Some(spec) = view.function_spec.as_mut() else {
        text_area(
            ui,
            &mut view.function_points,
            &tr!("synth.precision_points"),
        );
        return;
    };
    egui::ComboBox::from_label(tr!("synth.function"))
        .selected_text(spec.f.label())
        .show_ui(ui, |ui| {
            for f in Desired::ALL {
                ui.selectable_value(&mut spec.f, f, f.label());
            }
        });
    number(ui, &mut spec.x_range[0], &tr!("synth.x_from"), 0.01);
    number(ui, &mut spec.x_range[1], &tr!("synth.x_to"), 0.01);
    number(ui, &mut spec.input_deg[0], &tr!("synth.crank_start"), 0.5);
    number(ui, &mut spec.input_deg[1], &tr!("synth.crank_span"), 0.5);
    number(ui, &mut spec.output_deg[0], &tr!("synth.rocker_start"), 0.5);
    number(ui, &mut spec.output_deg[1], &tr!("synth.rocker_span"), 0.5);
    ui.horizontal(|ui| {
        let name = ui.label(tr!("synth.chebyshev"));
        ui.add(egui::DragValue::new(&mut spec.points).range(3..=10))
            .labelled_by(name.id);
    });
}

/// The positions tab: three to five positions and what fixes the four-bar.
pub fn motion_inputs(ui: &mut egui::Ui, view: &mut SynthInputs) {
    text_area(ui, &mut view.poses, &tr!("synth.positions"));
    let rows = view.poses.lines().filter(|l| !l.trim().is_empty()).count();
    let choice = &mut view.motion;
    let four = |ui: &mut egui::Ui, v: &mut [f64; 4], what: &str| {
        ui.label(what);
        ui.horizontal(|ui| {
            for (v, axis) in v.iter_mut().zip(["x1", "y1", "x2", "y2"]) {
                let name = ui.label(axis);
                ui.add(egui::DragValue::new(v).speed(1.0))
                    .labelled_by(name.id);
            }
        });
    };
    match rows {
        4 => four(ui, &mut choice.fixed_near_mm, &tr!("synth.fixed_near")),
        5 => {
            ui.horizontal(|ui| {
                let name = ui.label(tr!("synth.burmester"));
                ui.add(egui::DragValue::new(&mut choice.pair[0]).range(1..=4))
                    .labelled_by(name.id);
                ui.add(egui::DragValue::new(&mut choice.pair[1]).range(1..=4))
                    .labelled_by(name.id);
            });
        }
        _ => four(ui, &mut choice.moving_mm, &tr!("synth.moving_pivots")),
    }
}

/// The figure of a design, if it has one.
pub fn figure(ui: &mut egui::Ui, figure: &Figure) {
    match figure {
        Figure::None => {}
        Figure::ErrorCurve(curve) => {
            Plot::new("structural error")
                .height(160.0)
                .x_axis_label(tr!("synth.crank_angle_axis"))
                .y_axis_label(tr!("synth.structural_error"))
                // Hundredths of a degree: egui_plot's default spacing labels only
                // 0 here, so the marks are a round step of about a quarter of the span.
                .y_axis_min_width(44.0)
                .y_grid_spacer(egui_plot::uniform_grid_spacer(|input| {
                    let span = (input.bounds.1 - input.bounds.0).max(1e-12);
                    let step = 10f64.powf((span / 4.0).log10().floor());
                    [step, 5.0 * step, 10.0 * step]
                }))
                .y_axis_formatter(|mark, _| format!("{:.3}", mark.value))
                .show(ui, |p| {
                    p.line(Line::new(
                        tr!("synth.error"),
                        curve.iter().copied().collect::<PlotPoints<'_>>(),
                    ));
                });
        }
        Figure::Construction(c) => construction(ui, c),
    }
}

fn construction(ui: &mut egui::Ui, c: &Construction) {
    // Framed on the positions and the four-bar: far poles and Burmester points
    // would shrink them to a dot (zoom out to see those).
    let ([x0, y0], [x1, y1]) = frame(c);
    Plot::new("motion construction")
        .height(320.0)
        .data_aspect(1.0)
        .auto_bounds(false)
        .default_x_bounds(x0, x1)
        .default_y_bounds(y0, y1)
        .legend(Legend::default().position(egui_plot::Corner::LeftBottom))
        .show(ui, |p| {
            // The legend's words, in the app's language.
            let (curve, positions, poles) = (
                tr!("synth.curve"),
                tr!("synth.legend_positions"),
                tr!("synth.poles"),
            );
            let (burmester, four_bar, fixed) = (
                tr!("synth.burmester"),
                tr!("synth.four_bar"),
                tr!("synth.fixed"),
            );
            for seg in &c.curve {
                p.line(
                    Line::new(curve.as_str(), seg.to_vec())
                        .color(egui::Color32::from_rgb(120, 160, 220)),
                );
            }
            // Each position: its reference point and a tick along the body's x-axis.
            let tick = 0.04 * extent(c);
            for (at, angle) in &c.positions {
                let end = [at[0] + tick * angle.cos(), at[1] + tick * angle.sin()];
                p.line(
                    Line::new(positions.as_str(), vec![*at, end])
                        .color(egui::Color32::from_rgb(230, 160, 60))
                        .width(2.0),
                );
            }
            let at: Vec<[f64; 2]> = c.positions.iter().map(|(a, _)| *a).collect();
            p.points(
                Points::new(positions.as_str(), at)
                    .radius(4.0)
                    .color(egui::Color32::from_rgb(230, 160, 60)),
            );
            p.points(
                Points::new(poles.as_str(), c.poles.clone())
                    .radius(3.0)
                    .color(egui::Color32::GRAY),
            );
            if !c.burmester.is_empty() {
                p.points(
                    Points::new(burmester.as_str(), c.burmester.clone())
                        .radius(5.0)
                        .color(egui::Color32::from_rgb(200, 80, 200)),
                );
            }
            let [a0, b0] = c.fixed;
            let [a, b] = c.moving;
            p.line(
                Line::new(four_bar.as_str(), vec![a0, a, b, b0])
                    .color(egui::Color32::from_rgb(90, 200, 120))
                    .width(2.5),
            );
            p.points(
                Points::new(fixed.as_str(), vec![a0, b0])
                    .radius(5.0)
                    .color(egui::Color32::from_rgb(90, 200, 120)),
            );
        });
}

/// The box around the positions and pivots, with a fifth of its size around it.
fn frame(c: &Construction) -> ([f64; 2], [f64; 2]) {
    let points = c
        .positions
        .iter()
        .map(|(p, _)| *p)
        .chain(c.fixed)
        .chain(c.moving);
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let margin = 0.2 * (hi[0] - lo[0]).max(hi[1] - lo[1]).max(1.0);
    (
        [lo[0] - margin, lo[1] - margin],
        [hi[0] + margin, hi[1] + margin],
    )
}

/// The construction's size (the spread of its positions), at least 1 mm.
fn extent(c: &Construction) -> f64 {
    let first = c.positions.first().map_or([0.0; 2], |p| p.0);
    c.positions
        .iter()
        .map(|(p, _)| (p[0] - first[0]).hypot(p[1] - first[1]))
        .fold(1.0, f64::max)
}
