//! The gear-cutting lab, opened from the New… menu as a student would: the rack cutter
//! generating 12 teeth (undercut, marked and said) and the same with the least shift
//! (not undercut), at a laptop's 1366×768, in English and Chinese; back to the
//! mechanism as it was.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use linkage_lab::LinkageApp;
use linkage_lab::i18n::Language;

use crate::common;

/// The lab opened from the New… menu at 1366×768 in `language`.
fn lab(language: Language) -> Harness<'static, LinkageApp> {
    let h = common::opened_from_new_menu(1366.0, 768.0, language, "Gear cutting");
    assert!(h.state().state.gear_lab.is_some(), "the lab is open");
    h
}

#[test]
fn twelve_teeth_are_undercut_and_the_least_shift_cures_them() {
    let mut h = lab(Language::English);
    h.state_mut().state.gear_lab.as_mut().expect("lab").roll = 1.0;
    common::settle(&mut h);
    assert!(h.query_by_label_contains("Undercut (red)").is_some());
    common::still(&mut h);
    h.snapshot("gear_lab_12_teeth_undercut");
    h.get_by_label("Shift the cutter out to x_min").click();
    common::settle(&mut h);
    let shift = h.state().state.gear_lab.as_ref().expect("lab").shift;
    // x_min = h_a* (z_min − z)/z_min with z_min = 2/sin²20° = 17.1: 0.298, rounded
    // up to the slider's step.
    assert!((shift - 0.30).abs() < 1e-12, "{shift}");
    assert!(h.query_by_label_contains("No undercut").is_some());
    common::still(&mut h);
    h.snapshot("gear_lab_12_teeth_least_shift");
    let before = h.state().state.session.scene().clone();
    h.get_by_label("Back to the mechanism").click();
    common::settle(&mut h);
    assert!(h.state().state.gear_lab.is_none());
    assert_eq!(h.state().state.session.scene(), &before);
}

#[test]
fn the_lab_speaks_chinese() {
    let mut h = lab(Language::Chinese);
    h.state_mut().state.gear_lab.as_mut().expect("lab").roll = 1.0;
    common::settle(&mut h);
    assert!(h.query_by_label_contains("发生根切").is_some());
    common::still(&mut h);
    h.snapshot("gear_lab_12_teeth_undercut_zh");
    let lab = h.state_mut().state.gear_lab.as_mut().expect("lab");
    lab.shift = 0.3;
    common::settle(&mut h);
    assert!(h.query_by_label_contains("不发生根切").is_some());
    common::still(&mut h);
    h.snapshot("gear_lab_12_teeth_least_shift_zh");
}

/// The lab's second view: the 12-tooth pinion shifted to x_min meshing with a
/// 40-tooth wheel; the contact ratio shown is the solver's, and the
/// unshifted pinion's undercut is said as a check of the pair; at 15° two pairs of
/// teeth touch.
#[test]
fn a_meshing_pair_shows_its_contact_ratio() {
    meshing_pair(
        Language::English,
        "Meshing pair",
        "The pinion is undercut",
        "gear_lab_pair_12_40",
    );
}

#[test]
fn a_meshing_pair_speaks_chinese() {
    meshing_pair(
        Language::Chinese,
        "齿轮啮合",
        "小齿轮发生根切",
        "gear_lab_pair_12_40_zh",
    );
}

fn meshing_pair(language: Language, mode: &str, undercut: &str, name: &str) {
    {
        let mut h = lab(language);
        h.get_by_label(mode).click();
        common::settle(&mut h);
        assert!(h.query_by_label_contains(undercut).is_some(), "{undercut}");
        let lab = h.state_mut().state.gear_lab.as_mut().expect("lab");
        lab.shift = 0.3;
        lab.wheel_shift = 0.2;
        // 15°: within each 30° tooth period, two pairs touch from about 10.6° to 22.8°
        // (ε = 1.405): the picture shows what ε > 1 means.
        lab.turn_rad = 15f64.to_radians();
        let pair = lab.pair().expect("a pair");
        common::settle(&mut h);
        let eps = format!(
            "ε = {}",
            linkage_diagram::numbers::significant(pair.contact_ratio, 4)
        );
        assert!(h.query_by_label_contains(&eps).is_some(), "{eps}");
        assert!(h.query_by_label_contains(undercut).is_none());
        let pose = linkage::gears::MeshPose::at(&pair, 15f64.to_radians()).expect("external");
        assert_eq!(pose.contacts.len(), 2, "two pairs in contact at 15°");
        common::still(&mut h);
        h.snapshot(name);
    }
}

/// Shifted far out, the 12 teeth's tips grow thin: s_a under 0.25·m is said with
/// the textbooks' least (0.067·m at x = 0.75), in both languages.
#[test]
fn thin_tips_are_said() {
    for (language, words) in [
        (Language::English, "the tips are too thin"),
        (Language::Chinese, "齿顶厚过小"),
    ] {
        let mut h = lab(language);
        h.state_mut().state.gear_lab.as_mut().expect("lab").shift = 0.75;
        common::settle(&mut h);
        assert!(h.query_by_label_contains(words).is_some(), "{words}");
    }
}
