//! The session's edits, analyses and playback.

use super::*;

#[test]
fn each_scene_computes_only_what_it_models() {
    let kin = Session::open_builtin("slider_crank").expect("opens");
    assert!(kin.dynamics().is_none());
    let none = kin.model_curves();
    assert!(none.torque_n_m.is_empty() && none.inertia_kg_m2.is_empty());

    let ks = Session::open_builtin("die_cutter").expect("opens");
    assert!(ks.dynamics().is_none() && ks.run_progress().is_none());
    assert!(
        ks.model_curves().torque_n_m.len() > 300,
        "torque over the cycle"
    );
    assert!(ks.model_curves().inertia_kg_m2.is_empty());

    let mut dy = Session::open_builtin("gravity_flipper").expect("opens");
    dy.wait_for_run();
    let run = dy.dynamics().expect("a run").as_ref().expect("runs");
    // The CLI's DOP853 run reaches the end stop at t = 0.244660 s; rtol 1e-8 here.
    assert!(
        (run.duration_s() - 0.244660).abs() < 1e-5,
        "{}",
        run.duration_s()
    );
    let reduced = dy.model_curves();
    assert!(!reduced.inertia_kg_m2.is_empty() && !reduced.moment_n_m.is_empty());
}

#[test]
fn non_finite_edits_leave_a_message_and_the_pose() {
    let mut s = Session::open_builtin("quick_return").expect("opens");
    let pose = s.pose().clone();
    s.apply(SceneEdit::Input { deg: f64::NAN });
    assert!(
        matches!(s.notice(), Some(Notice::InvalidValue { value, .. }) if value.is_nan()),
        "{:?}",
        s.notice()
    );
    assert!(s.message().expect("message").contains("finite number"));
    s.apply(SceneEdit::Length {
        index: 0,
        value: f64::INFINITY,
    });
    assert!(s.message().expect("message").contains("positive length"));
    s.apply(SceneEdit::SpringK {
        index: 0,
        n_per_m: -1.0,
    });
    assert!(matches!(s.notice(), Some(Notice::InvalidValue { .. })));
    s.apply(SceneEdit::SpringK {
        index: 0,
        n_per_m: 1.0,
    }); // no spring: nothing to change, no panic
    assert_eq!(s.pose(), &pose);
}

#[test]
fn an_edit_shows_at_once_and_the_run_follows_off_the_frame() {
    let mut s = Session::open_builtin("gravity_flipper").expect("opens");
    s.wait_for_run();
    let first = s
        .dynamics()
        .expect("a run")
        .as_ref()
        .expect("runs")
        .duration_s();
    s.apply(SceneEdit::Mass {
        index: 1,
        kg: 2.0 * s.scene().links[1].mass.expect("a mass"),
    });
    assert!(s.message().is_none(), "{:?}", s.message());
    // The pose and curves are new at once; the run is being computed.
    assert!(s.dynamics().is_none() && s.run_progress().is_some());
    s.wait_for_run();
    let second = s
        .dynamics()
        .expect("a run")
        .as_ref()
        .expect("runs")
        .duration_s();
    assert!(s.run_progress().is_none());
    assert!((first - second).abs() > 1e-6, "{first} vs {second}");
}

#[test]
fn a_run_sliced_over_frames_is_the_run_computed_at_once() {
    let mut whole = Session::open_builtin("gravity_flipper").expect("opens");
    whole.wait_for_run();
    let mut sliced = Session::open_builtin("gravity_flipper").expect("opens");
    sliced.run_sliced();
    let mut frames = 0;
    while sliced.poll_run(RUN_SLICE_MS) {
        frames += 1;
        assert!(frames < 100_000, "the run ends");
    }
    let a = &whole.dynamics().expect("run").as_ref().expect("ok").sim;
    let b = &sliced.dynamics().expect("run").as_ref().expect("ok").sim;
    assert_eq!(a.samples, b.samples, "the same steps and samples");
    assert_eq!(a.stats.steps, b.stats.steps);
}

#[test]
fn a_refused_length_names_its_limit_found_on_the_margin() {
    let mut checked = 0;
    for b in crate::catalog::BUILTIN_SCENES {
        let mut s = Session::open_builtin(b.key).expect("opens");
        for i in 0..s.lengths().len() {
            let v = s.lengths()[i].value(s.scene()).expect("a length");
            for factor in [0.01, 100.0] {
                let pose = s.pose().clone();
                s.apply(SceneEdit::Length {
                    index: i,
                    value: factor * v,
                });
                let Some(Notice::LengthRefused {
                    limit: Some(limit), ..
                }) = s.notice().cloned()
                else {
                    s.apply(SceneEdit::Length { index: i, value: v });
                    continue;
                };
                let what = format!("{} length {i} x{factor}", b.key);
                assert_eq!(s.pose(), &pose, "{what}: the last valid pose stays");
                assert!(
                    limit > v.min(factor * v) && limit < v.max(factor * v),
                    "{what}"
                );
                // The limit assembles and a hair beyond it does not.
                let beyond = limit + (factor * v - limit) * 1e-6;
                s.apply(SceneEdit::Length {
                    index: i,
                    value: beyond,
                });
                assert!(
                    s.message().is_some(),
                    "{what}: just past {limit} is refused"
                );
                s.apply(SceneEdit::Length {
                    index: i,
                    value: limit,
                });
                assert!(s.message().is_none(), "{what}: {:?}", s.message());
                s.apply(SceneEdit::Length { index: i, value: v });
                checked += 1;
            }
        }
    }
    assert!(checked >= 3, "{checked} refusals checked");
}

#[test]
fn playback_follows_the_run_and_loops() {
    let mut s = Session::open_builtin("gravity_flipper").expect("opens");
    s.wait_for_run();
    let start = s.input_rad();
    s.advance(0.1, 1.0);
    assert!((s.time_s() - 0.1).abs() < 1e-12);
    assert!(
        s.input_rad() < start,
        "the table falls: link 1 turns clockwise"
    );
    s.advance(10.0, 1.0);
    assert_eq!(s.time_s(), 0.0, "loops after the end");
}
