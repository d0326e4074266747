//! The commands without a file of their own (sweep, at, report, share, synth): each
//! writes its output as it goes (a sweep row by row), or fails with a `CliError`; a
//! failed write is kept apart so that a closed pipe ends quietly.

use std::io::Write;

use linkage::sweep::{csv_header, csv_row};
use linkage::synthesis::{DieCutterSpec, crank_rocker, die_cutter, die_cutter_as_printed};
use linkage::{Kinematics, LinkId, Mechanism, Solution};
use serde_json::{Value, json};

use crate::args::{Format, ReportFormat, SceneArgs, SynthCommand};
use crate::error::{CliError, Result};
use crate::io::{check_finite, describe, json_text, length_unit, load, to_csv};

/// A CSV writer's failure: a failed write (a closed pipe) is the output's.
fn csv_failure(e: csv::Error) -> CliError {
    if !e.is_io_error() {
        return CliError::Csv(e);
    }
    match e.into_kind() {
        csv::ErrorKind::Io(io) => CliError::Output(io),
        other => CliError::refused(format!("cannot write CSV: {other:?}")),
    }
}

/// Most rows `sweep` writes as CSV (streamed: memory stays flat) and as JSON (held
/// whole: about 1 kB a row).
pub const MAX_CSV_STEPS: usize = 100_000_000;
/// See [`MAX_CSV_STEPS`].
pub const MAX_JSON_STEPS: usize = 100_000;

/// `share SCENE`: the fragment for the scene (checked to load first); `share --decode
/// LINK`: the scene text it carries, exactly.
pub(crate) fn share(scene: Option<&std::path::Path>, decode: Option<&str>) -> Result<String> {
    if let Some(link) = decode {
        return Ok(linkage::share::decode(link)?);
    }
    let path = scene.ok_or_else(|| CliError::refused("give a scene file, or --decode LINK"))?;
    let text = std::fs::read_to_string(path).map_err(|source| CliError::ReadScene {
        path: path.to_path_buf(),
        source,
    })?;
    Mechanism::from_ron(&text).map_err(|e| CliError::in_file(path, e))?;
    let payload = linkage::share::encode(&text)?;
    Ok(format!("{}={payload}\n", linkage::share::FRAGMENT_KEY))
}

pub(crate) fn sweep(
    args: &SceneArgs,
    steps: usize,
    format: Format,
    out: &mut dyn Write,
) -> Result<()> {
    let most = match format {
        Format::Csv => MAX_CSV_STEPS,
        Format::Json => MAX_JSON_STEPS,
    };
    if steps > most {
        return Err(CliError::refused(format!(
            "--steps {steps} is too many for {} output: at most {most}",
            if format == Format::Csv { "CSV" } else { "JSON" }
        )));
    }
    let mut k = load(args)?;
    let dead_points = dead_points(&k);
    if format == Format::Csv {
        sweep_csv(&mut k, steps, out).map_err(|f| match f {
            CliError::Solver(e) => describe(args, e),
            other => other,
        })?;
        note_dead_points(dead_points, steps);
        return Ok(());
    }
    let sw = linkage::sweep::sweep(&mut k, steps).map_err(|e| describe(args, e))?;
    note_dead_points(dead_points, steps);
    let m = k.mechanism();
    let header = csv_header(m);
    let rows: Vec<Vec<f64>> = sw
        .solutions
        .iter()
        .zip(&sw.angles)
        .map(|(s, a)| csv_row(m, s, a))
        .collect();
    for r in &rows {
        check_finite(r, "sweep")?;
    }
    warn_near_singular(&sw.near_singular);
    let text = json_text(&json!({
            "scene": m.name,
            "solver_path": k.path().label(),
            "input_speed_rad_s": m.driver.speed_rad_s,
            "range_rad": sw.range,
            "near_singular_inputs_rad": sw.near_singular,
            "dead_points_rad": dead_points,
            "rows_next_to_dead_points": dead_points.map_or(Vec::new(), |_| vec![0, steps - 1]),
            "columns": header,
            "rows": rows,
    }))?;
    out.write_all(text.as_bytes())?;
    Ok(())
}

