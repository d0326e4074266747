//! `linkage at`: one position as a CSV row (the table a report takes, as `sweep`), or as JSON with every point's and link's
//! motion, the velocity and acceleration polygons' equations and the instant centres.

use linkage::sweep::{csv_header, csv_row};
use linkage::{LinkId, Mechanism, Solution};
use linkage_diagram::cycle_table::{CycleTable, csv_line};
use serde_json::{Value, json};

use crate::args::{Format, SceneArgs};
use crate::error::Result;
use crate::io::{check_finite, describe, json_text, length_unit, load};

/// `at SCENE --input-deg X`.
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
        Format::Csv => {
            let table = CycleTable::new(length_unit(args)?);
            let mut text = csv_line(&table.header(m));
            text.push_str(&csv_line(&table.row(m, &s, &angles)));
            Ok(text)
        }
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
