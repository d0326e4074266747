//! The gear lab's second view: the gear being cut (the pinion) meshing with a wheel.
//! Its controls (the wheel's teeth and shift beside the lab's own numbers, the turn
//! with Play), its numbers (centre distance, working pressure angle, ratio, contact
//! ratio and what a designer should know: undercut, pointed tips, interference,
//! clearance, ε < 1), and its canvas, drawn by the GPU pass.

use std::sync::Arc;

use eframe::egui::{self, Align2, Color32, FontId};
use linkage::gears::{GearPair, Member, MeshPose, PairIssue};
use linkage_diagram::gear_profile::gear_outline;
use linkage_diagram::numbers::significant;

use crate::gear_lab::GearLab;
use crate::i18n::tr;
use crate::render::gear_pair_shapes::{build_gear_pair, pair_bounds};
use crate::ui::gear_canvas::Canvas;

/// Radii along each flank of a drawn outline.
const PER_FLANK: usize = 30;

/// The pair's own controls (after the lab's teeth, module, shift and angle).
pub fn controls(ui: &mut egui::Ui, lab: &mut GearLab) {
    ui.add(egui::Slider::new(&mut lab.wheel_teeth, 6..=120).text(tr!("gear.wheel_teeth")));
    ui.add(
        egui::Slider::new(&mut lab.wheel_shift, -1.0..=1.0)
            .step_by(0.01)
            .text(tr!("gear.wheel_shift")),
    );
    ui.horizontal(|ui| {
        crate::ui::gear_canvas::play_button(ui, lab);
        let mut deg = lab.turn_rad.to_degrees();
        let turn = egui::Slider::new(&mut deg, 0.0..=360.0).text(tr!("gear.turn"));
        if ui.add(turn).changed() {
            lab.turn_rad = deg.to_radians();
        }
    });
}

/// The pair's numbers and checks.
pub fn numbers(ui: &mut egui::Ui, pair: &GearPair) {
    let n = |v: f64| significant(v, 5);
    ui.separator();
    ui.label(tr!(
        "gear.pair_figures",
        a = n(pair.centre_m * 1e3),
        alpha = n(pair.working_pressure_angle_rad.to_degrees()),
        ratio = n(f64::from(pair.wheel.spec.teeth) / f64::from(pair.pinion.spec.teeth)),
        eps = significant(pair.contact_ratio, 4)
    ));
    // Where the shifts move the centres apart: the standard centre distance, y, and
    // the tips' shortening Δy·m, without which ε would be computed from the uncut tips.
    let m = pair.pinion.spec.module_m;
    ui.label(tr!(
        "gear.pair_shift_figures",
        a0 = n(pair.standard_centre_m * 1e3),
        y = significant(pair.centre_modification, 4)
    ));
    if let Some(dy) = pair.tip_shortening.filter(|dy| *dy > 0.0) {
        ui.label(tr!(
            "gear.pair_tips_cut",
            dy = significant(dy, 3),
            cut = significant(dy * m * 1e3, 3)
        ));
    }
    for issue in &pair.issues {
        ui.colored_label(Color32::from_rgb(190, 40, 30), issue_words(issue));
    }
    ui.label(tr!("gear.pair_legend"));
}

fn member(m: Member) -> String {
    match m {
        Member::Pinion => tr!("gear.pinion"),
        Member::Wheel => tr!("gear.wheel"),
    }
}

/// A pair's check in the user's words.
fn issue_words(issue: &PairIssue) -> String {
    match *issue {
        PairIssue::Undercut {
            member: m,
            shift_short,
        } => tr!(
            "gear.issue_undercut",
            gear = member(m),
            short = significant(shift_short, 3)
        ),
        PairIssue::PointedTip { member: m } => tr!("gear.issue_pointed", gear = member(m)),
        PairIssue::ThinTip {
            member: m,
            thickness_m,
            least_m,
        } => tr!(
            "gear.issue_thin_tip",
            gear = member(m),
            s = significant(thickness_m * 1e3, 3),
            least = significant(least_m * 1e3, 3)
        ),
        PairIssue::TipInterference { member: m } => {
            tr!("gear.issue_interference", gear = member(m))
        }
        PairIssue::RingTipInsideBase => tr!("gear.issue_ring_tip"),
        PairIssue::NoClearance {
            member: m,
            clearance_m,
        } => tr!(
            "gear.issue_clearance",
            gear = member(m),
            c = significant(clearance_m * 1e3, 3)
        ),
        PairIssue::ContactRatioBelowOne { contact_ratio } => tr!(
            "gear.issue_contact_ratio",
            eps = significant(contact_ratio, 3)
        ),
    }
}

