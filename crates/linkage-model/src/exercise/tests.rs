//! The shipped exercises' variants, truths, codes and grades, checked against the
//! analyses outside exercise mode and against closed forms written here.

use linkage::cam::CamSpec;
use linkage::{Kinematics, Mechanism, SceneFile};

use super::code::{AnswerSheet, CodeError, TypedAnswerError, typed_answer};
use super::grade::LineError;
use super::*;

const DIE: &str = include_str!("../../../../assets/exercises/die_cutter_slider.ron");
const FOUR_BAR: &str = include_str!("../../../../assets/exercises/four_bar_instant_centres.ron");
const CAM: &str = include_str!("../../../../assets/exercises/cam_pressure_angle.ron");

fn student(n: u32) -> StudentId {
    StudentId::parse(&format!("2026{n:03}")).expect("as set up")
}

fn scene_of(v: &Variant) -> &SceneFile {
    match &v.subject {
        SubjectData::Scene(s) => s,
        SubjectData::Cam(_) => panic!("a mechanism"),
    }
}

#[test]
fn every_shipped_exercise_gives_every_student_a_variant_the_same_each_time() {
    for text in [DIE, FOUR_BAR, CAM] {
        let ex = Exercise::parse(text).expect("as set up");
        let mut distinct = Vec::new();
        for n in 1..=60 {
            let v = ex.variant(&student(n)).expect("as set up");
            assert_eq!(
                ex.variant(&student(n)).expect("as set up"),
                v,
                "{}: drawn twice",
                ex.file.id
            );
            assert!(v.truths.iter().all(|t| t.is_finite()));
            if !distinct.contains(&v.values) {
                distinct.push(v.values.clone());
            }
        }
        // Copying is hard: at most a few of 60 students share their dimensions.
        assert!(
            distinct.len() >= 50,
            "{}: {} distinct of 60",
            ex.file.id,
            distinct.len()
        );
    }
}

/// The variants are pinned: the same student number gives the same dimensions in
/// every release and on every machine (the browser included), so these numbers may
/// change only with the file.
#[test]
fn a_students_dimensions_are_pinned_to_the_file_and_the_number() {
    let ex = Exercise::parse(DIE).expect("as set up");
    let v = ex.variant(&student(1)).expect("as set up");
    assert_eq!(v.values, [80.5, 188.0, 40.0]);
    assert_eq!(v.draws, 3);
    // Whole multiples of the step: the numbers a student reads are round.
    for (x, vary) in v.values.iter().zip(&ex.file.vary) {
        let step = match vary.values() {
            Values::Range { step, .. } | Values::Around { step, .. } => *step,
        };
        assert_eq!((x / step).round() * step, *x);
    }
}

#[test]
fn the_variants_meet_the_requirements() {
    let ex = Exercise::parse(FOUR_BAR).expect("as set up");
    for n in 1..=40 {
        let v = ex.variant(&student(n)).expect("as set up");
        let mut k = Kinematics::new(Mechanism::from_scene(scene_of(&v)).expect("as set up"))
            .expect("as set up");
        let g = linkage::analysis::grashof(&k).expect("as set up");
        assert_eq!(g.class, linkage::analysis::GrashofClass::CrankRocker);
        let report = linkage::analysis::report(&mut k).expect("as set up");
        assert!(
            report
                .transmission_angle_rad
                .expect("as set up")
                .min
                .to_degrees()
                >= 30.0
        );
    }
}

