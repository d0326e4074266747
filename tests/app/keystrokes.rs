//! Every keystroke kept: multi-digit values typed key by key into every number box
//! of every shipped scene, on the scene as opened (where the first keystroke used to
//! mark it "(edited)", reflow the top bar, lose the box's focus and keep only the
//! first digit: 300 became 3) and once edited. Each value typed is either taken
//! whole (the session then holds exactly the number typed) or refused with its
//! reason shown and the value kept; where the box has a slider, the value is taken
//! exactly when it lies in the slider's range (or wraps round a full turn).

use eframe::egui;
use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use linkage::cam::SegmentSpec;
use linkage_lab::catalog::BUILTIN_SCENES;
use linkage_lab::session::Session;
use linkage_lab::ui::controls::CRANK_LABEL;
use linkage_lab::{LinkageApp, StartOptions};

/// What a student types: whole, fractional, in powers of ten, negative; and text
/// that is no number.
const TYPED: [&str; 5] = ["300", "0.125", "1e3", "-45", "3O0"];

fn app() -> Harness<'static, LinkageApp> {
    let mut h = Harness::builder()
        .with_size(egui::vec2(1500.0, 950.0))
        .build_eframe(|cc| LinkageApp::new(cc, StartOptions::default()));
    h.run_steps(2);
    h
}

/// Frames until the app settles, the dynamic run waited for.
fn settle(h: &mut Harness<'static, LinkageApp>) {
    for _ in 0..3 {
        h.state_mut().state.session.wait_for_run();
        h.run_steps(1);
    }
}

fn open_fresh(h: &mut Harness<'static, LinkageApp>, key: &str) {
    let session = Session::open_builtin(key).expect("a shipped scene opens");
    crate::common::open_dropping_edits(&mut h.state_mut().state, session);
    settle(h);
    assert!(!h.state().state.session.is_dirty(), "{key} opens edited");
}

/// The value the app holds for the number labelled `label`, as the box shows it.
fn held(h: &Harness<'static, LinkageApp>, label: &str) -> f64 {
    let st = &h.state().state;
    let s = &st.session;
    let scene = s.scene();
    if label == CRANK_LABEL {
        let deg = s.input_rad().to_degrees();
        return if s.curves().full_rotation {
            deg.rem_euclid(360.0)
        } else {
            deg
        };
    }
    let cam_lift = || {
        scene.cams[0]
            .segments
            .iter()
            .filter_map(SegmentSpec::lift)
            .fold(0.0, f64::max)
    };
    match label {
        "run time (s)" => return s.time_s(),
        "speed ×" => return st.play.speed,
        "rtol" => return s.integrator().rtol,
        "Δt (s)" | "Δφ (rad)" => return s.integrator().step,
        _ if label.starts_with("lift (") => return cam_lift(),
        _ if label.starts_with("roller (") => return scene.cams[0].roller_radius,
        _ => {}
    }
    if let Some(p) = s.lengths().iter().find(|p| p.label == label) {
        return p.value(scene).expect("the length's points");
    }
    if let Some(segment) = label
        .strip_prefix("segment ")
        .and_then(|r| r.strip_suffix(" angle (°)"))
    {
        let i: usize = segment.parse().expect("a segment number");
        return scene.cams[0].segments[i - 1].angle_deg();
    }
    for spring in &scene.forces.springs {
        if label == format!("k {}-{} (N/m)", spring.a, spring.b) {
            return spring.k_n_per_m;
        }
    }
    for link in &scene.links {
        if label == format!("mass {} (kg)", link.name) {
            return link.mass.expect("a mass");
        }
    }
    panic!("no value for the box {label}");
}

/// The slider beside the box labelled `label`, if it has one: its range, and
/// whether its value wraps (the crank's full turn).
fn slider_range(h: &Harness<'static, LinkageApp>, label: &str) -> Option<([f64; 2], bool)> {
    let slider = h.query_by_role_and_label(Role::Slider, label)?;
    let node = slider.accesskit_node();
    let range = [node.min_numeric_value()?, node.max_numeric_value()?];
    let wraps = label == CRANK_LABEL && h.state().state.session.curves().full_rotation;
    Some((range, wraps))
}