/// The pair on the lab's canvas.
pub fn draw(ui: &egui::Ui, canvas: &Canvas<'_>, lab: &mut GearLab) {
    let (painter, rect) = (canvas.painter, canvas.rect);
    let Ok(pair) = lab.pair() else {
        return;
    };
    let Some(pose) = MeshPose::at(&pair, lab.turn_rad) else {
        return;
    };
    if rect.width() > 1.0 && rect.height() > 1.0 {
        lab.camera.fit(pair_bounds(&pair), rect);
    }
    let outlines = outlines_of(ui, &pair);
    if let Ok(mut list) = canvas.shapes.lock() {
        build_gear_pair(
            &mut list,
            &pair,
            &pose,
            [&outlines.0, &outlines.1],
            &lab.camera,
        );
    }
    canvas.paint(&lab.camera);
    let font = FontId::proportional(13.0);
    let purple = Color32::from_rgb(140, 25, 115);
    // N₁ below the line, N₂ above it, B₁ and B₂ on the far side from N's, P beside
    // the line of centres.
    let [n1, n2] = pose.line_of_action_m;
    let [b2, b1] = pose.path_of_contact_m;
    let pitch_point = [0.0, pair.working_pitch_radii_m[0]];
    for (p, name, align, offset) in [
        (n1, "N₁", Align2::LEFT_TOP, egui::vec2(6.0, 4.0)),
        (n2, "N₂", Align2::RIGHT_BOTTOM, egui::vec2(-6.0, -4.0)),
        (b1, "B₁", Align2::LEFT_BOTTOM, egui::vec2(6.0, -4.0)),
        (b2, "B₂", Align2::RIGHT_TOP, egui::vec2(-6.0, 4.0)),
        (pitch_point, "P", Align2::LEFT_BOTTOM, egui::vec2(5.0, -3.0)),
    ] {
        let at = lab.camera.to_screen(p, rect) + offset;
        let colour = if name == "P" { Color32::BLACK } else { purple };
        halo_text(painter, at, align, name, &font, colour);
    }
}

/// A name with a light halo under it, readable over teeth and lines (the pair's
/// points, the train's members).
pub fn halo_text(
    painter: &egui::Painter,
    at: egui::Pos2,
    align: Align2,
    text: &str,
    font: &FontId,
    colour: Color32,
) {
    let galley = painter.layout_no_wrap(text.to_owned(), font.clone(), colour);
    let rect = align.anchor_size(at, galley.size()).expand(1.5);
    painter.rect_filled(
        rect,
        2.0,
        Color32::from_rgba_unmultiplied(250, 250, 246, 210),
    );
    painter.galley(rect.min + egui::vec2(1.5, 1.5), galley, colour);
}

type Outlines = Arc<(Vec<[f64; 2]>, Vec<[f64; 2]>)>;

/// Both gears' cut outlines, made once for each pair and kept in egui's memory
/// while it stays the same (each is a search per radius of each flank).
fn outlines_of(ui: &egui::Ui, pair: &GearPair) -> Outlines {
    let key = format!("{:?}{:?}", pair.pinion.spec, pair.wheel.spec);
    let id = egui::Id::unique("gear_pair::outlines");
    if let Some((kept, outlines)) = ui.data(|d| d.get_temp::<(String, Outlines)>(id))
        && kept == key
    {
        return outlines;
    }
    let outlines: Outlines = Arc::new((
        gear_outline(&pair.pinion, PER_FLANK),
        gear_outline(&pair.wheel, PER_FLANK),
    ));
    ui.data_mut(|d| d.insert_temp(id, (key, outlines.clone())));
    outlines
}
