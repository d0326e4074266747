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
    let end = s
        .dynamics()
        .and_then(|r| r.as_ref().ok())
        .expect("a run")
        .duration_s();
    assert_eq!(s.time_s(), end, "holds the end");
    s.advance(0.4, 1.0);
    assert_eq!(s.time_s(), end, "still holds the end");
    s.advance(0.2, 1.0);
    assert_eq!(s.time_s(), 0.0, "loops after half a second at the end");
}

/// The gravity flipper played to its end stop shows one state: the pose's crank
/// angle is the run's (35°, the stop), not the angle of the link the run integrated
/// past the crank's dead point (it showed 138.6°, a pose the scene's crank cannot
/// reach, so the force polygons said "cannot assemble"); the force polygons exist
/// there. An edit then runs again from the run's start, where the pose goes back.
#[test]
fn the_flipper_played_to_its_stop_and_edited_shows_one_state() {
    let mut s = Session::open_builtin("gravity_flipper").expect("opens");
    s.wait_for_run();
    let (end, stop_q) = {
        let run = s.dynamics().expect("a run").as_ref().expect("runs");
        let stop = run.sim.events.iter().find(|e| e.stopped).expect("the stop");
        (run.duration_s(), stop.state.q)
    };
    // Played at speed 1 in 60 Hz frames, to a frame past the stop.
    let mut t = 0.0;
    while t <= end {
        s.advance(1.0 / 60.0, 1.0);
        t += 1.0 / 60.0;
    }
    assert!((s.time_s() - end).abs() < 1e-12, "{} {end}", s.time_s());
    let crank = s.input_rad();
    assert!(
        (crank - stop_q).abs() < 1e-12,
        "crank {} deg, the run's stop {} deg",
        crank.to_degrees(),
        stop_q.to_degrees()
    );
    assert!((crank.to_degrees() - 35.0).abs() < 1e-6);
    let link1 = s.mechanism().link_index("link1").expect("link1");
    let drawn = s.pose().links[link1].angle_rad();
    assert!(
        (drawn - crank).rem_euclid(std::f64::consts::TAU) < 1e-9,
        "the drawn crank is at {} deg",
        drawn.to_degrees()
    );
    match s.force_polygons() {
        Some(Ok(_)) => {}
        other => panic!("no force polygons at the stop: {other:?}"),
    }
    s.apply(SceneEdit::SpringK {
        index: 0,
        n_per_m: 1200.0,
    });
    assert_eq!(s.message(), None);
    assert_eq!(s.time_s(), 0.0);
    let start = s.mechanism().driver.start_rad;
    assert!((s.input_rad() - start).abs() < 1e-12);
}

/// Every refusal a user meets on the shipped scenes, a length past what the chain
/// takes at either end of its slider or the crank sent out of its range, is worded
/// in the user's terms: the length's label, the scene's unit, the crank's angle,
/// and never the solver's (a dyad's kind, an assembly margin, a link's index).
#[test]
fn refusals_name_links_and_lengths_never_the_solvers_terms() {
    let inner = [
        "dyad", "margin", "RRR", "RRP", "RPR", "PRP", "group ", "spring 0",
    ];
    let check = |key: &str, what: &str, msg: &str| {
        for word in inner {
            assert!(!msg.contains(word), "{key}, {what}: {word:?} in {msg:?}");
        }
    };
    let mut refused = 0;
    for b in crate::catalog::BUILTIN_SCENES {
        let mut s = Session::open_builtin(b.key).expect("opens");
        let unit = unit_label(s.scene());
        for (i, p) in s.lengths().to_vec().iter().enumerate() {
            for value in [*p.range().start(), *p.range().end()] {
                s.apply(SceneEdit::Length { index: i, value });
                if let Some(msg) = s.message() {
                    check(b.key, &p.label, &msg);
                    assert!(msg.contains(&p.label) && msg.contains(unit), "{msg}");
                    refused += 1;
                }
                s.apply(SceneEdit::Reset);
            }
        }
        if !s.curves().full_rotation {
            let [lo, _] = s.input_range_deg();
            s.apply(SceneEdit::Input { deg: lo - 20.0 });
            let msg = s.message().expect("out of the crank's range");
            check(b.key, "crank", &msg);
            assert!(msg.contains("crank"), "{msg}");
            refused += 1;
        }
    }
    assert!(refused >= 10, "{refused} refusals seen");
}

