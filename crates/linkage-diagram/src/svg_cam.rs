//! A cam's profile as an SVG sheet for the workshop: the profile drawn full size in
//! millimetres on an A4 page (scaled to fit where it is larger), the pitch curve
//! dashed, the base circle, the centre, a scale bar, and the places where the
//! pressure angle passes its limit or the profile is undercut marked in red, with
//! the largest pressure angle and the least radius of curvature written under it.

use std::f64::consts::TAU;
use std::fmt::Write as _;

use linkage::cam::{CamPoint, FollowerOutline};

use crate::geometry::{Pt, Rect};
use crate::layout::ScaleBar;
use crate::numbers::{degrees, si};
use crate::pages::{Pages, Sheet};
use crate::svg_draw::{
    MARGIN, PAGE_W, circle, fit_text, line, polygon_shape, scale_bar, text_at, titled_pane,
};
use crate::svg_follower::follower;
use crate::words::{Lang, sw};

const PROFILE: &str = "#222222";
const PITCH: &str = "#2f5f9e";
const PAST_LIMIT: &str = "#c0392b";
const BASE_CIRCLE: &str = "#8c8c8c";

/// A cam to draw: its points over the turn (in its own frame, m) and its limits.
pub struct CamSheet<'a> {
    /// The sheet's title.
    pub title: &'a str,
    /// The cam over its turn.
    pub points: &'a [CamPoint],
    /// The base circle's radius, m.
    pub base_radius_m: f64,
    /// The largest pressure angle allowed, rad.
    pub pressure_limit_rad: f64,
}

/// A cam as a task sheet draws it: at the start of its turn, with its follower.
#[derive(Clone, Copy)]
pub struct CamFigure<'a> {
    /// Its points over the turn.
    pub points: &'a [CamPoint],
    /// Its base circle's radius, m.
    pub base_radius_m: f64,
    /// Its follower at the start.
    pub follower: &'a FollowerOutline,
}

/// The sheet in `lang`: one A4 page.
pub fn cam_sheet(c: &CamSheet<'_>, lang: Lang) -> Sheet {
    let side = PAGE_W - 2.0 * MARGIN;
    let mut pages = Pages::new(c.title);
    let top = pages.place(side + 40.0);
    let body = pages.out();
    let pane = Rect::from_min_size([MARGIN, top], side, side + 40.0);
    let title = fit_text(&sw!(lang, "cam.title", title = c.title), side - 12.0, 14.0);
    let inner = titled_pane(body, &pane, &title, 14.0);
    let reach = c
        .points
        .iter()
        .flat_map(|p| [p.profile_m, p.pitch_m])
        .map(|[x, y]| x.hypot(y))
        .fold(c.base_radius_m, f64::max);
    // Full size (96 px per inch) unless the cam is larger than the pane.
    let full: f64 = 96.0 / 25.4 * 1e3;
    let scale = full.min(0.45 * inner.width().min(inner.height() - 40.0) / reach.max(1e-12));
    let centre: Pt = [
        0.5 * (inner.min[0] + inner.max[0]),
        inner.min[1] + 0.5 * (inner.height() - 40.0),
    ];
    let px = |[x, y]: [f64; 2]| -> Pt { [centre[0] + x * scale, centre[1] - y * scale] };
    draw_cam(body, c, &px, scale, centre);
    // A round length near half the cam's radius (round_scale takes a quarter).
    let bar_mm = crate::layout::round_scale(2.0 * reach * 1e3);
    let from = [inner.min[0] + 12.0, inner.max[1] - 50.0];
    let bar = ScaleBar {
        value: bar_mm * 1e-3,
        from,
        to: [from[0] + bar_mm * 1e-3 * scale, from[1]],
    };
    scale_bar(body, &bar, "m");
    figures(body, c, [inner.min[0] + 12.0, inner.max[1] - 24.0], lang);
    pages.finish()
}

