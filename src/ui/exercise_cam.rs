//! A cam exercise's cam drawn in the middle: the base circle, the pitch curve and
//! the profile of the student's cam, fitted to the space, with egui's painter (the
//! mechanism view's GPU pass draws mechanisms; a cam alone is a few hundred line
//! segments).

use eframe::egui;
use linkage_model::exercise::SubjectData;

use crate::state::AppState;

/// Draws the open exercise's cam; `false` where the exercise's subject is a
/// mechanism (or no variant is drawn yet), which the mechanism view shows.
pub fn show(ui: &mut egui::Ui, st: &AppState) -> bool {
    let Some(desk) = st.exercise.as_ref().filter(|d| d.variant.is_some()) else {
        return false;
    };
    let Some(cam) = &desk.cam else {
        // A mechanism's variant (the view draws it), or a cam the solver refused.
        return !matches!(
            desk.variant.as_ref().map(|v| &v.subject),
            Some(SubjectData::Scene(_))
        );
    };
    // The curves closed: the turn's last point joins the first.
    let closed = cam.points.iter().chain(cam.points.first());
    let (pitch, profile): (Vec<[f64; 2]>, Vec<[f64; 2]>) =
        closed.map(|p| (p.pitch_m, p.profile_m)).unzip();
    let reach = pitch
        .iter()
        .map(|p| p[0].hypot(p[1]))
        .fold(0.0, f64::max)
        .max(1e-9);
    let rect = ui.available_rect_before_wrap();
    let scale = 0.45 * rect.width().min(rect.height()) as f64 / reach;
    let centre = rect.center();
    let to_screen =
        |p: &[f64; 2]| centre + egui::vec2((p[0] * scale) as f32, (-p[1] * scale) as f32);
    let painter = ui.painter_at(rect);
    let ink = ui.visuals().text_color();
    let base = cam.base_radius_m * scale;
    painter.circle_stroke(
        centre,
        base as f32,
        egui::Stroke::new(1.0, ink.gamma_multiply(0.4)),
    );
    painter.add(egui::Shape::line(
        pitch.iter().map(to_screen).collect(),
        egui::Stroke::new(1.0, ink.gamma_multiply(0.5)),
    ));
    painter.add(egui::Shape::line(
        profile.iter().map(to_screen).collect(),
        egui::Stroke::new(2.0, ink),
    ));
    painter.circle_filled(centre, 3.0, ink);
    true
}
