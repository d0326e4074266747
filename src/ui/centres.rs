//! Instant centres on the mechanism view: every pair of links' centre (Kennedy's
//! theorem, `linkage::instant_centres`) as a dot with its typeset name I₁₃, those at
//! infinity listed with their direction, and the circle diagram in a corner — links
//! round a circle, a line for each centre found, solid for a joint's own centre,
//! dashed for one found by Kennedy's theorem — as the textbooks construct them.

use eframe::egui::{self, Align2, Color32, FontId, Pos2, Rect, Stroke, Vec2};
use linkage::Mechanism;
use linkage::instant_centres::{Centre, FoundBy, InstantCentres, instant_centres};
use linkage_diagram::pose_figure::{centre_label, link_number};

use crate::i18n::tr;
use crate::render::view::Camera;
use crate::state::AppState;
use crate::ui::typeset::galley;

const CENTRE_COLOUR: Color32 = Color32::from_rgb(176, 48, 106);

/// Draws the centres over the view in `rect`.
pub fn overlay(painter: &egui::Painter, rect: Rect, st: &AppState, camera: &Camera) {
    let m = st.session.mechanism();
    let pose = st.session.pose();
    let found = instant_centres(m, pose);
    let mut off = Vec::new();
    for c in &found.centres {
        let label = centre_label(link_number(m, c.links[0]), link_number(m, c.links[1]));
        match c.centre {
            Centre::At(p) if p[0].is_finite() && p[1].is_finite() => {
                let at = camera.to_screen(p, rect);
                if rect.contains(at) {
                    painter.circle_filled(at, 3.5, CENTRE_COLOUR);
                    let g = galley(painter, &label, 13.0, CENTRE_COLOUR);
                    painter.galley(at + Vec2::new(5.0, 2.0), g, CENTRE_COLOUR);
                } else {
                    off.push(tr!("centres.off_view", label = label.text()));
                }
            }
            Centre::At(_) => {}
            Centre::AtInfinity(d) => off.push(tr!(
                "centres.at_infinity",
                label = label.text(),
                deg = format!("{:.1}", d[1].atan2(d[0]).to_degrees())
            )),
        }
    }
    if !off.is_empty() {
        painter.text(
            rect.right_top() + Vec2::new(-8.0, 8.0),
            Align2::RIGHT_TOP,
            off.join("\n"),
            FontId::proportional(12.0),
            CENTRE_COLOUR,
        );
    }
    circle_diagram(painter, rect, m, &found);
}

/// The circle diagram, bottom right: link numbers round a circle, a line per centre.
fn circle_diagram(painter: &egui::Painter, rect: Rect, m: &Mechanism, found: &InstantCentres) {
    let n = m.links.len();
    if n < 2 {
        return;
    }
    let radius = 48.0;
    let centre = rect.right_bottom() + Vec2::new(-radius - 30.0, -radius - 40.0);
    let at = |number: usize| {
        let a =
            std::f32::consts::TAU * (number - 1) as f32 / n as f32 - std::f32::consts::FRAC_PI_2;
        centre + Vec2::new(a.cos(), a.sin()) * radius
    };
    painter.circle_stroke(centre, radius, Stroke::new(0.8, Color32::from_gray(170)));
    for c in &found.centres {
        let (a, b) = (
            at(link_number(m, c.links[0])),
            at(link_number(m, c.links[1])),
        );
        let stroke = Stroke::new(1.3, CENTRE_COLOUR);
        match c.found_by {
            FoundBy::Pin(_) | FoundBy::Slide(_) => {
                painter.line_segment([a, b], stroke);
            }
            FoundBy::Kennedy(_) | FoundBy::Velocities | FoundBy::CamContact(_) => {
                painter.extend(egui::Shape::dashed_line(&[a, b], stroke, 4.0, 3.0));
            }
        }
    }
    for k in 1..=n {
        let p: Pos2 = at(k);
        painter.circle_filled(p, 9.0, Color32::WHITE);
        painter.circle_stroke(p, 9.0, Stroke::new(1.0, Color32::from_gray(80)));
        painter.text(
            p,
            Align2::CENTER_CENTER,
            k.to_string(),
            FontId::proportional(12.0),
            Color32::from_gray(20),
        );
    }
    painter.text(
        rect.right_bottom() + Vec2::new(-8.0, -6.0),
        Align2::RIGHT_BOTTOM,
        "circle diagram (1 = frame): solid at a joint, dashed by Kennedy",
        FontId::proportional(11.0),
        Color32::from_gray(70),
    );
}