/// The sweep as CSV, each row written as soon as it is solved.
fn sweep_csv(k: &mut Kinematics, steps: usize, out: &mut dyn Write) -> Result<()> {
    let header = csv_header(k.mechanism());
    let mut w = csv::Writer::from_writer(out);
    w.write_record(&header).map_err(csv_failure)?;
    let mut cells: Vec<String> = Vec::with_capacity(header.len());
    let info = linkage::sweep::sweep_each(k, steps, |m, s, angles| -> Result<()> {
        let row = csv_row(m, s, angles);
        check_finite(&row, "sweep")?;
        cells.clear();
        cells.extend(row.iter().map(|v| format!("{v:e}")));
        w.write_record(&cells).map_err(csv_failure)?;
        Ok(())
    })?;
    w.flush()?;
    warn_near_singular(&info.near_singular);
    Ok(())
}

/// The input's dead points where its range ends (a rocker for input), located: the
/// ends of the assembly interval the sweep covers; `None` for a full turn.
fn dead_points(k: &Kinematics) -> Option<[f64; 2]> {
    let ranges = linkage::analysis::assembly_ranges_of(k);
    if ranges.full_rotation {
        return None;
    }
    ranges.containing(k.mechanism().driver.start_rad)
}

/// Says which rows sit next to the input's dead points: the sweep's first and last,
/// a millionth of the range inside them, where the outputs' rates grow without
/// bound (a slider's speed of hundreds of m/s there is the dead point's, not the
/// mechanism's working speed).
fn note_dead_points(dead_points: Option<[f64; 2]>, steps: usize) {
    if let Some([a, b]) = dead_points {
        eprintln!(
            "note: the input's range ends at dead points, {:.4} deg and {:.4} deg; rows 1 and \
             {steps} are a millionth of the range inside them, where the outputs' speeds and \
             accelerations grow without bound",
            a.to_degrees(),
            b.to_degrees()
        );
    }
}

fn warn_near_singular(inputs_rad: &[f64]) {
    for x in inputs_rad {
        eprintln!(
            "warning: near a dead point/tangency at input {:.4} deg (velocities lose digits)",
            x.to_degrees()
        );
    }
}

pub(crate) fn at(args: &SceneArgs, input_deg: f64, format: Format) -> Result<String> {
    let mut k = load(args)?;
    let s: Solution = k
        .solve(input_deg.to_radians())
        .and_then(|s| linkage::overflow::check(&mut k, &s).map(|()| s))
        .map_err(|e| describe(args, e))?;
    let m = k.mechanism();
    let angles: Vec<f64> = s.links.iter().map(|l| l.angle_rad()).collect();
    let header = csv_header(m);
    let row = csv_row(m, &s, &angles);
    check_finite(&row, "solution")?;
    match format {
        Format::Csv => to_csv(&header, &[row]),
        Format::Json => {
            let v2 = |v: &linkage::Vec2| json!([v.x, v.y]);
            let points: serde_json::Map<String, Value> = m
                .points
                .iter()
                .zip(&s.points)
                .map(|(p, q)| {
                    (p.name.clone(), json!({"position": v2(&q.position), "velocity": v2(&q.velocity), "acceleration": v2(&q.acceleration)}))
                })
                .collect();
            let links: serde_json::Map<String, Value> = m
                .moving_links()
                .map(|l| {
                    let lm = &s.links[l];
                    (m.links[l].name.clone(), json!({"theta": lm.angle_rad(), "omega": lm.omega_rad_s, "alpha": lm.alpha_rad_s2}))
                })
                .collect();
            let polygons = linkage::polygon::polygons(&k, &s);
            let centres = instant_centres_json(m, &s);
            json_text(&json!({
                "scene": m.name,
                "solver_path": k.path().label(),
                "input_rad": s.input_rad,
                "input_speed_rad_s": s.input_speed_rad_s,
                "conditioning": s.conditioning,
                "columns": header,
                "row": row,
                "points": points,
                "links": links,
                "polygons": polygons,
                "instant_centres": centres,
                "notes": m.notes,
            }))
        }
    }
}