/// The die's speed against the positions' finite differences (not the velocity
/// solution), its stroke against the positions swept, each relative to its size.
#[test]
fn the_die_cutters_truths_agree_with_finite_differences_of_positions() {
    let ex = Exercise::parse(DIE).expect("as set up");
    for n in 1..=10 {
        let v = ex.variant(&student(n)).expect("as set up");
        let mut k = Kinematics::new(Mechanism::from_scene(scene_of(&v)).expect("as set up"))
            .expect("as set up");
        let e = k.mechanism().point_index("E").expect("as set up");
        let omega = k.mechanism().driver.speed_rad_s;
        let y = |k: &mut Kinematics, deg: f64| {
            k.solve(deg.to_radians()).expect("as set up").points[e].position
        };
        let h = 1e-4_f64;
        for (q, deg) in [(0, 30.0), (3, 240.0)] {
            let d = (y(&mut k, deg + h.to_degrees()) - y(&mut k, deg - h.to_degrees())) / (2.0 * h);
            let speed = d.norm() * omega.abs();
            assert!(
                (v.truths[q] - speed).abs() < 1e-6 * speed,
                "student {n} q{}: {} vs {speed}",
                q + 1,
                v.truths[q]
            );
        }
        let heights: Vec<f64> = (0..3600).map(|i| y(&mut k, f64::from(i) * 0.1).y).collect();
        let stroke_mm = 1e3
            * (heights.iter().copied().fold(f64::MIN, f64::max)
                - heights.iter().copied().fold(f64::MAX, f64::min));
        assert!(
            (v.truths[4] - stroke_mm).abs() < 1e-4 * stroke_mm,
            "{} vs {stroke_mm}",
            v.truths[4]
        );
    }
}

/// Kennedy's theorem as the students use it: the coupler turns about its centre with
/// the frame, P13, so ω3 = ω2·AB / |P13 B| in size, and E's speed is ω3·|P13 E|.
#[test]
fn the_four_bars_angular_velocities_follow_from_its_instant_centre() {
    let ex = Exercise::parse(FOUR_BAR).expect("as set up");
    for n in 1..=10 {
        let v = ex.variant(&student(n)).expect("as set up");
        let mut k = Kinematics::new(Mechanism::from_scene(scene_of(&v)).expect("as set up"))
            .expect("as set up");
        let s = k.solve(60f64.to_radians()).expect("as set up");
        let m = k.mechanism();
        let at = |name: &str| s.points[m.point_index(name).expect("as set up")].position * 1e3;
        let p13 = linkage::Vec2::new(v.truths[0], v.truths[1]);
        let (a, b, e) = (at("A"), at("B"), at("E"));
        let w2 = m.driver.speed_rad_s;
        let w3 = w2 * (b - a).norm() / (b - p13).norm();
        assert!(
            (v.truths[2].abs() - w3).abs() < 1e-9 * w3,
            "{} vs {w3}",
            v.truths[2]
        );
        let v_e = w3 * (e - p13).norm() * 1e-3;
        assert!(
            (v.truths[4] - v_e).abs() < 1e-9 * v_e,
            "{} vs {v_e}",
            v.truths[4]
        );
    }
}

/// The cam's truths are the cam analysis of the cam with the student's values
/// written in, and its largest pressure angle is no smaller than any sampled one.
#[test]
fn the_cams_truths_are_the_cam_analysis_of_the_students_cam() {
    let ex = Exercise::parse(CAM).expect("as set up");
    for n in 1..=10 {
        let v = ex.variant(&student(n)).expect("as set up");
        let SubjectData::Cam(cam) = &v.subject else {
            panic!("a cam")
        };
        let written = CamSpec::from_ron(&ron::to_string(cam.as_ref()).expect("as set up"))
            .expect("as set up");
        assert_eq!(written.base_radius_mm, v.values[0]);
        let design = written.design().expect("as set up");
        let sampled = (0..7200)
            .map(|i| {
                design
                    .cam
                    .at(f64::from(i) * std::f64::consts::TAU / 7200.0)
                    .pressure_angle_rad
                    .abs()
            })
            .fold(0.0, f64::max)
            .to_degrees();
        assert!(
            v.truths[0] >= sampled - 1e-9 && v.truths[0] - sampled < 0.01,
            "{} vs {sampled}",
            v.truths[0]
        );
        assert!(v.truths[0] <= 35.0);
    }
}