/// Clicks into the box, selects what it shows, types `text` key by key, presses
/// Enter.
fn type_into(h: &mut Harness<'static, LinkageApp>, label: &str, text: &str) {
    let at = h
        .get_by_role_and_label(Role::TextInput, label)
        .rect()
        .center();
    let button = |pressed| egui::Event::PointerButton {
        pos: at,
        button: egui::PointerButton::Primary,
        pressed,
        modifiers: egui::Modifiers::default(),
    };
    h.event(egui::Event::PointerMoved(at));
    h.event(button(true));
    h.run_steps(1);
    h.event(button(false));
    h.run_steps(1);
    let key = |key, modifiers| egui::Event::Key {
        key,
        physical_key: None,
        pressed: true,
        repeat: false,
        modifiers,
    };
    h.event(key(egui::Key::A, egui::Modifiers::COMMAND));
    h.run_steps(1);
    for c in text.chars() {
        h.event(egui::Event::Text(c.to_string()));
        h.run_steps(1);
    }
    h.event(key(egui::Key::Enter, egui::Modifiers::NONE));
    settle(h);
}

/// Whether a refusal of the box labelled `label` is shown: its own line ("…; kept
/// …") or the session's message (a length the chain cannot take).
fn refusal_shown(h: &Harness<'static, LinkageApp>, label: &str) -> bool {
    let prefix = format!("{label}: ");
    let own = h
        .query_all_by(|n| {
            n.value()
                .is_some_and(|l| l.starts_with(&prefix) && l.contains("kept"))
        })
        .next()
        .is_some();
    own || h.state().state.session.message().is_some()
}

/// Types `text` into the box `label` and checks what the app holds after it.
fn check_typed(h: &mut Harness<'static, LinkageApp>, scene: &str, label: &str, text: &str) {
    let before = held(h, label);
    let range = slider_range(h, label);
    type_into(h, label, text);
    let after = held(h, label);
    let at = format!("{scene}, {label}, typed {text:?}: before {before}, after {after}");
    let Ok(typed) = text.parse::<f64>() else {
        assert_eq!(after, before, "{at}: text that is no number changed it");
        assert!(refusal_shown(h, label), "{at}: refused without a word");
        return;
    };
    let wanted = match range {
        Some(([lo, hi], true)) => lo + (typed - lo).rem_euclid(hi - lo),
        _ => typed,
    };
    let taken = (after - wanted).abs() <= 1e-9 * wanted.abs().max(1e-12);
    if taken {
        return;
    }
    assert_eq!(after, before, "{at}: neither taken whole nor kept");
    assert!(refusal_shown(h, label), "{at}: refused without a word");
    if let Some(([lo, hi], wraps)) = range {
        // A value in the slider's range is refused only by the chain itself (a
        // length it cannot assemble with), which says so in the session's message.
        let inside = wraps || (lo..=hi).contains(&typed);
        assert!(
            !inside || h.state().state.session.message().is_some(),
            "{at}: in the range {lo} … {hi} but refused"
        );
    }
}

/// A value inside the box's range with four significant digits: 0.93 of the way
/// along its slider (on a logarithmic one, in ratio), or 0.93 of its value.
fn inside_value(h: &Harness<'static, LinkageApp>, label: &str) -> String {
    let v = match slider_range(h, label) {
        Some(([lo, hi], _)) if lo > 0.0 && hi / lo > 100.0 => lo * (hi / lo).powf(0.93),
        Some(([lo, hi], _)) => lo + 0.93 * (hi - lo),
        None => 0.93 * held(h, label),
    };
    format!("{:.3e}", v)
}

/// The boxes of the controls pane, by label, in the order drawn.
fn boxes(h: &Harness<'static, LinkageApp>) -> Vec<String> {
    h.query_all_by_role(Role::TextInput)
        .filter_map(|n| n.accesskit_node().label())
        .collect()
}

#[test]
fn every_digit_typed_into_every_box_of_every_scene_is_kept() {
    let mut h = app();
    let mut typed_boxes = 0;
    for scene in BUILTIN_SCENES {
        open_fresh(&mut h, scene.key);
        for label in boxes(&h) {
            // The first value on the scene as opened, the rest once it is edited.
            open_fresh(&mut h, scene.key);
            for text in TYPED {
                check_typed(&mut h, scene.key, &label, text);
            }
            // And a value inside the range, of four digits, taken whole.
            let inside = inside_value(&h, &label);
            type_into(&mut h, &label, &inside);
            let want: f64 = inside.parse().expect("a number");
            let after = held(&h, &label);
            assert!(
                (after - want).abs() <= 1e-9 * want.abs()
                    || h.state().state.session.message().is_some(),
                "{}, {label}: typed {inside}, holds {after}",
                scene.key
            );
            typed_boxes += 1;
        }
    }
    // Every scene has its crank, its speed and its lengths at least.
    assert!(typed_boxes >= 4 * BUILTIN_SCENES.len(), "{typed_boxes}");
}
