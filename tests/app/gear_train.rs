//! The gear lab's train view, opened from the New… menu as a student would: the
//! planetary set with its ring held (the carrier's 290 rpm in the table, the
//! converted-train ratio and the assembly checks said), turning; the die cutter's
//! fixed-axis drive; every shipped train at a laptop's and a phone's size; English
//! and Chinese.

use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use linkage_lab::LinkageApp;
use linkage_lab::catalog::TRAINS;
use linkage_lab::gear_lab::{GearLab, LabMode};
use linkage_lab::i18n::Language;
use linkage_lab::train_view::TrainView;

use crate::common;

/// The train view opened from the New… menu at `w`×`h` in `language`.
fn trains(w: f32, h: f32, language: Language) -> Harness<'static, LinkageApp> {
    let h = common::opened_from_new_menu(w, h, language, "Gear trains");
    let lab = h.state().state.gear_lab.as_ref().expect("the lab is open");
    assert_eq!(lab.mode, LabMode::Train);
    h
}

fn view<'a>(h: &'a mut Harness<'static, LinkageApp>) -> &'a mut TrainView {
    &mut h.state_mut().state.gear_lab.as_mut().expect("lab").train
}

/// The sun at 1450 rpm, the ring held: the carrier at 1450/(1 + 80/20) = 290 rpm,
/// the planet at ω_H − (z_s/z_p)(ω_s − ω_H) = 290 − (20/30)·1160 = −483.33 rpm, the
/// converted train's ratio of sun to ring −z_r/z_s = −4; played, the sun turns five
/// times as far as the carrier.
#[test]
fn the_planetary_set_turns_at_the_willis_speeds() {
    let mut h = trains(1366.0, 768.0, Language::English);
    assert!(h.query_by_label("290").is_some(), "the carrier's speed");
    assert!(
        h.query_by_label_contains("483.33").is_some(),
        "the planet's speed"
    );
    assert!(
        h.query_by_label_contains("= -4").is_some(),
        "the Willis ratio"
    );
    assert!(
        h.query_by_label_contains("Equal spacing of 4 planets")
            .is_some()
    );
    let sun = |h: &Harness<'static, LinkageApp>| {
        h.state().state.gear_lab.as_ref().expect("lab").train.angles[0]
    };
    let start = sun(&h);
    h.get_by_label("Play").click();
    for _ in 0..10 {
        h.step();
    }
    h.get_by_label("Pause").click();
    h.run();
    let lab = h.state().state.gear_lab.as_ref().expect("lab");
    let (s, c) = (lab.train.angles[0] - start, lab.train.angles[2]);
    assert!(s != 0.0, "the sun turned");
    assert!((c / s - 0.2).abs() < 1e-9, "carrier {c} vs sun {s}");
    for angle in &mut view(&mut h).angles {
        *angle = 0.3;
    }
    common::still(&mut h);
    h.snapshot("gear_train_planetary");
}

#[test]
fn the_train_view_speaks_chinese() {
    let mut h = trains(1366.0, 768.0, Language::Chinese);
    assert!(h.query_by_label_contains("转化轮系").is_some());
    assert!(h.query_by_label_contains("均布").is_some());
    for angle in &mut view(&mut h).angles {
        *angle = 0.3;
    }
    common::still(&mut h);
    h.snapshot("gear_train_planetary_zh");
}

/// The die cutter's drive: motor 1450 rpm, belt 2.9, gears 40/20 and 95/19: the
/// crank at 1450/29 = 50 rpm, the paper's.
#[test]
fn the_die_cutters_drive_turns_its_crank_at_fifty_rpm() {
    let mut h = trains(1366.0, 768.0, Language::English);
    let choice = TRAINS
        .iter()
        .position(|t| t.key == "die_cutter_drive")
        .expect("shipped");
    *view(&mut h) = TrainView::of(choice);
    common::settle(&mut h);
    assert!(h.query_by_label("50").is_some(), "the crank's speed");
    assert!(h.query_by_label("29").is_some(), "the total ratio");
    common::still(&mut h);
    h.snapshot("gear_train_die_cutter");
}

/// Every shipped train at a laptop's and a phone's size, in both languages: drawn
/// without a missing glyph or a panic, every member's speed in the table.
#[test]
fn every_shipped_train_shows_at_every_size() {
    for (w, hgt) in [(1366.0, 768.0), (390.0, 844.0)] {
        for language in [Language::English, Language::Chinese] {
            // On a phone New… sits in a menu; the lab is opened as the menu does.
            let mut h = common::sized_harness(w, hgt);
            h.ctx
                .set_missing_glyph_policy(egui::MissingGlyphPolicy::Panic);
            h.state_mut().state.language = language;
            h.state_mut().state.gear_lab = Some(GearLab {
                mode: LabMode::Train,
                ..GearLab::default()
            });
            for (choice, train) in TRAINS.iter().enumerate() {
                *view(&mut h) = TrainView::of(choice);
                common::settle(&mut h);
                let solution = view(&mut h).solve().expect("solves").clone();
                for m in &solution.speeds_rpm {
                    assert!(
                        h.query_all_by_label_contains(&m.member).next().is_some(),
                        "{}: {} at {w}x{hgt}",
                        train.key,
                        m.member
                    );
                }
            }
            if w < 500.0 && language == Language::English {
                *view(&mut h) = TrainView::default();
                common::settle(&mut h);
                common::still(&mut h);
                h.snapshot("gear_train_planetary_phone");
            }
        }
    }
}