pub(crate) fn report(args: &SceneArgs, format: ReportFormat) -> Result<String> {
    let mut k = load(args)?;
    let r = linkage::analysis::report(&mut k)?;
    let peaks = linkage::analysis::output_peaks(&mut k).map_err(|e| describe(args, e))?;
    match format {
        ReportFormat::Json => {
            let mut value = serde_json::to_value(&r)?;
            value["output_peaks"] = serde_json::to_value(&peaks)?;
            json_text(&value)
        }
        ReportFormat::Text => Ok(crate::report_text::text(&r, &peaks, length_unit(args)?)),
    }
}

pub(crate) fn synth(what: SynthCommand) -> Result<String> {
    match what {
        SynthCommand::CrankRocker {
            rocker,
            swing_deg,
            k,
            rocker_start_deg,
            arc_deg,
            side,
            scene_out,
        } => {
            let choice = arc_deg.map(|a| (a.to_radians(), if side >= 0 { 1 } else { -1 }));
            let d = crank_rocker(
                rocker,
                swing_deg.to_radians(),
                k,
                rocker_start_deg.to_radians(),
                choice,
            )?;
            if let Some(path) = scene_out {
                let scene = linkage::synthesis::four_bar_scene(&d, k);
                let text = scene.to_ron()?;
                std::fs::write(&path, text).map_err(|source| CliError::Write { path, source })?;
            }
            json_text(&serde_json::to_value(&d)?)
        }
        SynthCommand::Function {
            points,
            ground,
            scene_out,
        } => crate::synth_function::run(&points, ground, scene_out.as_deref()),
        SynthCommand::Path(args) => crate::synth_path::run(&args),
        SynthCommand::Motion {
            poses,
            moving,
            fixed_near,
            pair,
            scene_out,
        } => crate::synth_motion::run(
            &poses,
            &crate::synth_motion::Choice {
                moving,
                fixed_near,
                pair,
            },
            scene_out.as_deref(),
        ),
        SynthCommand::DieCutter {
            stroke_mm,
            k,
            link_mm,
            rpm,
            as_printed,
        } => {
            let spec = DieCutterSpec {
                stroke_m: stroke_mm * 1e-3,
                k,
                link_m: link_mm * 1e-3,
                crank_rpm: rpm,
            };
            let (scene, _) = match as_printed.as_deref() {
                Some([ab, bc]) => die_cutter_as_printed(ab * 1e-3, bc * 1e-3, &spec),
                _ => die_cutter(&spec),
            }?;
            Ok(scene.to_ron()? + "\n")
        }
    }
}

/// The instant centres at `s`, by link names: `{"links": [a, b], "at": [x, y]}` or
/// `"at_infinity": [dx, dy]` (unit direction), and how each was found (`"pin B"`,
/// `"slide block/ground"`, `"Kennedy via crank, rod"`, or from the velocities where
/// Kennedy's lines coincide); pairs that move as one at this pose under `"unresolved"`.
fn instant_centres_json(m: &Mechanism, s: &Solution) -> Value {
    use linkage::instant_centres::{Centre, FoundBy, instant_centres};
    let ic = instant_centres(m, s);
    let names = |[a, b]: [LinkId; 2]| json!([m.links[a].name, m.links[b].name]);
    let centres: Vec<Value> = ic
        .centres
        .iter()
        .map(|c| {
            let found_by = match c.found_by {
                FoundBy::Pin(p) => format!("pin {}", m.points[p].name),
                FoundBy::Slide(j) => format!("slide {}", m.sliders[j].name),
                FoundBy::Kennedy([k, l]) => {
                    format!("Kennedy via {}, {}", m.links[k].name, m.links[l].name)
                }
                FoundBy::Velocities => "velocities (Kennedy's lines coincide here)".into(),
                FoundBy::CamContact(c) => {
                    format!("cam {}: common normal and Kennedy", m.cams[c].name)
                }
            };
            match c.centre {
                Centre::At(p) => json!({"links": names(c.links), "at": p, "found_by": found_by}),
                Centre::AtInfinity(d) => {
                    json!({"links": names(c.links), "at_infinity": d, "found_by": found_by})
                }
            }
        })
        .collect();
    let unresolved: Vec<Value> = ic.unresolved.iter().map(|&p| names(p)).collect();
    json!({"centres": centres, "unresolved": unresolved})
}