#[test]
fn an_answer_code_reads_back_the_answers_and_refuses_what_is_not_its_own() {
    let ex = Exercise::parse(DIE).expect("as set up");
    let sheet = AnswerSheet {
        student: student(7),
        answers: vec![
            Some(0.1062),
            Some(-1e-7),
            None,
            Some(12.5),
            Some(53.0),
            Some(1.3),
        ],
    };
    let code = ex.answer_code(&sheet);
    assert_eq!(ex.read_code(&code), Ok(sheet.clone()));
    // Among other text, as pasted into a CSV or an e-mail.
    assert_eq!(
        ex.read_code(&format!("\"Li Lei\",{code},extra")),
        Ok(sheet.clone())
    );
    // One character changed anywhere: damaged.
    for i in 4..code.len() {
        let mut bytes = code.clone().into_bytes();
        bytes[i] = if bytes[i] == b'1' { b'2' } else { b'1' };
        let changed = String::from_utf8(bytes).expect("as set up");
        assert!(ex.read_code(&changed).is_err(), "{changed} read");
    }
    assert_eq!(ex.read_code("no code here"), Err(CodeError::NotACode));
    let other =
        Exercise::parse(&DIE.replace("id: \"die-slider\"", "id: \"die-2\"")).expect("as set up");
    assert_eq!(
        other.read_code(&code),
        Err(CodeError::OtherExercise("die-slider".into()))
    );
    // A question asked at another angle: the answers mean something else.
    let edited =
        Exercise::parse(&DIE.replacen("crank_deg: 30.0", "crank_deg: 31.0", 1)).expect("as set up");
    assert_eq!(edited.read_code(&code), Err(CodeError::OtherVersion));
    // A tolerance widened, a title mended after the codes came in: still graded,
    // and every student keeps the variant.
    let mended = DIE
        .replace("Relative(0.03)", "Relative(0.04)")
        .replace("Die cutter:", "The die cutter:");
    let mended = Exercise::parse(&mended).expect("as set up");
    assert_eq!(mended.read_code(&code), Ok(sheet.clone()));
    assert_eq!(
        mended.variant(&student(7)).expect("a variant").values,
        ex.variant(&student(7)).expect("a variant").values
    );
}

#[test]
fn typed_answers_convert_units_of_their_kind_and_refuse_others() {
    let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
    assert!(close(
        typed_answer("1250 mm/s", Unit::MetrePerSecond).expect("as set up"),
        1.25
    ));
    assert!(close(
        typed_answer("1,25", Unit::MetrePerSecond).expect("as set up"),
        1.25
    ));
    assert!(close(
        typed_answer("-3.5e-1 rad/s", Unit::RadianPerSecond).expect("as set up"),
        -0.35
    ));
    assert!(close(
        typed_answer("30°", Unit::Degree).expect("as set up"),
        30.0
    ));
    assert_eq!(
        typed_answer("1.25 rad/s", Unit::MetrePerSecond),
        Err(TypedAnswerError::Unit {
            typed: "rad/s".into(),
            expected: Unit::MetrePerSecond
        })
    );
    assert!(matches!(
        typed_answer("fast", Unit::MetrePerSecond),
        Err(TypedAnswerError::NotANumber(_))
    ));
}

#[test]
fn grading_is_right_just_inside_the_tolerance_and_wrong_just_outside() {
    let ex = Exercise::parse(DIE).expect("as set up");
    let v = ex.variant(&student(3)).expect("as set up");
    let t = &v.truths;
    // q1 relative 3 %, q6 absolute 0.03.
    let sheet = |a1: f64, a6: f64| AnswerSheet {
        student: student(3),
        answers: vec![Some(a1), None, None, None, None, Some(a6)],
    };
    let g = ex.grade(&sheet(t[0] * (1.0 + 0.03 * 0.999), t[5] - 0.03 * 0.999), &v);
    assert!(g.marked[0].right && g.marked[5].right);
    assert!(!g.marked[1].right, "not answered is not right");
    assert_eq!((g.score, g.out_of), (2.0, 6.0));
    let g = ex.grade(&sheet(t[0] * (1.0 - 0.03 * 1.001), t[5] + 0.03 * 1.001), &v);
    assert!(!g.marked[0].right && !g.marked[5].right);
}

