//! Velocity and acceleration polygons drawn as the textbooks draw them: pole p (p'),
//! each joint's absolute vector to its lowercase point (b, c / b', c'), relative and
//! component vectors head to tail (normal and tangential dashed, Coriolis in red), a
//! scale bar, and beside them the vector-equation table.

use eframe::egui::{self, Color32, Pos2, Stroke, Vec2};
use linkage::polygon::{Component, Quantity, Symbol, Term, VectorEquation};

use crate::app::AppState;

/// How a polygon segment is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// Absolute vector from the pole.
    Absolute,
    /// Relative vector (`v_CB`).
    Relative,
    /// Normal component (`^n`).
    Normal,
    /// Tangential component (`^t`).
    Tangential,
    /// Coriolis component (`^k`).
    Coriolis,
    /// Sliding component (`^r`).
    Sliding,
}

/// One drawn vector, in the polygon's own units (m/s or m/s²).
#[derive(Clone, Debug, PartialEq)]
pub struct Segment {
    /// Tail.
    pub from: [f64; 2],
    /// Head.
    pub to: [f64; 2],
    /// Style.
    pub style: Style,
    /// Label (a point letter for absolute vectors, the symbol otherwise).
    pub label: String,
}

/// One polygon: its segments.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Diagram {
    /// Segments, absolute vectors first.
    pub segments: Vec<Segment>,
}

impl Diagram {
    /// Largest distance of any vertex from the pole (0 for a still mechanism).
    pub fn extent(&self) -> f64 {
        self.segments
            .iter()
            .flat_map(|s| [s.from, s.to])
            .map(|p| p[0].hypot(p[1]))
            .filter(|d| d.is_finite())
            .fold(0.0, f64::max)
    }
}

fn style_of(symbol: &Symbol) -> Style {
    match symbol.component {
        Component::Whole => Style::Relative,
        Component::Normal => Style::Normal,
        Component::Tangential => Style::Tangential,
        Component::Coriolis => Style::Coriolis,
        Component::Sliding => Style::Sliding,
    }
}

/// An absolute term (`v_B`, `a_C`: a joint's whole motion relative to the frame) is
/// drawn from the pole with the joints' vectors, not again in a chain.
fn is_absolute(symbol: &Symbol, joints: &[(String, [f64; 2])]) -> bool {
    symbol.relative_to.is_none()
        && symbol.component == Component::Whole
        && joints.iter().any(|(name, _)| *name == symbol.point)
}

/// The polygon of `kind` (`velocity` or `acceleration`) from the session's equations
/// and the absolute vectors of the joints.
pub fn diagram(
    equations: &[VectorEquation],
    kind: Quantity,
    absolute: &[(String, [f64; 2])],
) -> Diagram {
    let prime = if kind == Quantity::Acceleration {
        "'"
    } else {
        ""
    };
    let mut segments: Vec<Segment> = absolute
        .iter()
        .filter(|(_, v)| v[0].is_finite() && v[1].is_finite())
        .map(|(name, v)| Segment {
            from: [0.0, 0.0],
            to: *v,
            style: Style::Absolute,
            label: format!("{}{prime}", name.to_lowercase()),
        })
        .collect();
    for eq in equations.iter().filter(|e| e.kind == kind) {
        for side in [&eq.rhs, &eq.lhs] {
            chain(side, absolute, &mut segments);
        }
    }
    Diagram { segments }
}

/// Lays `terms` head to tail from the pole; absolute terms are already drawn.
fn chain(terms: &[Term], joints: &[(String, [f64; 2])], out: &mut Vec<Segment>) {
    let mut at = [0.0, 0.0];
    for t in terms {
        let next = [at[0] + t.vector[0], at[1] + t.vector[1]];
        if !(next[0].is_finite() && next[1].is_finite()) {
            return;
        }
        if !is_absolute(&t.symbol, joints) && t.magnitude > 0.0 {
            out.push(Segment {
                from: at,
                to: next,
                style: style_of(&t.symbol),
                label: t.symbol.to_string(),
            });
        }
        at = next;
    }
}

