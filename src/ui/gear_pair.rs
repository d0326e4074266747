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
        let label = if lab.playing {
            tr!("gear.pause")
        } else {
            tr!("gear.play")
        };
        if ui.button(label).clicked() {
            lab.toggle_play();
        }
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
    let [n1, n2] = pose.line_of_action_m;
    for (p, name) in [(n1, "N₁"), (n2, "N₂")] {
        let at = lab.camera.to_screen(p, rect) + egui::vec2(6.0, 2.0);
        painter.text(at, Align2::LEFT_TOP, name, font.clone(), purple);
    }
    let [b2, b1] = pose.path_of_contact_m;
    for (p, name) in [(b2, "B₂"), (b1, "B₁")] {
        let at = lab.camera.to_screen(p, rect) + egui::vec2(-6.0, 2.0);
        painter.text(at, Align2::RIGHT_TOP, name, font.clone(), purple);
    }
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