#[test]
fn a_class_is_graded_line_by_line_with_the_bad_lines_named() {
    let ex = Exercise::parse(DIE).expect("as set up");
    let class: Vec<StudentId> = (1..=4).map(student).collect();
    let code = |n: u32, a: f64| {
        let v = ex.variant(&student(n)).expect("as set up");
        let answers = v.truths.iter().map(|t| Some(t * a)).collect();
        ex.answer_code(&AnswerSheet {
            student: student(n),
            answers,
        })
    };
    let damaged = code(2, 1.0).replacen("2026002", "2026003", 1);
    let text = [
        "name,code".to_string(),
        code(1, 1.0),
        damaged,
        code(2, 1.5),
        code(2, 1.0),
        code(9, 1.0),
    ]
    .join("\n");
    let graded = ex.grade_class(&text, Some(&class));
    let problems: Vec<(usize, &LineError)> = graded.problems.iter().map(|(n, e)| (*n, e)).collect();
    assert!(
        matches!(problems[0], (3, LineError::Code(CodeError::Damaged))),
        "{problems:?}"
    );
    assert!(
        matches!(problems[1], (4, LineError::Superseded(_))),
        "{problems:?}"
    );
    assert!(
        matches!(problems[2], (6, LineError::NotOnList(_))),
        "{problems:?}"
    );
    let scores: Vec<(f64, bool)> = graded.grades.iter().map(|g| (g.score, g.no_code)).collect();
    assert_eq!(
        scores,
        [(6.0, false), (6.0, false), (0.0, true), (0.0, true)]
    );
    let csv = ex.grades_csv(&graded.grades);
    assert!(
        csv.starts_with("student,q1 answer (m/s),q1 truth (m/s),q1 error (m/s),q1 right,"),
        "{csv}"
    );
    assert_eq!(csv.lines().count(), 5);
}

#[test]
fn an_exercise_no_variant_can_meet_is_refused_with_the_requirement_and_how_often() {
    let text = FOUR_BAR.replace(
        "LeastTransmissionAngleDeg(30.0)",
        "LeastTransmissionAngleDeg(80.0)",
    );
    let ex = Exercise::parse(&text).expect("as set up");
    let Err(ExerciseError::NoVariant {
        draws,
        cause,
        times,
        ..
    }) = ex.variant(&student(1))
    else {
        panic!("a variant met 80 deg");
    };
    assert_eq!(draws, variant::MOST_DRAWS);
    assert!(
        matches!(
            cause,
            DrawFailure::Requirement {
                requirement: file::Requirement::LeastTransmissionAngleDeg(_),
                measured: Some(_)
            }
        ),
        "{cause:?}"
    );
    assert!(times > draws / 2, "{times}");
    assert!(
        ex.variant(&student(1))
            .expect_err("refused")
            .to_string()
            .contains("least transmission angle >= 80 deg")
    );
}

#[test]
fn a_bad_exercise_file_is_refused_with_what_and_where() {
    let err = |text: String| Exercise::parse(&text).expect_err("refused");
    let e = err(FOUR_BAR.replace("length: \"BC\"", "length: \"XY\""));
    assert!(
        matches!(&e, ExerciseError::UnknownLength { index: 2, known, .. } if known.contains(&"BC".to_string())),
        "{e:?}"
    );
    let e = err(FOUR_BAR.replace("unit: \"rad/s\"", "unit: \"mm\""));
    assert!(
        matches!(e, ExerciseError::UnitKind { question: 3, .. }),
        "{e:?}"
    );
    let e = err(FOUR_BAR.replace("unit: \"rad/s\"", "unit: \"furlong\""));
    assert!(e.to_string().contains("unknown unit \"furlong\""), "{e}");
    let e = err(DIE.replace("Scene(\"die_cutter\")", "Scene(\"die_cuter\")"));
    assert!(
        matches!(&e, ExerciseError::UnknownSubject { known, .. } if known.contains(&"die_cutter".to_string())),
        "{e:?}"
    );
    let e = err(DIE.replace(
        "point: \"E\", crank_deg: 240.0",
        "point: \"Q\", crank_deg: 240.0",
    ));
    assert!(
        matches!(e, ExerciseError::Question { question: 4, .. }),
        "{e:?}"
    );
    let e = err(DIE.replace("id: \"die-slider\"", "id: \"die slider\""));
    assert!(matches!(e, ExerciseError::Id(_)), "{e:?}");
    let e = err(FOUR_BAR.replace("step: 5.0", "step: 0.0"));
    assert!(matches!(e, ExerciseError::Values { index: 1, .. }), "{e:?}");
    let e = err(CAM.replace("Offset(values", "CrankRpm(values"));
    assert!(
        matches!(e, ExerciseError::NoDimension { index: 3, .. }),
        "{e:?}"
    );
    assert!(matches!(
        err("Exercise(".into()),
        ExerciseError::Syntax { .. }
    ));
}

