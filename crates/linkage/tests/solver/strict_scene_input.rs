//! Scene text that serde would once take silently: a misspelt field, a key given twice,
//! an angle too large for a double to hold. Each is refused with the field, line and
//! column (and the fields allowed, or both entries), never loaded as something the
//! author did not write. Regression tests for issue 11's fuzzing findings.

use linkage::{LinkageError, Mechanism, SceneFile};

const SLIDER_CRANK: &str = include_str!("../../../../assets/scenes/slider_crank.ron");

fn syntax_error(text: &str) -> (usize, usize, String) {
    match SceneFile::parse(text) {
        Err(LinkageError::SceneSyntax {
            line,
            column,
            message,
        }) => (line, column, message),
        other => panic!("expected a syntax error, got {other:?}"),
    }
}

#[test]
fn misspelt_relative_angel_is_refused_with_the_fields_allowed() {
    let text = SLIDER_CRANK.replace("angle: 0.0)", "angle: 0.0, relative_angel: 5.0)");
    assert_ne!(text, SLIDER_CRANK);
    let (line, column, message) = syntax_error(&text);
    assert!(message.contains("relative_angel"), "{message}");
    assert!(
        message.contains("relative_angle"),
        "names what is allowed: {message}"
    );
    assert_eq!(line, 15, "the slider's line");
    assert!(column > 1, "{column}");
}

#[test]
fn unknown_top_level_field_is_refused() {
    let text = SLIDER_CRANK.replace(
        "models: Kinematics,",
        "models: Kinematics, modles: Kinematics,",
    );
    let (_, _, message) = syntax_error(&text);
    assert!(
        message.contains("modles") && message.contains("models"),
        "{message}"
    );
}

#[test]
fn unknown_field_in_a_damper_variant_is_refused() {
    let text = SLIDER_CRANK.replace(
        "output: Some(\"slider\"),",
        "output: Some(\"slider\"), forces: (dampers: [Linear(a: \"B\", b: \"C\", c_n_s_per_m: 1.0, c: 2.0)]),",
    );
    let (_, _, message) = syntax_error(&text);
    assert!(
        message.contains("`c`") || message.contains("\"c\""),
        "{message}"
    );
}

#[test]
fn duplicated_point_key_is_refused_naming_both_entries() {
    let text = SLIDER_CRANK.replace(
        "\"B\": (50.0, 0.0)}",
        "\"B\": (50.0, 0.0), \"B\": (60.0, 0.0)}",
    );
    assert_ne!(text, SLIDER_CRANK);
    let (line, _, message) = syntax_error(&text);
    assert!(message.contains("\"B\" is given twice"), "{message}");
    assert!(message.contains("entry 2 and entry 3"), "{message}");
    assert_eq!(line, 10, "the crank's line");
}

#[test]
fn point_twice_in_branches_is_refused() {
    let text = SLIDER_CRANK.replace(
        "branches: {\"C\": Along}",
        "branches: {\"C\": Along, \"C\": Against}",
    );
    let (_, _, message) = syntax_error(&text);
    assert!(message.contains("\"C\" is given twice"), "{message}");
}

#[test]
fn driver_start_of_1e16_deg_is_refused_with_the_valid_range() {
    let text = SLIDER_CRANK.replace("start: 0.0", "start: 1e16");
    let scene = SceneFile::parse(&text).expect("parses");
    let err = Mechanism::from_scene(&scene).expect_err("refused");
    let msg = err.to_string();
    assert!(msg.contains("driver.start"), "{msg}");
    assert!(msg.contains("within ±"), "names the range: {msg}");
}

#[test]
fn a_start_angle_of_many_turns_within_range_still_loads() {
    // 2000 turns: a double holds it to 1e-12 rad.
    let text = SLIDER_CRANK.replace("start: 0.0", "start: 720000.0");
    let scene = SceneFile::parse(&text).expect("parses");
    Mechanism::from_scene(&scene).expect("loads");
}

#[test]
fn every_shipped_scene_still_parses_strictly() {
    for entry in std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../../assets/scenes"))
        .expect("scene dir")
    {
        let path = entry.expect("entry").path();
        if path.extension().is_some_and(|e| e == "ron") {
            let text = std::fs::read_to_string(&path).expect("read");
            SceneFile::parse(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        }
    }
}
