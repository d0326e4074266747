//! The timing tab: every output of the machine against the main shaft's angle, one
//! lane each (its share of its stroke, lowest at the lane's foot), dwells shaded, with
//! a cursor at the current position: how the cams and the linkages on one shaft are
//! laid out against each other.

use eframe::egui;
use egui_plot::{Line, PlotPoint, PlotPoints, Polygon, Text, VLine};
use linkage::analysis::TimingLane;
use linkage::scene::LengthUnit;
use linkage_model::session::words::length;

use crate::i18n::tr;
use crate::session::Session;
use crate::ui::plot_axes::AxisTitle;

/// A lane's height on the plot's axis, of which its curve takes 1.
const LANE: f64 = 1.4;

/// The timing tab's plot, `height` high, with the cursor at `cursor_deg`.
pub fn timing_plot(ui: &mut egui::Ui, s: &Session, cursor_deg: f64, height: f32) {
    let d = &s.curves().timing;
    let shaft_deg: Vec<f64> = d.shaft_rad.iter().map(|x| x.to_degrees()).collect();
    let (Some(&x0), n) = (shaft_deg.first(), d.lanes.len()) else {
        return;
    };
    let key = ("timing", s.scene().name.as_str(), s.generation());
    let x_title = AxisTitle::degrees(tr!("plot.shaft_axis"));
    crate::ui::plot_axes::plot(key, height, &x_title, &AxisTitle::plain(""))
        .show_axes([true, false])
        .show_grid([true, false])
        .include_y(-0.2)
        .include_y(LANE * n as f64)
        .show(ui, |p| {
            for (i, lane) in d.lanes.iter().enumerate() {
                let foot = LANE * (n - 1 - i) as f64;
                for [a, b] in &lane.dwells {
                    let (a, b) = (a.to_degrees(), b.to_degrees());
                    let corners = vec![[a, foot], [b, foot], [b, foot + 1.0], [a, foot + 1.0]];
                    p.polygon(
                        Polygon::new(
                            tr!("plot.dwell", lane = lane.name),
                            PlotPoints::from(corners),
                        )
                        .fill_color(egui::Color32::from_rgba_unmultiplied(230, 190, 90, 70))
                        .stroke(egui::Stroke::NONE),
                    );
                }
                let points: PlotPoints<'_> = shaft_deg
                    .iter()
                    .zip(&lane.share)
                    .map(|(&x, &y)| [x, foot + y])
                    .collect();
                p.line(Line::new(lane.name.clone(), points));
                let label = format!(
                    "{} ({})",
                    lane.name,
                    stroke_text(lane, s.scene().length_unit)
                );
                p.text(
                    Text::new(label.clone(), PlotPoint::new(x0, foot + 1.2), label)
                        .anchor(egui::Align2::LEFT_CENTER),
                );
            }
            if cursor_deg.is_finite() {
                p.vline(VLine::new(tr!("plot.now"), cursor_deg));
            }
        });
}

/// The lane's swing in degrees or stroke in the scene's length unit.
fn stroke_text(lane: &TimingLane, unit: LengthUnit) -> String {
    let [lo, hi] = lane.range;
    if lane.is_angle {
        tr!(
            "plot.swing",
            angle = format!("{:.2}°", (hi - lo).to_degrees())
        )
    } else {
        tr!("plot.stroke", length = length(hi - lo, unit))
    }
}