/// What a sheet's reader reads: the text of its `<text>` elements, their marks
/// (subscripts' `<tspan>`) left out. Not the drawing's coordinates, whose digits
/// can be anything (a cam's profile point at y = 332.25 px held a student's 32.25°).
fn sheet_words(pages: &[String]) -> String {
    let mut words = String::new();
    for page in pages {
        for element in page.split("<text").skip(1) {
            let inner = element.split("</text>").next().unwrap_or_default();
            let mut in_tag = true;
            for c in inner.chars() {
                match c {
                    '<' => in_tag = true,
                    '>' => in_tag = false,
                    c if !in_tag => words.push(c),
                    _ => {}
                }
            }
            words.push('\n');
        }
    }
    words
}

/// The task sheet carries the student's number, the student's own data and every
/// question, in the language asked for, on A4 pages; a cam's sheet has no drawing
/// of a mechanism.
#[test]
fn a_task_sheet_holds_the_students_data_and_questions_in_their_language() {
    use linkage_diagram::words::Lang;
    let ex = Exercise::parse(DIE).expect("as set up");
    let v = ex.variant(&student(1)).expect("as set up");
    let zh = ex.task_sheet(&v, Lang::Chinese);
    let text = zh.pages.join("");
    assert!(
        zh.pages
            .iter()
            .all(|p| p.contains("width=\"210.0mm\" height=\"297.0mm\""))
    );
    assert!(text.contains("学号：2026001"), "the number");
    assert!(
        text.contains("80.5 mm") && text.contains("188 mm"),
        "AB and BC of this student"
    );
    assert!(text.contains("行程速比系数 K"), "the questions in Chinese");
    let words = sheet_words(&zh.pages);
    assert!(words.contains("学号：2026001"), "the words read");
    for t in &v.truths {
        let shown = linkage_diagram::numbers::significant(*t, 4);
        assert!(!words.contains(&shown), "the truth {shown} on the sheet");
    }
    let cam = Exercise::parse(CAM).expect("as set up");
    let v = cam.variant(&student(1)).expect("as set up");
    let sheet = cam.task_sheet(&v, Lang::English);
    let text = sheet.pages.join("");
    let words = sheet_words(&sheet.pages);
    assert!(words.contains("Largest pressure angle"), "the words read");
    // The cam drawn (its profile a polygon), and neither its extremes nor the
    // marks of where the pressure angle passes a limit: the answers.
    assert!(text.contains("<polygon"), "the cam drawn");
    for t in &v.truths {
        let shown = linkage_diagram::numbers::significant(*t, 4);
        assert!(
            !words.contains(&shown),
            "the truth {shown} on the cam's sheet"
        );
    }
    assert!(
        !text.contains("#c0392b"),
        "a pressure-angle mark on the cam's sheet"
    );
}

/// An in-line slider-crank whose crank and rod are drawn from overlapping ranges:
/// a crank longer than the rod does not turn (refused by the requirement), one as
/// long as the rod folds flat at a change point (redrawn: its stroke came out 0);
/// every variant's stroke is the closed form 2·AB.
const SLIDER_CRANK: &str = r#"Exercise(
    name: "Slider-crank", id: "sc", mode: Homework, subject: Scene("slider_crank"),
    vary: [
        Length(length: "AB", values: Range(min: 150.0, max: 250.0, step: 10.0)),
        Length(length: "BC", values: Around(spread: 0.1, step: 5.0)),
    ],
    require: [FullRotation],
    questions: [(ask: Stroke(output: "slider"), unit: "mm", tolerance: Absolute(1.0))],
)"#;

