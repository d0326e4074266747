//! `linkage exercise`: a class of 30 through the teacher's commands: the variants
//! (the key), each student's answer code made from typed answers, the class graded
//! from the codes with bad lines reported and the rest graded.

use crate::common;

use common::{repo, run_linkage};

fn temp(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("linkage-exercise-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("written");
    path.display().to_string()
}

fn ok(args: &[&str]) -> String {
    let (code, out, err) = run_linkage(args);
    assert_eq!(code, Some(0), "{args:?}: {err}");
    out
}

/// The key's rows: student, draws, the dimensions, the truths.
fn key(exercise: &str, class: &str) -> Vec<Vec<String>> {
    let out = ok(&["exercise", "variants", exercise, "--students", class]);
    out.lines()
        .skip(1)
        .map(|l| l.split(',').map(String::from).collect())
        .collect()
}

#[test]
fn a_class_of_thirty_is_graded_from_its_answer_codes() {
    let exercise = repo("assets/exercises/four_bar_instant_centres.ron");
    let numbers: Vec<String> = (1..=30).map(|i| format!("2026{i:03}")).collect();
    let class = temp(
        "class.csv",
        &format!("student,name\n{}\n", numbers.join(",x\n")),
    );
    let rows = key(&exercise, &class);
    assert_eq!(rows.len(), 30);
    // Student i answers every question right when i is even; an odd student gives
    // the second answer 20 % off and the others in other units of their kind.
    let mut codes = vec!["code".to_string()];
    for (i, row) in rows.iter().enumerate() {
        let truths: Vec<f64> = row[6..]
            .iter()
            .map(|t| t.parse().expect("number"))
            .collect();
        let wrong = if i % 2 == 1 { 1.2 } else { 1.0 };
        let answers = [
            format!("{}", truths[0] / 1000.0) + " m",
            format!("{}", truths[1] * wrong),
            format!("{}", truths[2]),
            format!("{} rpm", truths[3] * 60.0 / std::f64::consts::TAU),
            format!("{} mm/s", truths[4] * 1000.0),
        ];
        let mut args = vec!["exercise", "code", &exercise, "--student", &row[0]];
        for a in &answers {
            args.extend(["--answer", a.as_str()]);
        }
        codes.push(ok(&args).trim().to_string());
    }
    codes.push("LX1:fourbar-ic:00000000:2026001:1/2/3/4/5:00000000".into());
    codes.push(codes[3].replace("LX1:fourbar-ic", "LX1:fourbar-IC"));
    let answers = temp("answers.csv", &codes.join("\n"));
    let (code, out, err) = run_linkage(&[
        "exercise",
        "grade",
        &exercise,
        "--answers",
        &answers,
        "--students",
        &class,
    ]);
    assert_eq!(code, Some(0), "{err}");
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 31, "{out}");
    assert!(lines[0].ends_with(",score,out of,note"), "{}", lines[0]);
    for (i, line) in lines[1..].iter().enumerate() {
        let score = line.split(',').nth(21).expect("score");
        assert_eq!(score, if i % 2 == 1 { "4" } else { "5" }, "{line}");
    }
    // The two bad lines, each named with its line number and why.
    assert!(err.contains("line 32: the code is damaged"), "{err}");
    assert!(err.contains("line 33: the code is damaged"), "{err}");
}

#[test]
fn check_says_what_the_exercise_asks_and_that_every_trial_student_has_a_variant() {
    for file in [
        "die_cutter_slider",
        "four_bar_instant_centres",
        "cam_pressure_angle",
    ] {
        let out = ok(&[
            "exercise",
            "check",
            &repo(&format!("assets/exercises/{file}.ron")),
        ]);
        assert!(
            out.contains("students 1 to 100: every variant drawn"),
            "{out}"
        );
    }
}

#[test]
fn bad_input_is_refused_with_its_cause() {
    let exercise = repo("assets/exercises/die_cutter_slider.ron");
    let (code, _, err) = run_linkage(&[
        "exercise",
        "code",
        &exercise,
        "--student",
        "2026001",
        "--answer",
        "1 rad/s",
    ]);
    assert_eq!(code, Some(1));
    assert!(
        err.contains("1 answer given, the exercise asks 6 questions"),
        "{err}"
    );
    let six = [
        "--answer", "1 rad/s", "--answer", "1", "--answer", "1", "--answer", "1", "--answer", "1",
        "--answer", "1",
    ];
    let mut args = vec!["exercise", "code", &exercise, "--student", "2026001"];
    args.extend(six);
    let (_, _, err) = run_linkage(&args);
    assert!(
        err.contains("answer 1: \"rad/s\" is not a unit of this answer: give it in m/s"),
        "{err}"
    );
    let broken = temp("broken.ron", "Exercise(name: \"x\")");
    let (code, _, err) = run_linkage(&["exercise", "check", &broken]);
    assert_eq!(code, Some(1));
    assert!(err.contains("broken.ron"), "{err}");
    let class = temp("bad_class.csv", "student\n2026001\n2026 001\n");
    let (_, _, err) = run_linkage(&["exercise", "variants", &exercise, "--students", &class]);
    assert!(err.contains("line 3: student number \"2026 001\""), "{err}");
}

/// Every student's task sheet, a page each: as SVG pages (A4, each with its
/// student's number) and as one PDF.
#[test]
fn the_classes_task_sheets_are_a_page_a_student() {
    let exercise = repo("assets/exercises/die_cutter_slider.ron");
    let class = temp("sheet_class.csv", "student\n2026001\n2026002\n2026003\n");
    let dir = std::env::temp_dir().join(format!("linkage-tasks-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a folder");
    let svg = dir.join("task.svg").display().to_string();
    let pdf = dir.join("tasks.pdf").display().to_string();
    ok(&[
        "exercise",
        "sheets",
        &exercise,
        "--students",
        &class,
        "--svg",
        &svg,
        "--pdf",
        &pdf,
        "--lang",
        "zh-CN",
    ]);
    for (i, name) in ["task.svg", "task-2.svg", "task-3.svg"].iter().enumerate() {
        let page = std::fs::read_to_string(dir.join(name)).expect("a page a student");
        assert!(
            page.contains("width=\"210.0mm\" height=\"297.0mm\""),
            "{name}: A4"
        );
        assert!(
            page.contains(&format!("学号：202600{}", i + 1)),
            "{name}: its student"
        );
    }
    assert!(
        !dir.join("task-4.svg").exists(),
        "three students, three pages"
    );
    assert!(std::fs::read(&pdf).expect("the PDF").starts_with(b"%PDF"));
    let _ = std::fs::remove_dir_all(&dir);
}