/// The flipper's legend gives the run's time only with the run's pose: after the
/// crank is moved by hand the pose is no state of the run (it said t = 0.000 s at
/// any angle the slider set); the run's time shown again brings it back, and so
/// does an edit (which shows the run's start).
#[test]
fn the_run_time_goes_with_the_runs_pose_only() {
    let mut s = Session::open_builtin("gravity_flipper").expect("opens");
    s.wait_for_run();
    assert_eq!(s.run_time_shown(), Some(0.0), "opened at the run's start");
    s.apply(SceneEdit::RunTime { s: 0.1 });
    assert_eq!(s.run_time_shown(), Some(0.1));
    s.apply(SceneEdit::Input { deg: 80.0 });
    assert_eq!(s.run_time_shown(), None, "moved by hand");
    s.apply(SceneEdit::RunTime { s: 0.05 });
    assert_eq!(s.run_time_shown(), Some(0.05));
    s.apply(SceneEdit::Input { deg: 80.0 });
    s.apply(SceneEdit::SpringK {
        index: 0,
        n_per_m: 1400.0,
    });
    s.wait_for_run();
    assert_eq!(
        s.run_time_shown(),
        Some(0.0),
        "an edit shows the run's start"
    );
    assert_eq!(
        Session::open_builtin("die_cutter")
            .expect("opens")
            .run_time_shown(),
        None
    );
}

/// The edits a user can make that the model refuses: each length a hundredth and a
/// hundred times itself and negative, a spring's constant and a mass negative, the
/// crank at an angle that is no number and at each tenth of a turn.
fn refusable_edits(s: &Session) -> Vec<SceneEdit> {
    let mut edits = Vec::new();
    for (index, p) in s.lengths().iter().enumerate() {
        let v = p.value(s.scene()).expect("a length");
        for factor in [0.01, 100.0, -1.0] {
            edits.push(SceneEdit::Length {
                index,
                value: factor * v,
            });
        }
    }
    edits.push(SceneEdit::SpringK {
        index: 0,
        n_per_m: -1.0,
    });
    edits.push(SceneEdit::Mass { index: 1, kg: -1.0 });
    edits.push(SceneEdit::Input { deg: f64::NAN });
    edits.extend((0..10).map(|i| SceneEdit::Input {
        deg: 36.0 * f64::from(i) + 1.0,
    }));
    edits
}

/// Every refusal those edits give on every shipped scene reads in Chinese when the
/// user's language is Chinese: no English word but the scene's own names (and the
/// scene file's keys), never the solver's inner words.
#[test]
fn every_refused_edit_of_every_scene_reads_in_chinese() {
    use linkage_diagram::words::{Lang, english_words};
    let mut refused = 0;
    for b in crate::catalog::BUILTIN_SCENES {
        let fresh = Session::open_builtin(b.key).expect("opens");
        let scene = fresh.scene();
        let mut names: Vec<&str> = scene.links.iter().map(|l| l.name.as_str()).collect();
        names.extend(
            scene
                .links
                .iter()
                .flat_map(|l| l.points.keys().map(String::as_str)),
        );
        let mut s = Session::open_builtin(b.key).expect("opens");
        for edit in refusable_edits(&fresh) {
            s.apply(edit.clone());
            let Some(zh) = s.message_in(Lang::Chinese) else {
                // Taken: start the next edit from the scene as shipped.
                s = Session::open_builtin(b.key).expect("opens");
                continue;
            };
            refused += 1;
            let english = english_words(&zh, &names);
            assert!(english.is_empty(), "{}, {edit:?}: {zh}\n{english:?}", b.key);
            let en = s.message_in(Lang::English).expect("the same notice");
            assert_ne!(en, zh, "{}, {edit:?}", b.key);
        }
    }
    assert!(refused > 50, "only {refused} refusals met");
}