/// The polygon pane.
pub fn panel(ui: &mut egui::Ui, st: &AppState) {
    let s = &st.session;
    let pose = s.pose();
    let names = |f: &dyn Fn(usize) -> [f64; 2]| -> Vec<(String, [f64; 2])> {
        s.topology()
            .joint_points
            .iter()
            .map(|&p| (s.mechanism().points[p].name.clone(), f(p)))
            .collect()
    };
    let v_abs = names(&|p| {
        let v = pose.points[p].velocity;
        [v.x, v.y]
    });
    let a_abs = names(&|p| {
        let a = pose.points[p].acceleration;
        [a.x, a.y]
    });
    for (title, kind, abs, unit) in [
        ("Velocity polygon", Quantity::Velocity, v_abs, "m/s"),
        (
            "Acceleration polygon",
            Quantity::Acceleration,
            a_abs,
            "m/s²",
        ),
    ] {
        ui.strong(title);
        let d = diagram(s.polygons(), kind, &abs);
        draw(
            ui,
            &d,
            unit,
            if kind == Quantity::Acceleration {
                "p'"
            } else {
                "p"
            },
        );
        egui::CollapsingHeader::new(format!("{title}: vector equations"))
            .default_open(false)
            .show(ui, |ui| table(ui, s.polygons(), kind));
    }
}

fn colour(style: Style) -> Color32 {
    match style {
        Style::Absolute => Color32::from_rgb(30, 90, 170),
        Style::Relative => Color32::from_gray(70),
        Style::Normal => Color32::from_rgb(40, 140, 200),
        Style::Tangential => Color32::from_rgb(220, 130, 20),
        Style::Coriolis => Color32::from_rgb(210, 40, 40),
        Style::Sliding => Color32::from_rgb(40, 150, 70),
    }
}

/// A round scale-bar length near a quarter of `extent`: 1, 2 or 5 × 10^k.
pub fn scale_bar(extent: f64) -> f64 {
    if !(extent.is_finite() && extent > 0.0) {
        return 0.0;
    }
    let target = extent / 4.0;
    let decade = 10f64.powf(target.log10().floor());
    [5.0, 2.0, 1.0]
        .into_iter()
        .map(|m| m * decade)
        .find(|&v| v <= target)
        .unwrap_or(decade)
}

fn draw(ui: &mut egui::Ui, d: &Diagram, unit: &str, pole: &str) {
    let size = Vec2::new(ui.available_width().max(120.0), 220.0);
    let (rect, _) = ui.allocate_exact_size(size, egui::Sense::hover());
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 4.0, ui.visuals().extreme_bg_color);
    let extent = d.extent();
    if extent <= 0.0 {
        painter.text(
            rect.center(),
            egui::Align2::CENTER_CENTER,
            "at rest: the polygon is a point",
            egui::FontId::proportional(12.0),
            ui.visuals().text_color(),
        );
        return;
    }
    let scale = f64::from(rect.width().min(rect.height())) * 0.42 / extent;
    let origin = rect.center();
    let to_screen = |p: [f64; 2]| {
        Pos2::new(
            origin.x + (p[0] * scale) as f32,
            origin.y - (p[1] * scale) as f32,
        )
    };
    let font = egui::FontId::proportional(11.0);
    for seg in &d.segments {
        let (a, b) = (to_screen(seg.from), to_screen(seg.to));
        let c = colour(seg.style);
        let width = if seg.style == Style::Absolute {
            2.0
        } else {
            1.4
        };
        if matches!(seg.style, Style::Absolute | Style::Relative) {
            painter.arrow(a, b - a, Stroke::new(width, c));
        } else {
            painter.add(egui::Shape::dashed_line(
                &[a, b],
                Stroke::new(width, c),
                5.0,
                3.0,
            ));
            painter.arrow(
                b - (b - a).normalized() * 6.0,
                (b - a).normalized() * 6.0,
                Stroke::new(width, c),
            );
        }
        let at = if seg.style == Style::Absolute {
            b
        } else {
            a + (b - a) * 0.5
        };
        painter.text(
            at + Vec2::new(4.0, -4.0),
            egui::Align2::LEFT_BOTTOM,
            &seg.label,
            font.clone(),
            c,
        );
    }
    painter.circle_filled(origin, 3.0, ui.visuals().text_color());
    painter.text(
        origin + Vec2::new(-4.0, 4.0),
        egui::Align2::RIGHT_TOP,
        pole,
        font.clone(),
        ui.visuals().text_color(),
    );
    // Scale bar, bottom left.
    let bar = scale_bar(extent);
    let len = (bar * scale) as f32;
    let y = rect.bottom() - 10.0;
    let x0 = rect.left() + 10.0;
    painter.line_segment(
        [Pos2::new(x0, y), Pos2::new(x0 + len, y)],
        Stroke::new(2.0, ui.visuals().text_color()),
    );
    painter.text(
        Pos2::new(x0, y - 4.0),
        egui::Align2::LEFT_BOTTOM,
        format!("{} {unit}", fmt_value(bar)),
        font,
        ui.visuals().text_color(),
    );
}

