//! The student's side of an exercise, as a student meets it: *New… → Exercises*, the
//! student number typed, the variant's data and the mechanism; the answers typed
//! digit by digit, marked in homework, and the answer code the teacher grades; the
//! true answers nowhere on screen while the exercise is open, in either language,
//! on a laptop and a phone.

use eframe::egui;
use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use linkage_lab::LinkageApp;
use linkage_lab::catalog::EXERCISES;
use linkage_lab::exercise::Exercise;
use linkage_lab::i18n::Language;
use linkage_lab::ui::control_map::ControlKind;

use crate::common;

/// The app at `w`×`h` in `language` with the exercise `key` opened from the New…
/// menu and the student number `number` typed and taken.
fn desk(
    w: f32,
    h: f32,
    language: Language,
    key: &str,
    number: &str,
) -> Harness<'static, LinkageApp> {
    let mut h = common::sized_harness(w, h);
    h.ctx
        .set_missing_glyph_policy(egui::MissingGlyphPolicy::Panic);
    h.state_mut().state.language = language;
    common::settle(&mut h);
    if h.state().state.layout.compact() {
        // On a phone or tablet the file actions are in the top bar's menu.
        common::click_control(&mut h, ControlKind::Menu, "Menu");
        common::settle(&mut h);
    }
    common::click_control(&mut h, ControlKind::FileButton, "New…");
    common::settle(&mut h);
    let submenu = words(language, "exercise.menu");
    h.get_by_label(&submenu).click();
    common::settle(&mut h);
    common::click_control(&mut h, ControlKind::TemplateItem, key);
    common::settle(&mut h);
    assert!(
        h.state().state.exercise.is_some(),
        "{key}: the desk is open"
    );
    let field = words(language, "exercise.student_number");
    type_into(&mut h, &field, number);
    common::click_control(
        &mut h,
        ControlKind::Exercise,
        linkage_lab::ui::exercise::START_BUTTON,
    );
    common::settle(&mut h);
    h
}

/// The catalogue's words for `key` in `language`.
fn words(language: Language, key: &str) -> String {
    linkage_lab::i18n::set_language(language);
    linkage_lab::i18n::text(key)
}

/// Clicks into the text box labelled `label` and types `text`, a key at a time.
fn type_into(h: &mut Harness<'static, LinkageApp>, label: &str, text: &str) {
    h.get_by_role_and_label(Role::TextInput, label).click();
    h.run_steps(1);
    for c in text.chars() {
        h.event(egui::Event::Text(c.to_string()));
        h.run_steps(1);
    }
    h.run_steps(2);
}

fn exercise(key: &str) -> Exercise {
    let e = EXERCISES.iter().find(|e| e.key == key).expect("shipped");
    Exercise::parse(e.text).expect("reads")
}

/// Every text on screen: labels and the values of text boxes.
fn texts(h: &Harness<'static, LinkageApp>) -> Vec<String> {
    h.query_all_by(|_| true)
        .flat_map(|n| [n.accesskit_node().label(), n.value()])
        .flatten()
        .collect()
}

/// The truths as a student might read them off a screen: 3 to 6 significant digits.
fn truth_digits(truths: &[f64]) -> Vec<String> {
    let mut out = Vec::new();
    for t in truths {
        for digits in 3..=6 {
            let s = linkage_diagram::numbers::significant(*t, digits);
            // A digit string too short to be told apart from other numbers (a "1.3").
            if s.trim_start_matches('-')
                .replace('.', "")
                .trim_start_matches('0')
                .len()
                >= 3
            {
                out.push(s.trim_start_matches('-').to_string());
            }
        }
    }
    out
}

