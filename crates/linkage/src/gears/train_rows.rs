//! A train file's names checked and its constraint rows written: one a mesh (Willis'
//! relation relative to the member holding both axes' line of centres) and one a belt
//! or chain stage.

use super::train_file::{FRAME, GearFile, TrainFile, is_frame};
use super::train_results::TrainError;
use crate::error::{NameKind, TrainField};

/// Every name defined once, every name used defined, every number in range.
pub(crate) fn check_names(file: &TrainFile) -> Result<(), TrainError> {
    if file.members.is_empty() {
        return Err(TrainError::NoMembers);
    }
    let mut seen: Vec<&str> = vec![FRAME];
    for name in file.members.iter().map(|m| m.name.as_str()) {
        if seen.contains(&name) {
            return Err(TrainError::Duplicate { name: name.into() });
        }
        seen.push(name);
    }
    let member = |what: TrainField, name: &str| known(&seen, what, name);
    for m in &file.members {
        let named = m.name.clone();
        member(
            TrainField::AxisOn {
                member: named.clone(),
            },
            &m.axis_on,
        )?;
        range(
            TrainField::Inertia { member: named },
            m.inertia_kg_m2,
            0.0,
            1e9,
        )?;
    }
    check_gears(file, &seen)?;
    if let Some(eta) = file.mesh_efficiency {
        range(TrainField::MeshEfficiency, eta, 0.01, 1.0)?;
    }
    for s in &file.stages {
        let (from, to) = (s.from.clone(), s.to.clone());
        member(
            TrainField::StageFrom {
                from: from.clone(),
                to: to.clone(),
            },
            &s.from,
        )?;
        member(
            TrainField::StageTo {
                from: from.clone(),
                to: to.clone(),
            },
            &s.to,
        )?;
        if let Some(eta) = s.efficiency {
            let what = TrainField::StageEfficiency {
                from: from.clone(),
                to: to.clone(),
            };
            range(what, eta, 0.01, 1.0)?;
        }
        range(TrainField::StageRatio { from, to }, s.ratio, 1e-6, 1e6)?;
    }
    for i in &file.inputs {
        if is_frame(&i.member) {
            // The frame does not turn: a member held still is one with an input of 0.
            return Err(TrainError::Unknown {
                what: TrainField::InputOnFrame,
                name: i.member.clone(),
                kind: NameKind::TurningMembers,
            });
        }
        let what = TrainField::Input {
            member: i.member.clone(),
        };
        member(what, &i.member)?;
        let rpm = TrainField::InputRpm {
            member: i.member.clone(),
        };
        range(rpm, i.rpm, -1e7, 1e7)?;
    }
    Ok(())
}

/// `name`, used by `what`, is one of the members `seen` (the frame among them).
fn known(seen: &[&str], what: TrainField, name: &str) -> Result<(), TrainError> {
    if seen.contains(&name) {
        Ok(())
    } else {
        Err(TrainError::Unknown {
            what,
            name: name.into(),
            kind: NameKind::Members,
        })
    }
}

/// Every gear named once, on a member `seen`, with teeth in range; every mesh of
/// gears defined.
fn check_gears(file: &TrainFile, seen: &[&str]) -> Result<(), TrainError> {
    let mut gear_names: Vec<&str> = Vec::new();
    for g in &file.gears {
        if gear_names.contains(&g.name.as_str()) {
            return Err(TrainError::Duplicate {
                name: g.name.clone(),
            });
        }
        gear_names.push(&g.name);
        let gear = g.name.clone();
        known(
            seen,
            TrainField::GearMember { gear: gear.clone() },
            &g.member,
        )?;
        range(
            TrainField::Teeth { gear },
            f64::from(g.teeth),
            3.0,
            10_000.0,
        )?;
    }
    for (a, b) in &file.meshes {
        for name in [a, b] {
            if !gear_names.contains(&name.as_str()) {
                return Err(TrainError::Unknown {
                    what: TrainField::Mesh {
                        a: a.clone(),
                        b: b.clone(),
                    },
                    name: name.clone(),
                    kind: NameKind::Gears,
                });
            }
        }
    }
    Ok(())
}

fn range(what: TrainField, value: f64, min: f64, max: f64) -> Result<(), TrainError> {
    if value.is_finite() && (min..=max).contains(&value) {
        Ok(())
    } else {
        Err(TrainError::OutOfRange {
            what,
            value,
            min,
            max,
        })
    }
}

/// The members a row ties: a mesh's two gears' members and the member holding their
/// line of centres, or a stage's driving and driven members (held by the frame);
/// `None` for the frame, which has no column.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RowMembers {
    pub(crate) a: Option<usize>,
    pub(crate) b: Option<usize>,
    pub(crate) holder: Option<usize>,
}