fn fmt_value(v: f64) -> String {
    if (1e-3..1e4).contains(&v.abs()) {
        format!("{v}")
    } else {
        format!("{v:.0e}")
    }
}

fn table(ui: &mut egui::Ui, equations: &[VectorEquation], kind: Quantity) {
    for (i, eq) in equations.iter().filter(|e| e.kind == kind).enumerate() {
        ui.label(format!("{}: {}", eq.group, eq.equation));
        egui::Grid::new((kind, i)).striped(true).show(ui, |ui| {
            ui.strong("term");
            ui.strong("magnitude");
            ui.strong("direction");
            ui.strong("known");
            ui.end_row();
            for t in eq.lhs.iter().chain(&eq.rhs) {
                ui.label(t.symbol.to_string());
                ui.label(format!("{:.4}", t.magnitude));
                ui.label(format!(
                    "{:.2}° ({})",
                    t.direction_rad.to_degrees(),
                    t.direction
                ));
                let known = |k: bool| if k { "yes" } else { "solved" };
                ui.label(format!(
                    "mag {}, dir {}",
                    known(t.magnitude_known),
                    known(t.direction_known)
                ));
                ui.end_row();
            }
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::session::Session;

    #[test]
    fn chains_close_on_the_absolute_vector_of_the_dyad_point() {
        // The rhs chain of v_C = v_B + v_CB ends where the absolute v_C does.
        let s = Session::open_builtin("slider_crank").expect("opens");
        let eqs = s.polygons();
        let v = s.pose().points[s.mechanism().point_index("C").expect("C")].velocity;
        let d = diagram(eqs, Quantity::Velocity, &[("C".into(), [v.x, v.y])]);
        let rel = d
            .segments
            .iter()
            .find(|g| g.label == "v_CB")
            .expect("relative vector");
        assert!((rel.to[0] - v.x).abs() < 1e-12 && (rel.to[1] - v.y).abs() < 1e-12);
        assert_eq!(d.segments[0].label, "c");
    }

    #[test]
    fn quick_return_acceleration_polygon_shows_coriolis() {
        let s = Session::open_builtin("quick_return").expect("opens");
        let d = diagram(s.polygons(), Quantity::Acceleration, &[]);
        assert!(
            d.segments.iter().any(|g| g.style == Style::Coriolis),
            "{d:?}"
        );
    }

    #[test]
    fn scale_bar_is_round_and_at_most_a_quarter() {
        assert_eq!(scale_bar(10.0), 2.0);
        assert_eq!(scale_bar(0.37), 0.05);
        assert_eq!(scale_bar(0.0), 0.0);
        assert_eq!(scale_bar(f64::NAN), 0.0);
    }
}
