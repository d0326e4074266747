//! `linkage train FILE`: a gear train's every member speed from its inputs (the
//! file's, or `--input MEMBER RPM` given), the ratio of each to the first input,
//! Willis' converted ratios and a planetary set's assembly conditions; the members'
//! inertias reduced to one member and, with a load on one member, every member's
//! torque and power, on request. Text for a person, JSON for programs.

use std::fmt::Write as _;

use linkage::gears::train_file::{InputFile, TrainFile};
use linkage::gears::{AssemblyCheck, Train, TrainSolution, TrainTorques};
use linkage_diagram::numbers::significant;
use serde::Serialize;

use crate::args::{ReportFormat, TrainArgs};
use crate::error::{CliError, Result};

/// What `--format json` writes.
#[derive(Serialize)]
struct Json<'a> {
    solution: &'a TrainSolution,
    reduced_inertia_kg_m2: Option<f64>,
    torques: Option<&'a TrainTorques>,
}

/// Runs `linkage train`.
pub(crate) fn run(args: &TrainArgs) -> Result<String> {
    let (path, inputs, format) = (args.file.as_path(), &args.input, args.format);
    let reduce_to = args.reduce_to.as_deref();
    let text = std::fs::read_to_string(path).map_err(|source| CliError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    let mut file = TrainFile::from_ron(&text)
        .map_err(|e| CliError::in_file(path, CliError::refused(e.to_string())))?;
    if !inputs.is_empty() {
        file.inputs = given_inputs(inputs)?;
    }
    let refused =
        |e: linkage::gears::TrainError| CliError::in_file(path, CliError::refused(e.to_string()));
    let train = Train::new(file).map_err(refused)?;
    let s = train.solve().map_err(refused)?;
    let reduced = match reduce_to {
        Some(member) => Some(train.reduced_inertia_kg_m2(&s, member).ok_or_else(|| {
            CliError::refused(format!(
                "--reduce-to {member}: not a member of the train, or it stands still"
            ))
        })?),
        None => None,
    };
    let torques = match args.load.as_slice() {
        [member, value] => {
            let t = value
                .parse::<f64>()
                .ok()
                .filter(|t| t.is_finite())
                .ok_or_else(|| {
                    CliError::refused(format!(
                        "--load {member} {value}: the torque must be a number of N·m"
                    ))
                })?;
            Some(train.torques(&s, member, t).map_err(refused)?)
        }
        _ => None,
    };
    Ok(match format {
        ReportFormat::Json => {
            let json = Json {
                solution: &s,
                reduced_inertia_kg_m2: reduced,
                torques: torques.as_ref(),
            };
            serde_json::to_string_pretty(&json)? + "\n"
        }
        ReportFormat::Text => {
            let mut text = words(&s, reduce_to.zip(reduced));
            if let Some(t) = &torques {
                text += &torque_words(t);
            }
            text
        }
    })
}

/// Every member's torque and power with the load, and the housing's reaction.
fn torque_words(t: &TrainTorques) -> String {
    let losses = if t.lost_w == 0.0 {
        "ideal gears"
    } else {
        "with the file's efficiencies"
    };
    let mut out = format!(
        "with a load on {} ({losses})\n{:<24}{:>14}{:>14}\n",
        t.loaded, "member", "torque (N·m)", "power (W)"
    );
    for m in &t.members {
        let _ = writeln!(
            out,
            "{:<24}{:>14}{:>14}",
            m.member,
            significant(m.torque_n_m, 6),
            significant(m.power_w, 6)
        );
    }
    let _ = writeln!(
        out,
        "the frame (housing) takes {} N·m",
        significant(t.frame_n_m, 6)
    );
    // What goes in: the members taking power from outside (the motor's).
    let given: f64 = t.members.iter().map(|m| m.power_w.max(0.0)).sum();
    if t.lost_w != 0.0 && given > 0.0 {
        let _ = writeln!(
            out,
            "lost in the meshes and stages: {} W of the {} W put in (efficiency {})",
            significant(t.lost_w, 6),
            significant(given, 6),
            significant(1.0 - t.lost_w / given, 5)
        );
    }
    out
}

/// `--input MEMBER RPM` pairs as the file's inputs.
fn given_inputs(values: &[String]) -> Result<Vec<InputFile>> {
    values
        .chunks(2)
        .map(|pair| {
            let rpm = pair[1].parse::<f64>().map_err(|_| {
                CliError::refused(format!(
                    "--input {} {}: the speed must be a number of rpm",
                    pair[0], pair[1]
                ))
            })?;
            Ok(InputFile {
                member: pair[0].clone(),
                rpm,
            })
        })
        .collect()
}

/// The solution as a person reads it.
fn words(s: &TrainSolution, reduced: Option<(&str, f64)>) -> String {
    let mut out = String::new();
    let o = &mut out;
    let _ = writeln!(o, "{} ({} degree(s) of freedom)", s.name, s.dof);
    let first = s.speeds_rpm.first().map(|m| m.member.clone());
    let _ = writeln!(
        o,
        "{:<24}{:>14}{:>16}",
        "member", "speed (rpm)", "ratio to first"
    );
    for speed in &s.speeds_rpm {
        let (name, rpm) = (&speed.member, &speed.rpm);
        let ratio = first
            .as_deref()
            .and_then(|f| s.ratio(f, name))
            .filter(|r| r.is_finite())
            .map_or("-".into(), |r| significant(r, 6));
        let _ = writeln!(o, "{name:<24}{:>14}{ratio:>16}", significant(*rpm, 6));
    }
    for w in &s.willis {
        let _ = writeln!(
            o,
            "Willis ratio i^{}({}, {}) = {}",
            w.carrier,
            w.from,
            w.to,
            significant(w.ratio, 6)
        );
    }
    for check in &s.assembly {
        let _ = writeln!(o, "{}", check_words(check));
    }
    if let Some((member, j)) = reduced {
        let _ = writeln!(
            o,
            "inertia reduced to {member}: {} kg·m²",
            significant(j, 4)
        );
    }
    out
}

fn check_words(c: &AssemblyCheck) -> String {
    let mark = |holds: bool| if holds { "holds" } else { "FAILS" };
    match c {
        AssemblyCheck::Coaxial {
            carrier,
            distances_modules,
            holds,
        } => format!(
            "{carrier}: coaxiality {} (planet centres at {} modules)",
            mark(*holds),
            distances_modules
                .iter()
                .map(|d| significant(*d, 6))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        AssemblyCheck::EqualSpacing {
            carrier,
            planets,
            value,
            holds,
        } => format!(
            "{carrier}: equal spacing of {planets} planets {} ((z_sun + z_ring)/k = {})",
            mark(*holds),
            significant(*value, 6)
        ),
        AssemblyCheck::Neighbours {
            carrier,
            planets,
            clearance_modules,
            holds,
        } => format!(
            "{carrier}: {planets} neighbouring planets clear {} (gap {} modules)",
            mark(*holds),
            significant(*clearance_modules, 4)
        ),
    }
}
