//! The cam tabs of the plot pane: the follower's lift, velocity, acceleration and
//! jerk against the cam's angle at the cam's speed; and the cam's limits, the
//! pressure angle with its allowed band and the profile's radius of curvature with
//! zero (below it, where the pitch curve is convex, the cam is undercut), each with
//! the places past the limit marked in red.

use eframe::egui;
use egui_plot::{HLine, Line, PlotPoints, Points, VLine};

use crate::i18n::tr;
use crate::session::Session;
use crate::session::cam_curves::CamCurves;
use crate::ui::plot_axes::{self, Axis, AxisTitle, Unit};

/// Red, for the places past a limit.
const PAST: egui::Color32 = egui::Color32::from_rgb(220, 70, 60);

/// Whether the scene has a cam joint to plot.
pub fn has_cams(s: &Session) -> bool {
    !s.curves().cams.is_empty()
}

/// The cam angle of the current pose, deg in [0, 360), for the cursor.
fn cursor_deg(s: &Session, cam: usize) -> Option<f64> {
    let joint = s.mechanism().cams.get(cam)?;
    Some(
        s.pose().links[joint.cam]
            .angle_rad()
            .to_degrees()
            .rem_euclid(360.0),
    )
}

/// s, v, a and jerk of the first cam joint's follower against the cam angle.
pub fn motion_plots(ui: &mut egui::Ui, s: &Session) {
    let Some(c) = s.curves().cams.first() else {
        return;
    };
    // An arm's swing in degrees; a translating follower's lift, velocity,
    // acceleration and jerk in the scene's length unit.
    let length = s.scene().length_unit;
    let (scale, units) = if c.is_arm {
        (
            [180.0 / std::f64::consts::PI; 4],
            [
                Unit::Degrees,
                Unit::Fixed("°/s"),
                Unit::Fixed("°/s²"),
                Unit::Fixed("°/s³"),
            ],
        )
    } else {
        let units = match length {
            linkage::scene::LengthUnit::Millimetre => ["mm", "mm/s", "mm/s²", "mm/s³"],
            linkage::scene::LengthUnit::Metre => ["m", "m/s", "m/s²", "m/s³"],
        };
        ([1.0 / length.to_metres(); 4], units.map(Unit::Fixed))
    };
    let names = [
        tr!("cam.lift_axis"),
        tr!("cam.velocity_axis"),
        tr!("cam.acceleration_axis"),
        tr!("cam.jerk_axis"),
    ];
    let w = c.speed_rad_s;
    let cursor = cursor_deg(s, 0);
    crate::ui::plot_layout::side_by_side(ui, names.len(), |ui, i, height| {
        // Each derivative by the cam angle times the cam's speed to that power.
        let data: Vec<[f64; 2]> = c
            .points
            .iter()
            .map(|p| {
                let m = &p.motion;
                let per_rad = [m.s, m.v, m.a, m.j][i];
                [
                    p.angle_rad.to_degrees(),
                    per_rad * w.powi(i as i32) * scale[i],
                ]
            })
            .collect();
        let axis = Axis::new(&names[i], units[i]);
        cam_plot(ui, (s, "cam motion", i), axis, &data, &[], cursor, height);
    });
}

/// The pressure angle within its band, and the profile's radius of curvature.
pub fn limit_plots(ui: &mut egui::Ui, s: &Session) {
    let Some(c) = s.curves().cams.first() else {
        return;
    };
    let cursor = cursor_deg(s, 0);
    let limit = c.pressure_limit_rad.to_degrees();
    let length = s.scene().length_unit;
    let pressure = series(c, |p| p.pressure_angle_rad.to_degrees());
    let radius = series(c, |p| p.profile_radius_m / length.to_metres());
    let pressure_name = tr!("cam.pressure_axis", limit = format!("{limit:.0}"));
    let pressure_axis = Axis::new(&pressure_name, Unit::Degrees);
    let radius_name = tr!("cam.radius_axis");
    let radius_axis = Axis::new(
        &radius_name,
        Unit::Fixed(crate::session::unit_label_of(length)),
    );
    crate::ui::plot_layout::side_by_side(ui, 2, |ui, i, height| {
        let (axis, data, limits) = if i == 0 {
            (pressure_axis, &pressure, vec![-limit, limit])
        } else {
            (radius_axis, &radius, vec![0.0])
        };
        cam_plot(
            ui,
            (s, "cam limits", i),
            axis,
            data,
            &limits,
            cursor,
            height,
        );
    });
    let past: Vec<[f64; 2]> = c
        .points
        .iter()
        .filter(|p| p.past_limit(c.pressure_limit_rad))
        .map(|p| [p.angle_rad.to_degrees(), p.pressure_angle_rad.to_degrees()])
        .collect();
    if !past.is_empty() {
        ui.colored_label(
            PAST,
            tr!("cam.past_count", past = past.len(), all = c.points.len()),
        );
    }
}

/// `f` of every point of the cam against its angle, deg.
fn series(c: &CamCurves, f: impl Fn(&linkage::cam::CamPoint) -> f64) -> Vec<[f64; 2]> {
    c.points
        .iter()
        .map(|p| [p.angle_rad.to_degrees(), f(p)])
        .collect()
}

/// One plot against the cam angle, with its limit lines and the points past them
/// (`limits` in the axis' unit, before its prefix).
fn cam_plot(
    ui: &mut egui::Ui,
    (s, id, i): (&Session, &str, usize),
    axis: Axis<'_>,
    data: &[[f64; 2]],
    limits: &[f64],
    cursor: Option<f64>,
    height: f32,
) {
    let series = plot_axes::series(axis, data);
    let limits: Vec<f64> = limits.iter().map(|l| l * series.factor).collect();
    let data = series.points.as_slice();
    let limits = limits.as_slice();
    let [lo, hi] = crate::ui::plot_layout::robust_range(data);
    let (lo, hi) = limits
        .iter()
        .fold((lo, hi), |(a, b), &l| (a.min(l), b.max(l)));
    let key = (id, i, s.scene().name.as_str(), s.generation());
    let x_title = AxisTitle::degrees(tr!("cam.angle_axis"));
    plot_axes::plot(key, height, &x_title, &series.title)
        .include_y(lo)
        .include_y(hi)
        .show(ui, |p| {
            p.line(Line::new(
                series.title.text.clone(),
                data.iter().copied().collect::<PlotPoints<'_>>(),
            ));
            for &l in limits {
                p.hline(HLine::new(tr!("cam.limit"), l).color(PAST));
            }
            let past = out_of(data, limits);
            if !past.is_empty() {
                p.points(
                    Points::new(tr!("cam.past_limit"), PlotPoints::from(past))
                        .color(PAST)
                        .radius(2.0),
                );
            }
            if let Some(x) = cursor {
                p.vline(VLine::new(tr!("plot.now"), x));
            }
        });
}

/// The points of `data` outside the band of `limits` (two: below the first or above
/// the second; one: below it).
fn out_of(data: &[[f64; 2]], limits: &[f64]) -> Vec<[f64; 2]> {
    data.iter()
        .copied()
        .filter(|&[_, y]| match limits {
            [lo, hi] => y < *lo || y > *hi,
            [lo] => y < *lo,
            _ => false,
        })
        .collect()
}