#[test]
fn a_student_gets_the_variant_of_the_number_typed_and_answers_it() {
    let mut h = desk(
        1366.0,
        768.0,
        Language::English,
        "die_cutter_slider",
        "2026001",
    );
    let ex = exercise("die_cutter_slider");
    let student = linkage_lab::exercise::StudentId::parse("2026001").expect("a number");
    let variant = ex.variant(&student).expect("a variant");
    // The data as drawn: AB and BC of this student, the crank's speed.
    let number = |x: f64| linkage_diagram::numbers::significant(x, 6);
    let [ab, bc, rpm] = [0, 1, 2].map(|i| number(variant.values[i]));
    assert!(h.query_by_label(&format!("{ab} mm")).is_some(), "AB");
    assert!(h.query_by_label(&format!("{bc} mm")).is_some(), "BC");
    assert!(
        h.query_by_label(&format!("{rpm} r/min, counter-clockwise"))
            .is_some(),
        "the crank's speed"
    );
    assert_eq!(
        h.state().state.session.scene(),
        match &variant.subject {
            linkage_lab::exercise::SubjectData::Scene(s) => s.as_ref(),
            _ => panic!("a mechanism"),
        }
    );
    // Answer 1 right in mm/s, answer 2 20 % off, the rest left.
    let a1 = format!("{:.2} mm/s", variant.truths[0] * 1000.0);
    let a2 = format!("{:.4}", variant.truths[1] * 1.2);
    let (q1, q2) = (question_words(&h, 0), question_words(&h, 1));
    type_into(&mut h, &format!("1. {q1}"), &a1);
    type_into(&mut h, &format!("2. {q2}"), &a2);
    common::settle(&mut h);
    assert!(
        h.query_by_label_contains("right (within 3 %)").is_some(),
        "answer 1 marked right"
    );
    assert!(
        h.query_by_label_contains("wrong (within 5 % is right)")
            .is_some(),
        "answer 2 marked wrong"
    );
    let desk = h.state().state.exercise.as_ref().expect("open");
    let code = desk.code().expect("a code");
    let sheet = ex.read_code(&code).expect("the teacher reads it");
    assert_eq!(sheet.student, student);
    assert!(
        (sheet.answers[0].expect("answered") - variant.truths[0]).abs() < 0.01 * variant.truths[0]
    );
    assert_eq!(sheet.answers[2], None);
    let grade = ex.grade(&sheet, &variant);
    assert_eq!(grade.score, 1.0);
    assert!(
        h.query_all_by(|n| n.value().is_some_and(|v| v == code))
            .next()
            .is_some(),
        "the code is shown"
    );
}

/// Question `i` as its label reads (its subscripts set apart, so no marks).
fn question_words(h: &Harness<'static, LinkageApp>, i: usize) -> String {
    let desk = h.state().state.exercise.as_ref().expect("open");
    let ask = &desk.exercise.file.questions[i].ask;
    let words = linkage_lab::ui::exercise_words::question(ask, &desk.exercise.subject);
    linkage_diagram::label::Label::marked(&words).text()
}

/// No true answer on screen while the exercise is open: every shipped exercise, five
/// students each, English and Chinese, a laptop and a phone.
#[test]
fn the_true_answers_are_nowhere_on_screen() {
    for (w, ht) in [(1366.0, 768.0), (390.0, 844.0)] {
        for language in [Language::English, Language::Chinese] {
            for e in EXERCISES {
                let ex = exercise(e.key);
                let mut h = desk(w, ht, language, e.key, "2026003");
                let student = linkage_lab::exercise::StudentId::parse("2026003").expect("a number");
                let truths = ex.variant(&student).expect("a variant").truths;
                let shown = texts(&h);
                assert!(
                    shown.len() > 10,
                    "{}: the desk shows its data and questions",
                    e.key
                );
                for digits in truth_digits(&truths) {
                    let found: Vec<&String> =
                        shown.iter().filter(|t| t.contains(&digits)).collect();
                    assert!(
                        found.is_empty(),
                        "{} at {w}x{ht} {language:?}: {digits} shown in {found:?}",
                        e.key
                    );
                }
                // The pose at the asked angle shows no answer either.
                h.state_mut()
                    .state
                    .edit(linkage_lab::session::SceneEdit::Input { deg: 30.0 });
                common::settle(&mut h);
                let shown = texts(&h);
                for digits in truth_digits(&truths) {
                    assert!(
                        !shown.iter().any(|t| t.contains(&digits)),
                        "{}: {digits} at 30 deg",
                        e.key
                    );
                }
            }
        }
    }
}

/// A snapshot of the desk to look at.
fn snapshot(name: &str, size: [f32; 2], language: Language, key: &str) {
    let mut h = desk(size[0], size[1], language, key, "2026001");
    common::still(&mut h);
    h.snapshot(name);
}

#[test]
fn the_desk_on_a_laptop() {
    snapshot(
        "exercise_die_cutter",
        [1366.0, 768.0],
        Language::English,
        "die_cutter_slider",
    );
}

#[test]
fn the_desk_on_a_phone_in_chinese() {
    snapshot(
        "exercise_four_bar_zh_phone",
        [390.0, 844.0],
        Language::Chinese,
        "four_bar_instant_centres",
    );
}

#[test]
fn a_cam_exercise_in_chinese() {
    snapshot(
        "exercise_cam_zh",
        [1366.0, 768.0],
        Language::Chinese,
        "cam_pressure_angle",
    );
}

#[test]
fn the_desk_on_a_phone_in_english() {
    snapshot(
        "exercise_die_cutter_phone",
        [390.0, 844.0],
        Language::English,
        "die_cutter_slider",
    );
}
