//! A cam exercise's cam drawn in the middle: the base circle, the pitch curve and
//! the profile of the student's cam, fitted to the space, with egui's painter (the
//! mechanism view's GPU pass draws mechanisms; a cam alone is a few hundred line
//! segments).

use eframe::egui;
use linkage::cam::FollowerOutline;
use linkage_model::exercise::SubjectData;

use crate::state::AppState;

/// The follower's colour: the mechanism view's links' blue.
const FOLLOWER: egui::Color32 = egui::Color32::from_rgb(0x44, 0x78, 0xb8);

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
    let follower = &cam.follower;
    let reach = pitch
        .iter()
        .copied()
        .chain(follower.extent_m())
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
    let paper = ui.visuals().extreme_bg_color;
    draw_follower(&painter, follower, &to_screen, scale as f32, [ink, paper]);
    true
}

/// The follower where it stands at the start (the solver's outline, so that it
/// touches the profile drawn): the stem in its guide or the arm on its pivot, and the
/// roller, knife edge or flat face.
fn draw_follower(
    painter: &egui::Painter,
    o: &FollowerOutline,
    to_screen: &dyn Fn(&[f64; 2]) -> egui::Pos2,
    scale: f32,
    [ink, paper]: [egui::Color32; 2],
) {
    let stem = egui::Stroke::new(3.0, FOLLOWER);
    painter.line_segment([to_screen(&o.stem_m[0]), to_screen(&o.stem_m[1])], stem);
    if let Some([a, b]) = &o.guide_m {
        // The guide's two walls beside the stem, as the textbooks draw a sliding pair.
        for side in [-6.0, 6.0] {
            let wall = [to_screen(a), to_screen(b)].map(|p| p + egui::vec2(side, 0.0));
            painter.line_segment(wall, egui::Stroke::new(1.0, ink));
        }
    }
    if let Some([a, b]) = &o.flat_face_m {
        painter.line_segment([to_screen(a), to_screen(b)], stem);
    }
    let tip = to_screen(&o.tip_m);
    match o.roller_radius_m {
        Some(r) => {
            let r = (r as f32 * scale).max(2.0);
            painter.circle(tip, r, paper, stem);
        }
        None => {
            painter.circle_filled(tip, 2.5, FOLLOWER);
        }
    }
    if let Some(pivot) = &o.pivot_m {
        let frame = egui::Stroke::new(1.5, ink);
        painter.circle(to_screen(pivot), 4.0, paper, frame);
    }
}