#[test]
fn a_variant_that_folds_flat_is_drawn_again_and_strokes_are_twice_the_crank() {
    let ex = Exercise::parse(SLIDER_CRANK).expect("as set up");
    let mut redrawn = false;
    for n in 1..=60 {
        let v = ex.variant(&student(n)).expect("a variant");
        let (ab, bc) = (v.values[0], v.values[1]);
        assert!(ab < bc, "student {n}: AB {ab} BC {bc}");
        assert!(
            (v.truths[0] - 2.0 * ab).abs() < 1e-9 * ab,
            "student {n}: stroke {} for AB {ab}",
            v.truths[0]
        );
        redrawn |= v.draws > 1;
    }
    assert!(redrawn, "some student's first draws were refused");
}

#[test]
fn what_a_teacher_gets_wrong_is_refused_with_its_cause() {
    let err = |text: String| Exercise::parse(&text).expect_err("refused");
    let e = err(SLIDER_CRANK.replace("require: [FullRotation]", "require: [Grashof(CrankRocker)]"));
    assert!(
        matches!(e, ExerciseError::Requirement { index: 1, .. }),
        "{e:?}"
    );
    assert!(e.to_string().contains("four-bar"), "{e}");
    let e = err(FOUR_BAR.replacen("crank_deg: 60.0", "crank_deg: 400.0", 1));
    assert!(
        matches!(e, ExerciseError::CrankAngle { question: 1, .. }),
        "{e:?}"
    );
    let e = err(FOUR_BAR.replace("link: \"rocker\"", "link: \"ground\""));
    assert!(
        e.to_string().contains("is the frame: it does not move"),
        "{e}"
    );
    let e = err(FOUR_BAR.replace("link: \"rocker\"", "link: \"rockr\""));
    assert!(
        e.to_string()
            .contains("(the links: ground, crank, coupler, rocker)"),
        "{e}"
    );
    let e = err(FOUR_BAR.replace("unit: \"rad/s\"", "unit: \"m/s\""));
    assert!(
        e.to_string().contains("give one of \"rad/s\", \"rpm\""),
        "{e}"
    );
    let e = err(FOUR_BAR.replace("min: 80.0, max: 120.0", "min: 120.0, max: 80.0"));
    assert!(e.to_string().contains("min is above max"), "{e}");
    let e = err(FOUR_BAR.replace("min: 80.0, max: 120.0", "min: 80.0, max: 84.0"));
    assert!(e.to_string().contains("would not vary"), "{e}");
}

/// A link with no role of its own is named by the joints it carries, as the textbooks
/// name it ("link CE", "构件 CE"), on the sheet and in the app alike: never by the
/// scene's inner name (`link_ce`, which the questions' words showed before).
#[test]
fn a_link_without_a_role_is_named_by_its_joints() {
    use linkage_diagram::words::Lang;
    let rocker = r#"AngularVelocity(link: "rocker", crank_deg: 30.0)"#;
    assert!(DIE.contains(rocker), "as set up");
    let text = DIE.replace(
        rocker,
        r#"AngularVelocity(link: "link_ce", crank_deg: 30.0)"#,
    );
    let ex = Exercise::parse(&text).expect("link_ce is the die cutter's link CE");
    let asked = |lang| {
        let q = ex.file.questions.iter().find(
            |q| matches!(&q.ask, Quantity::AngularVelocity { link, .. } if link == "link_ce"),
        );
        words::question(&q.expect("asked").ask, &ex.subject, lang)
    };
    let (en, zh) = (asked(Lang::English), asked(Lang::Chinese));
    assert!(en.contains("link CE") && !en.contains("link_ce"), "{en}");
    assert!(zh.contains("构件 CE") && !zh.contains("link_ce"), "{zh}");
    let sheet = ex.task_sheet(&ex.variant(&student(1)).expect("as set up"), Lang::Chinese);
    assert!(
        sheet_words(&sheet.pages).contains("构件 CE"),
        "on the sheet"
    );
}