/// A cam drawn in `pane` (of a task sheet) with its follower at the start: the
/// profile, the pitch curve dashed, the base circle and the centre, scaled to fit,
/// with no mark of where the pressure angle passes a limit (that is what the student
/// works out).
pub(crate) fn cam_in_pane(out: &mut String, cam: &CamFigure<'_>, pane: &Rect) {
    let reach = cam
        .points
        .iter()
        .flat_map(|p| [p.profile_m, p.pitch_m])
        .chain(cam.follower.extent_m())
        .map(|[x, y]| x.hypot(y))
        .fold(cam.base_radius_m, f64::max);
    let scale = 0.45 * pane.width().min(pane.height()) / reach.max(1e-12);
    let centre: Pt = [
        0.5 * (pane.min[0] + pane.max[0]),
        0.5 * (pane.min[1] + pane.max[1]),
    ];
    let px = |[x, y]: [f64; 2]| -> Pt { [centre[0] + x * scale, centre[1] - y * scale] };
    let sheet = CamSheet {
        title: "",
        points: cam.points,
        base_radius_m: cam.base_radius_m,
        pressure_limit_rad: f64::INFINITY,
    };
    draw_cam(out, &sheet, &px, scale, centre);
    follower(out, cam.follower, &px, scale);
}

/// The pitch curve dashed, the profile, the base circle, the centre, the marks.
fn draw_cam(out: &mut String, c: &CamSheet<'_>, px: &dyn Fn([f64; 2]) -> Pt, scale: f64, at: Pt) {
    let n = 180;
    let base: Vec<Pt> = (0..n)
        .map(|i| TAU * f64::from(i) / f64::from(n))
        .map(|t| px([c.base_radius_m * t.cos(), c.base_radius_m * t.sin()]))
        .collect();
    // One path, so that its dashes run on round the curve.
    let pitch: Vec<String> = c
        .points
        .iter()
        .map(|p| px(p.pitch_m))
        .map(|[x, y]| format!("{x:.2},{y:.2}"))
        .collect();
    let _ = writeln!(
        out,
        "<polygon points=\"{}\" fill=\"none\" stroke=\"{PITCH}\" stroke-width=\"0.8\" stroke-dasharray=\"5 3\"/>",
        pitch.join(" ")
    );
    let profile: Vec<Pt> = c.points.iter().map(|p| px(p.profile_m)).collect();
    polygon_shape(out, &profile, "#efe6cf", PROFILE);
    // Over the profile's fill, which would hide it: the base circle lies inside.
    polygon_shape(out, &base, "none", BASE_CIRCLE);
    for p in c
        .points
        .iter()
        .filter(|p| p.past_limit(c.pressure_limit_rad))
    {
        circle(out, px(p.profile_m), 2.2, PAST_LIMIT, "none");
    }
    let arm = 6.0_f64.max(0.05 * c.base_radius_m * scale);
    line(
        out,
        [at[0] - arm, at[1]],
        [at[0] + arm, at[1]],
        PROFILE,
        0.8,
        false,
    );
    line(
        out,
        [at[0], at[1] - arm],
        [at[0], at[1] + arm],
        PROFILE,
        0.8,
        false,
    );
}

/// The largest pressure angle and the least radii, and the legend.
fn figures(out: &mut String, c: &CamSheet<'_>, at: Pt, lang: Lang) {
    let largest = c
        .points
        .iter()
        .map(|p| p.pressure_angle_rad.abs())
        .fold(0.0, f64::max);
    let least = |f: fn(&CamPoint) -> f64| c.points.iter().map(f).fold(f64::INFINITY, f64::min);
    let text = sw!(
        lang,
        "cam.figures",
        base = si(c.base_radius_m, "m"),
        pressure = degrees(largest.to_degrees()),
        limit = degrees(c.pressure_limit_rad.to_degrees()),
        pitch = si(least(|p| p.pitch_radius_m), "m"),
        profile = si(least(|p| p.profile_radius_m), "m"),
    );
    text_at(out, at, &text, 10.0, "normal");
    let legend = sw!(lang, "cam.legend");
    text_at(out, [at[0], at[1] + 14.0], &legend, 10.0, "normal");
}
