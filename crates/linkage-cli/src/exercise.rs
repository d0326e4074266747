//! `linkage exercise`: an exercise file checked, the class's variants (the teacher's
//! key), a student's answer code, and the class graded from its codes.

use std::fmt::Write as _;
use std::path::Path;

use linkage_diagram::numbers::significant;
use linkage_diagram::pages::Sheet;
use linkage_diagram::words::Lang;
use linkage_model::exercise::class_list::class_list;
use linkage_model::exercise::code::{AnswerSheet, typed_answer};
use linkage_model::exercise::error::requirement_words;
use linkage_model::exercise::words::{self, plain};
use linkage_model::exercise::{Exercise, Mode, StudentId};

use crate::args::ExerciseCommand;
use crate::error::{CliError, Result};
use crate::io::records_to_csv;

/// Runs one `exercise` command.
pub(crate) fn run(command: ExerciseCommand) -> Result<String> {
    match command {
        ExerciseCommand::Check { file } => check(&read_exercise(&file)?),
        ExerciseCommand::Variants { file, students } => {
            variants(&read_exercise(&file)?, &read_class(&students)?)
        }
        ExerciseCommand::Sheets {
            file,
            students,
            out,
        } => {
            let sheet = sheets(&read_exercise(&file)?, &read_class(&students)?, out.lang)?;
            crate::diagram::write_sheet(sheet, &out)
        }
        ExerciseCommand::Code {
            file,
            student,
            answer,
        } => code(&read_exercise(&file)?, &student, &answer),
        ExerciseCommand::Grade {
            file,
            answers,
            students,
            out,
        } => grade(
            &read_exercise(&file)?,
            &answers,
            students.as_deref(),
            out.as_deref(),
        ),
    }
}

/// Every student's task sheet, one after another.
fn sheets(ex: &Exercise, class: &[StudentId], lang: Lang) -> Result<Sheet> {
    let mut pages = Vec::new();
    for student in class {
        pages.extend(ex.task_sheet(&ex.variant(student)?, lang).pages);
    }
    Ok(Sheet {
        title: ex.file.name.clone(),
        pages,
    })
}

/// The grades CSV of the codes in `answers` (to `out`, or returned); each line not
/// graded said on stderr.
fn grade(
    ex: &Exercise,
    answers: &Path,
    students: Option<&Path>,
    out: Option<&Path>,
) -> Result<String> {
    let class = students.map(read_class).transpose()?;
    let graded = ex.grade_class(&read(answers)?, class.as_deref());
    for (line, why) in &graded.problems {
        eprintln!("{}: line {line}: {why}", answers.display());
    }
    let csv = ex.grades_csv(&graded.grades);
    let Some(path) = out else { return Ok(csv) };
    std::fs::write(path, csv).map_err(|source| CliError::Write {
        path: path.to_path_buf(),
        source,
    })?;
    Ok(format!(
        "{} students graded, {} lines not graded; grades in {}\n",
        graded.grades.len(),
        graded.problems.len(),
        path.display()
    ))
}

fn read(path: &Path) -> Result<String> {
    std::fs::read_to_string(path).map_err(|source| CliError::Read {
        path: path.to_path_buf(),
        source,
    })
}

fn read_exercise(path: &Path) -> Result<Exercise> {
    Exercise::parse(&read(path)?).map_err(|e| CliError::in_file(path, CliError::from(e)))
}

fn read_class(path: &Path) -> Result<Vec<StudentId>> {
    class_list(&read(path)?).map_err(|e| CliError::in_file(path, CliError::refused(e.to_string())))
}

/// What the exercise asks, what varies, and a trial of a hundred student numbers.
fn check(ex: &Exercise) -> Result<String> {
    let f = &ex.file;
    let mut t = String::new();
    let mode = match f.mode {
        Mode::Homework => "homework: each answer marked as it is typed",
        Mode::Test => "test: answers marked when graded",
    };
    let _ = writeln!(t, "{} (id {}; {mode})", f.name, f.id);
    let _ = writeln!(
        t,
        "answer codes carry the fingerprint {:08X}",
        ex.fingerprint()
    );
    for (i, v) in f.vary.iter().enumerate() {
        if let Some((first, last, step, count)) = ex.value_range(i) {
            let unit = ex.vary_unit(v);
            let [a, b, s] = [first, last, step].map(|x| significant(x, 10));
            let _ = writeln!(
                t,
                "varies: {} from {a} to {b} {unit} in steps of {s} ({count} values)",
                v.label()
            );
        }
    }
    for r in &f.require {
        let _ = writeln!(t, "requires: {}", requirement_words(r));
    }
    for (i, q) in f.questions.iter().enumerate() {
        let unit = match q.unit.symbol() {
            "" => "no unit".to_string(),
            s => format!("in {s}"),
        };
        let tolerance = plain(&words::tolerance(q.tolerance, q.unit));
        let points = if q.points == 1.0 {
            "1 point".into()
        } else {
            format!("{} points", significant(q.points, 6))
        };
        let asked = plain(&words::question(&q.ask, &ex.subject, Lang::English));
        let _ = writeln!(
            t,
            "question {}: {asked}, {unit}, right within {tolerance}, {points}",
            i + 1
        );
    }
    let mut most = 0;
    for n in 1..=100 {
        let student = StudentId::parse(&n.to_string()).expect("a number");
        most = most.max(ex.variant(&student)?.draws);
    }
    let draws = if most == 1 {
        "1 draw".to_string()
    } else {
        format!("{most} draws")
    };
    let _ = writeln!(
        t,
        "students 1 to 100: every variant drawn, at most {draws} for one"
    );
    Ok(t)
}

/// Each student's dimensions and true answers, as CSV.
fn variants(ex: &Exercise, class: &[StudentId]) -> Result<String> {
    let mut header = vec!["student".to_string(), "draws".to_string()];
    header.extend(
        ex.file
            .vary
            .iter()
            .map(|v| format!("{} ({})", v.label(), ex.vary_unit(v))),
    );
    header.extend(
        ex.file
            .questions
            .iter()
            .enumerate()
            .map(|(i, q)| match q.unit.symbol() {
                "" => format!("q{}", i + 1),
                unit => format!("q{} ({unit})", i + 1),
            }),
    );
    let mut rows = Vec::new();
    for student in class {
        let v = ex.variant(student)?;
        let mut row = vec![student.to_string(), v.draws.to_string()];
        row.extend(v.values.iter().map(|&x| significant(x, 10)));
        row.extend(v.truths.iter().map(|&x| significant(x, 6)));
        rows.push(row);
    }
    records_to_csv(&header, &rows)
}

/// The answer code of answers typed with their units.
fn code(ex: &Exercise, student: &str, typed: &[String]) -> Result<String> {
    let student = StudentId::parse(student).map_err(|e| CliError::refused(e.to_string()))?;
    let questions = &ex.file.questions;
    if typed.len() != questions.len() {
        return Err(CliError::refused(format!(
            "{} given, the exercise asks {} questions (--answer \"\" for one not answered)",
            match typed.len() {
                1 => "1 answer".to_string(),
                n => format!("{n} answers"),
            },
            questions.len()
        )));
    }
    let answers = typed
        .iter()
        .zip(questions)
        .enumerate()
        .map(|(i, (text, q))| match text.trim() {
            "" => Ok(None),
            t => typed_answer(t, q.unit)
                .map(Some)
                .map_err(|e| CliError::refused(format!("answer {}: {e}", i + 1))),
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(format!(
        "{}\n",
        ex.answer_code(&AnswerSheet { student, answers })
    ))
}