/// The rows over the members' speeds (the frame's is 0 and has no column), and the
/// members each ties.
pub(crate) fn rows(file: &TrainFile) -> Result<(Vec<Vec<f64>>, Vec<RowMembers>), TrainError> {
    let n = file.members.len();
    let column = |name: &str| file.members.iter().position(|m| m.name == name);
    let add = |row: &mut Vec<f64>, name: &str, v: f64| {
        if let Some(j) = column(name) {
            row[j] += v;
        }
    };
    let mut rows = Vec::new();
    let mut members = Vec::new();
    for (a, b) in &file.meshes {
        let (ga, gb) = (gear(file, a), gear(file, b));
        if ga.internal && gb.internal {
            return Err(TrainError::BothInternal {
                a: a.clone(),
                b: b.clone(),
            });
        }
        for (ring, mate) in [(ga, gb), (gb, ga)] {
            if ring.internal && ring.teeth <= mate.teeth {
                return Err(TrainError::RingTooSmall {
                    ring: ring.name.clone(),
                    ring_teeth: ring.teeth,
                    mate: mate.name.clone(),
                    mate_teeth: mate.teeth,
                });
            }
        }
        let holder = holder(file, ga, gb)?;
        let sigma = if ga.internal || gb.internal {
            -1.0
        } else {
            1.0
        };
        let (za, zb) = (f64::from(ga.teeth), f64::from(gb.teeth));
        let mut row = vec![0.0; n];
        add(&mut row, &ga.member, za);
        add(&mut row, &gb.member, sigma * zb);
        add(&mut row, &holder, -(za + sigma * zb));
        rows.push(row);
        members.push(RowMembers {
            a: column(&ga.member),
            b: column(&gb.member),
            holder: column(&holder),
        });
    }
    for s in &file.stages {
        let sign = if s.crossed { -1.0 } else { 1.0 };
        let mut row = vec![0.0; n];
        add(&mut row, &s.from, 1.0);
        add(&mut row, &s.to, -sign * s.ratio);
        rows.push(row);
        members.push(RowMembers {
            a: column(&s.from),
            b: column(&s.to),
            holder: None,
        });
    }
    Ok((rows, members))
}

/// Each row's efficiency, in the rows' order (the meshes', then the stages'): 1
/// where the file gives none.
pub(crate) fn efficiencies(file: &TrainFile) -> Vec<f64> {
    let mesh = file.mesh_efficiency.unwrap_or(1.0);
    file.meshes
        .iter()
        .map(|_| mesh)
        .chain(file.stages.iter().map(|s| s.efficiency.unwrap_or(1.0)))
        .collect()
}

/// A gear by name (checked to exist).
fn gear<'a>(file: &'a TrainFile, name: &str) -> &'a GearFile {
    file.gears
        .iter()
        .find(|g| g.name == name)
        .expect("meshes name gears, checked first")
}

/// The member holding an axis: the frame or a carrier.
fn axis_of<'a>(file: &'a TrainFile, member: &'a str) -> &'a str {
    file.members
        .iter()
        .find(|m| m.name == member)
        .map_or(FRAME, |m| m.axis_on.as_str())
}

/// The member that holds the line of centres of two meshing gears: the one holding
/// both axes, or the carrier of a planet meshing with a gear on the carrier's axis.
fn holder(file: &TrainFile, a: &GearFile, b: &GearFile) -> Result<String, TrainError> {
    let (pa, pb) = (axis_of(file, &a.member), axis_of(file, &b.member));
    let found = if pa == pb {
        Some(pa)
    } else if !is_frame(pb) && axis_of(file, pb) == pa {
        Some(pb)
    } else if !is_frame(pa) && axis_of(file, pa) == pb {
        Some(pa)
    } else {
        None
    };
    found
        .map(str::to_string)
        .ok_or_else(|| TrainError::AxesApart {
            a: a.name.clone(),
            b: b.name.clone(),
            a_axis: pa.into(),
            b_axis: pb.into(),
        })
}

/// Each carrier (a member holding another's axis) with its central members: those
/// not on the carrier whose gears mesh with a gear on a member it carries.
pub(crate) fn central_members(file: &TrainFile) -> Vec<(String, Vec<String>)> {
    let carried = |carrier: &str, member: &str| axis_of(file, member) == carrier;
    let mut out = Vec::new();
    for h in &file.members {
        let mut central: Vec<String> = Vec::new();
        for (a, b) in &file.meshes {
            let (ga, gb) = (gear(file, a), gear(file, b));
            for (planet, other) in [(ga, gb), (gb, ga)] {
                let central_one = carried(&h.name, &planet.member)
                    && !carried(&h.name, &other.member)
                    && other.member != h.name;
                if central_one && !central.contains(&other.member) {
                    central.push(other.member.clone());
                }
            }
        }
        if !central.is_empty() {
            out.push((h.name.clone(), central));
        }
    }
    out
}
