//! A gear train drawn as the textbooks draw it (机构运动简图 of a 轮系): seen from the
//! side, each shaft a line, each gear a block across its shaft as tall as its pitch
//! circle, gears in mesh touching at their pitch lines, an internal gear opening
//! towards its axis with a cup to its shaft, a carrier (H) an arm from its shaft to
//! its planets' pins, a planet drawn twice (above and mirrored below the axis), belt
//! and chain stages as two pulleys and the run between them.
//!
//! Laid out from the train file alone, in units of pitch radius per tooth (a gear of
//! z teeth is z/2 tall about its axis: the module is the same through a textbook's
//! schematic, not to scale). The app draws it (`render::train_shapes`); tests check
//! that meshing gears touch, planetary sets are coaxial and blocks do not overlap.

use linkage::gears::train_file::{StageFile, StageKind, TrainFile, is_frame};

/// How the schematic is laid out, in units of the gears' mean pitch radius.
const UNIT_PER_MEAN_RADIUS: f64 = 0.2;

/// One member's axis as drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct MemberLine {
    /// The member (index in the file).
    pub member: usize,
    /// Its axis's height; a planet's is its upper copy.
    pub y: f64,
    /// The shaft's ends, x (a planet's is its pin).
    pub x: [f64; 2],
    /// Where its name goes: the shaft's free end, the name reading outwards from it,
    /// or above it where the shaft is hollow (nothing for a planet: its pin is on the
    /// carrier).
    pub label_at: Option<[f64; 2]>,
    /// Whether the label reads leftwards from `label_at` (the shaft ends on the left).
    pub label_left: bool,
    /// Whether the shaft is hollow (around a coaxial shaft that runs out through
    /// it); its name then stands above its free end, clear of the shaft running on.
    pub hollow: bool,
    /// Whether its axis is held by a carrier (a planet).
    pub on_carrier: bool,
}

/// One gear, or a pulley or sprocket of a stage, as a block across its shaft.
#[derive(Clone, Debug, PartialEq)]
pub struct Block {
    /// The member it is fixed to.
    pub member: usize,
    /// The gear (index in the file), or `None` for a pulley or sprocket.
    pub gear: Option<usize>,
    /// The block's middle, x.
    pub x: f64,
    /// Its centres (its axis's heights): two for a planet, drawn above and below.
    pub centres_y: Vec<f64>,
    /// Its pitch radius (a pulley's radius).
    pub radius: f64,
    /// Half its width.
    pub half_width: f64,
    /// Whether its teeth are internal: drawn outside its pitch radius, with a cup
    /// to its shaft at `hub_x`.
    pub internal: bool,
    /// Where it joins its shaft, x.
    pub hub_x: f64,
}

/// A belt or chain stage's run between its two pulleys.
#[derive(Clone, Debug, PartialEq)]
pub struct StageRun {
    /// The stage (index in the file).
    pub stage: usize,
    /// Belt or chain.
    pub kind: StageKind,
    /// The run's x.
    pub x: f64,
    /// Where it leaves the driver and meets the driven pulley, y.
    pub y: [f64; 2],
    /// A crossed belt.
    pub crossed: bool,
}

/// A carrier's arm: from its hub on its axis out to each planet's pin.
#[derive(Clone, Debug, PartialEq)]
pub struct Arm {
    /// The carrier (index in the file).
    pub member: usize,
    /// Its hub, on its axis.
    pub hub: [f64; 2],
    /// The planets' pins it holds.
    pub pins: Vec<[f64; 2]>,
}

/// A train's schematic.
#[derive(Clone, Debug, PartialEq)]
pub struct Schematic {
    /// Every member's axis, in the file's order.
    pub members: Vec<MemberLine>,
    /// Gears, then pulleys.
    pub blocks: Vec<Block>,
    /// Belt and chain runs.
    pub runs: Vec<StageRun>,
    /// Carriers' arms.
    pub arms: Vec<Arm>,
    /// The drawing's unit (the gears' mean pitch radius / 5).
    pub unit: f64,
    /// The box it fills: x min, y min, x max, y max.
    pub bounds: [f64; 4],
}

/// The schematic of `file` (its names already checked by `Train::new`; a name that
/// does not resolve is left out, not a panic).
pub fn schematic(file: &TrainFile) -> Schematic {
    let unit = drawing_unit(file);
    let radii = radii(file, unit);
    let y = heights(file, &radii, unit);
    let columns = columns(file, unit);
    let mut blocks = gear_blocks(file, &radii, &y, &columns, unit);
    let runs = stage_runs(file, &radii, &y, &columns, &mut blocks, unit);
    let arms = arms(file, &y, &blocks, unit);
    let members = member_lines(file, &y, &blocks, &arms, unit);
    let bounds = bounds(&members, &blocks, &arms, unit);
    Schematic {
        members,
        blocks,
        runs,
        arms,
        unit,
        bounds,
    }
}

/// The gears' mean pitch radius (z/2) / 5, or 2 for a train of belts only.
fn drawing_unit(file: &TrainFile) -> f64 {
    let n = file.gears.len().max(1) as f64;
    let mean = file
        .gears
        .iter()
        .map(|g| f64::from(g.teeth) / 2.0)
        .sum::<f64>()
        / n;
    if mean > 0.0 {
        mean * UNIT_PER_MEAN_RADIUS
    } else {
        2.0
    }
}

/// Each gear's drawn pitch radius (z/2), and each stage's pulleys' radii
/// (the driver's 2.5 units, the driven one `ratio` times that, within 1..12 units).
struct Radii {
    gears: Vec<f64>,
    stages: Vec<[f64; 2]>,
}

fn radii(file: &TrainFile, unit: f64) -> Radii {
    let gears = file
        .gears
        .iter()
        .map(|g| f64::from(g.teeth) / 2.0)
        .collect();
    let stages = file
        .stages
        .iter()
        .map(|s| {
            let driver = 2.5 * unit;
            let driven = (driver * s.ratio.abs()).clamp(unit, 12.0 * unit);
            [driver, if driven.is_finite() { driven } else { driver }]
        })
        .collect();
    Radii { gears, stages }
}

fn member_index(file: &TrainFile, name: &str) -> Option<usize> {
    file.members.iter().position(|m| m.name == name)
}

/// A stage's driving and driven members.
fn stage_members(file: &TrainFile, stage: &StageFile) -> Option<(usize, usize)> {
    Some((
        member_index(file, &stage.from)?,
        member_index(file, &stage.to)?,
    ))
}

fn gear_index(file: &TrainFile, name: &str) -> Option<usize> {
    file.gears.iter().position(|g| g.name == name)
}

/// Every member's axis height: the first input's (or the first member's) at 0,
/// then outwards through meshes (an external pair's axes r₁ + r₂ apart, the second
/// above; an internal pair's the ring's radius less the pinion's, the ring's centre
/// on the side of the pinion's other mates, so that a planet's ring is coaxial with
/// its sun whichever way round the meshes are written) and stages (pulleys 3 units
/// apart, the driven one above); a carrier on the axis of the central gears its
/// planets mesh with.
fn heights(file: &TrainFile, radii: &Radii, unit: f64) -> Vec<Option<f64>> {
    let n = file.members.len();
    let mut y: Vec<Option<f64>> = vec![None; n];
    if n > 0 {
        y[first_input(file)] = Some(0.0);
    }
    let links = links(file, radii, unit);
    relax(n, || {
        for link in &links {
            place(link, &links, &mut y);
        }
    });
    for (c, m) in file.members.iter().enumerate() {
        if y[c].is_none() && file.members.iter().any(|p| p.axis_on == m.name) {
            y[c] = carrier_height(file, c, &y);
        }
    }
    y
}

/// Two members whose axes a mesh or a stage sets apart.
enum Link {
    /// `b`'s axis `offset` above `a`'s (an external mesh, a stage).
    Above { a: usize, b: usize, offset: f64 },
    /// A pinion inside a ring, their axes `apart`.
    Inside {
        ring: usize,
        pinion: usize,
        apart: f64,
    },
}

/// Places the member of `link` not yet placed, if the other is.
fn place(link: &Link, links: &[Link], y: &mut [Option<f64>]) {
    match *link {
        Link::Above { a, b, offset } => match (y[a], y[b]) {
            (Some(ya), None) => y[b] = Some(ya + offset),
            (None, Some(yb)) => y[a] = Some(yb - offset),
            _ => {}
        },
        Link::Inside {
            ring,
            pinion,
            apart,
        } => match (y[ring], y[pinion]) {
            (Some(yr), None) => y[pinion] = Some(yr + apart),
            (None, Some(yp)) => {
                // The ring's centre lies towards the pinion's placed external mates
                // (the sun), below a planet drawn above it.
                let mate = links.iter().find_map(|l| match *l {
                    Link::Above { a, b, .. } if a == pinion => y[b],
                    Link::Above { a, b, .. } if b == pinion => y[a],
                    _ => None,
                });
                let side = mate.map_or(1.0, |ym| if yp >= ym { 1.0 } else { -1.0 });
                y[ring] = Some(yp - side * apart);
            }
            _ => {}
        },
    }
}

/// The links of every mesh and stage.
fn links(file: &TrainFile, radii: &Radii, unit: f64) -> Vec<Link> {
    let mut links = Vec::new();
    for (a, b) in &file.meshes {
        let (Some(ga), Some(gb)) = (gear_index(file, a), gear_index(file, b)) else {
            continue;
        };
        let (fa, fb) = (&file.gears[ga], &file.gears[gb]);
        let (Some(ma), Some(mb)) = (
            member_index(file, &fa.member),
            member_index(file, &fb.member),
        ) else {
            continue;
        };
        let (ra, rb) = (radii.gears[ga], radii.gears[gb]);
        links.push(match (fa.internal, fb.internal) {
            (true, false) => Link::Inside {
                ring: ma,
                pinion: mb,
                apart: ra - rb,
            },
            (false, true) => Link::Inside {
                ring: mb,
                pinion: ma,
                apart: rb - ra,
            },
            _ => Link::Above {
                a: ma,
                b: mb,
                offset: ra + rb,
            },
        });
    }
    for (s, stage) in file.stages.iter().enumerate() {
        let Some((a, b)) = stage_members(file, stage) else {
            continue;
        };
        let [ra, rb] = radii.stages[s];
        links.push(Link::Above {
            a,
            b,
            offset: ra + rb + 3.0 * unit,
        });
    }
    links
}

/// A carrier's axis: that of a frame-held member whose gear meshes with one of its
/// planets (the sun or the ring), else its first planet's.
fn carrier_height(file: &TrainFile, carrier: usize, y: &[Option<f64>]) -> Option<f64> {
    let name = &file.members[carrier].name;
    let planets: Vec<&str> = file
        .members
        .iter()
        .filter(|m| &m.axis_on == name)
        .map(|m| m.name.as_str())
        .collect();
    let member_of = |gear: &str| {
        let g = file.gears.iter().find(|g| g.name == gear)?;
        member_index(file, &g.member)
    };
    let central = file.meshes.iter().find_map(|(a, b)| {
        let (ma, mb) = (member_of(a)?, member_of(b)?);
        let (na, nb) = (&file.members[ma], &file.members[mb]);
        if planets.contains(&na.name.as_str()) && is_frame(&nb.axis_on) {
            Some(mb)
        } else if planets.contains(&nb.name.as_str()) && is_frame(&na.axis_on) {
            Some(ma)
        } else {
            None
        }
    });
    central
        .and_then(|c| y[c])
        .or_else(|| planets.first().and_then(|p| y[member_index(file, p)?]))
}

/// The columns (x) where each gear and each stage stand: gears in mesh share one,
/// one column per stage, ordered from the first input outwards; a column holding an
/// internal gear or a carrier's planets is wider on its right (the cup, the arm).
struct Columns {
    gear_x: Vec<f64>,
    stage_x: Vec<f64>,
}

fn columns(file: &TrainFile, unit: f64) -> Columns {
    let groups = column_groups(file);
    let mut x = 0.0;
    let mut gear_x = vec![0.0; file.gears.len()];
    let mut stage_x = vec![0.0; file.stages.len()];
    for (k, group) in groups.iter().enumerate() {
        if k > 0 {
            x += 8.0 * unit;
        }
        match group {
            Group::Stage(s) => stage_x[*s] = x,
            Group::Gears(gears) => {
                for &g in gears {
                    gear_x[g] = x;
                }
                let wide = gears.iter().any(|&g| {
                    let gear = &file.gears[g];
                    gear.internal
                        || file
                            .members
                            .iter()
                            .any(|m| m.name == gear.member && !is_frame(&m.axis_on))
                });
                if wide {
                    x += 7.0 * unit;
                }
            }
        }
    }
    Columns { gear_x, stage_x }
}

enum Group {
    Stage(usize),
    Gears(Vec<usize>),
}

/// The stages and the sets of gears in mesh, in the order power flows from the
/// first input (by each member's distance from it), then the file's.
fn column_groups(file: &TrainFile) -> Vec<Group> {
    let depth = depths(file);
    let member_depth = |name: &str| member_index(file, name).map_or(usize::MAX, |m| depth[m]);
    let mut sets: Vec<Vec<usize>> = Vec::new();
    for g in 0..file.gears.len() {
        if !sets.iter().any(|s| s.contains(&g)) {
            sets.push(mesh_set(file, g));
        }
    }
    let mut groups: Vec<(usize, Group)> = file
        .stages
        .iter()
        .enumerate()
        .map(|(s, st)| {
            (
                member_depth(&st.from).min(member_depth(&st.to)),
                Group::Stage(s),
            )
        })
        .collect();
    for set in sets {
        let d = set
            .iter()
            .map(|&g| member_depth(&file.gears[g].member))
            .min()
            .unwrap_or(usize::MAX);
        groups.push((d, Group::Gears(set)));
    }
    groups.sort_by_key(|(d, _)| *d);
    groups.into_iter().map(|(_, g)| g).collect()
}

/// The gears reached from `start` through meshes.
fn mesh_set(file: &TrainFile, start: usize) -> Vec<usize> {
    let mut set = vec![start];
    let mut k = 0;
    while k < set.len() {
        let name = &file.gears[set[k]].name;
        for (a, b) in &file.meshes {
            let other = if a == name {
                b
            } else if b == name {
                a
            } else {
                continue;
            };
            if let Some(o) = gear_index(file, other)
                && !set.contains(&o)
            {
                set.push(o);
            }
        }
        k += 1;
    }
    set
}

/// Each member's distance from the first input through meshes, stages and
/// fixed gears (usize::MAX where unreached).
fn depths(file: &TrainFile) -> Vec<usize> {
    let n = file.members.len();
    let mut depth = vec![usize::MAX; n];
    if n == 0 {
        return depth;
    }
    depth[first_input(file)] = 0;
    let member_of = |gear: &str| {
        let g = file.gears.iter().find(|g| g.name == gear)?;
        member_index(file, &g.member)
    };
    let mut links: Vec<(usize, usize)> = file
        .meshes
        .iter()
        .filter_map(|(a, b)| Some((member_of(a)?, member_of(b)?)))
        .collect();
    links.extend(file.stages.iter().filter_map(|s| stage_members(file, s)));
    relax(n, || {
        for &(a, b) in &links {
            let d = depth[a].min(depth[b]).saturating_add(1);
            for m in [a, b] {
                if depth[m] == usize::MAX || depth[m] > d {
                    depth[m] = depth[m].min(d);
                }
            }
        }
    });
    depth
}

/// The member the drawing starts from: the first input's (the first member where
/// the inputs name none).
fn first_input(file: &TrainFile) -> usize {
    file.inputs
        .first()
        .and_then(|i| member_index(file, &i.member))
        .unwrap_or(0)
}

/// Runs `pass` once per member: a pass carries what is known (a height, a depth)
/// one link further from the first input, so `members` passes reach every member
/// the meshes and stages join to it, however the file orders them.
fn relax(members: usize, mut pass: impl FnMut()) {
    for _ in 0..members {
        pass();
    }
}

/// The gears' blocks: a planet's twice (mirrored about its carrier's axis when it
/// carries two or more), an internal gear's cup 6 units to the right.
fn gear_blocks(
    file: &TrainFile,
    radii: &Radii,
    y: &[Option<f64>],
    columns: &Columns,
    unit: f64,
) -> Vec<Block> {
    let mut blocks = Vec::new();
    for (g, gear) in file.gears.iter().enumerate() {
        let Some(m) = member_index(file, &gear.member) else {
            continue;
        };
        let Some(ym) = y[m] else {
            continue;
        };
        let mut centres_y = vec![ym];
        let axis_on = &file.members[m].axis_on;
        if !is_frame(axis_on)
            && let Some(c) = member_index(file, axis_on)
            && let Some(yc) = y[c]
            && file.members[c].planets.unwrap_or(1) >= 2
        {
            centres_y.push(2.0 * yc - ym);
        }
        let x = columns.gear_x[g];
        blocks.push(Block {
            member: m,
            gear: Some(g),
            x,
            centres_y,
            radius: radii.gears[g],
            half_width: 1.5 * unit,
            internal: gear.internal,
            hub_x: if gear.internal { x + 6.0 * unit } else { x },
        });
    }
    blocks
}

/// The stages' pulleys (added to `blocks`) and runs.
fn stage_runs(
    file: &TrainFile,
    radii: &Radii,
    y: &[Option<f64>],
    columns: &Columns,
    blocks: &mut Vec<Block>,
    unit: f64,
) -> Vec<StageRun> {
    let mut runs = Vec::new();
    for (s, stage) in file.stages.iter().enumerate() {
        let Some((a, b)) = stage_members(file, stage) else {
            continue;
        };
        let (Some(ya), Some(yb)) = (y[a], y[b]) else {
            continue;
        };
        let x = columns.stage_x[s];
        let [ra, rb] = radii.stages[s];
        for (m, yc, r) in [(a, ya, ra), (b, yb, rb)] {
            blocks.push(Block {
                member: m,
                gear: None,
                x,
                centres_y: vec![yc],
                radius: r,
                half_width: 0.8 * unit,
                internal: false,
                hub_x: x,
            });
        }
        let (lower, upper) = if ya <= yb {
            (ya + ra, yb - rb)
        } else {
            (ya - ra, yb + rb)
        };
        runs.push(StageRun {
            stage: s,
            kind: stage.kind,
            x,
            y: [lower, upper],
            crossed: stage.crossed,
        });
    }
    runs
}

/// Each carrier's arm: its hub 3.5 units right of its planets' column, on its axis,
/// out to every copy of every planet's pin.
fn arms(file: &TrainFile, y: &[Option<f64>], blocks: &[Block], unit: f64) -> Vec<Arm> {
    let mut arms = Vec::new();
    for (c, carrier) in file.members.iter().enumerate() {
        let planets: Vec<&Block> = blocks
            .iter()
            .filter(|b| file.members[b.member].axis_on == carrier.name)
            .collect();
        let (Some(first), Some(yc)) = (planets.first(), y[c]) else {
            continue;
        };
        let pins = planets
            .iter()
            .flat_map(|b| b.centres_y.iter().map(|&py| [b.x, py]))
            .collect();
        arms.push(Arm {
            member: c,
            hub: [first.x + 3.5 * unit, yc],
            pins,
        });
    }
    arms
}

/// Every member's shaft: from its leftmost to its rightmost block or hub, and on to
/// a free end where its name goes: leftwards for the first frame-held member of the
/// first column, else rightwards. Coaxial shafts leaving on the right nest: the one
/// whose hub lies farther in runs out farther, through the others, which are drawn
/// hollow.
fn member_lines(
    file: &TrainFile,
    y: &[Option<f64>],
    blocks: &[Block],
    arms: &[Arm],
    unit: f64,
) -> Vec<MemberLine> {
    let min_x = blocks.iter().map(|b| b.x).fold(f64::INFINITY, f64::min);
    let mut lines: Vec<MemberLine> = Vec::new();
    for (m, member) in file.members.iter().enumerate() {
        let hubs: Vec<f64> = blocks
            .iter()
            .filter(|b| b.member == m)
            .map(|b| b.hub_x)
            .chain(arms.iter().filter(|a| a.member == m).map(|a| a.hub[0]))
            .collect();
        let lo = hubs.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = hubs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        if !lo.is_finite() {
            continue;
        }
        let ym = y[m].unwrap_or(0.0);
        let on_carrier = !is_frame(&member.axis_on);
        let left = !on_carrier
            && lo <= min_x + 1e-9 * unit
            && !lines
                .iter()
                .any(|l| l.label_left && (l.y - ym).abs() < 1e-9 * unit);
        lines.push(MemberLine {
            member: m,
            y: ym,
            x: if on_carrier {
                [lo - 2.0 * unit, hi + 2.0 * unit]
            } else {
                [lo, hi]
            },
            label_at: None,
            label_left: left,
            hollow: false,
            on_carrier,
        });
    }
    free_ends(&mut lines, unit);
    lines
}

/// Each frame-held shaft's free end and name: 5 units out, and 4 more for each
/// coaxial shaft on its side whose hub lies beyond its own (it runs out through
/// them; they are hollow).
fn free_ends(lines: &mut [MemberLine], unit: f64) {
    let coaxial = |a: &MemberLine, b: &MemberLine| {
        !a.on_carrier && !b.on_carrier && (a.y - b.y).abs() < 1e-9 * unit
    };
    let snapshot = lines.to_vec();
    for line in lines.iter_mut().filter(|l| !l.on_carrier) {
        let outer = snapshot
            .iter()
            .filter(|o| {
                coaxial(o, line) && o.label_left == line.label_left && o.member != line.member
            })
            .filter(|o| {
                if line.label_left {
                    o.x[1] < line.x[1]
                } else {
                    o.x[0] > line.x[0]
                }
            })
            .count();
        let reach = (5.0 + 4.0 * outer as f64) * unit;
        if line.label_left {
            line.x[0] -= reach;
            line.label_at = Some([line.x[0], line.y]);
        } else {
            line.x[1] += reach;
            line.label_at = Some([line.x[1], line.y]);
        }
    }
    let ends = lines.to_vec();
    for line in lines.iter_mut() {
        line.hollow = ends.iter().any(|o| {
            coaxial(o, line)
                && o.member != line.member
                && o.label_left == line.label_left
                && if line.label_left {
                    o.x[0] < line.x[0] && o.x[1] > line.x[0]
                } else {
                    o.x[1] > line.x[1] && o.x[0] < line.x[1]
                }
        });
    }
}

/// The box the schematic fills, with a margin of 2 units (the names outside it
/// are placed by the reader).
fn bounds(members: &[MemberLine], blocks: &[Block], arms: &[Arm], unit: f64) -> [f64; 4] {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    let mut add = |x: f64, y: f64| {
        b = [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)];
    };
    for l in members {
        add(l.x[0], l.y);
        add(l.x[1], l.y);
    }
    for bl in blocks {
        let outer = if bl.internal {
            bl.radius + unit
        } else {
            bl.radius
        };
        for &yc in &bl.centres_y {
            add(bl.x - bl.half_width, yc - outer);
            add(bl.hub_x + bl.half_width, yc + outer);
        }
    }
    for a in arms {
        add(a.hub[0], a.hub[1]);
    }
    if !b[0].is_finite() {
        return [-1.0, -1.0, 1.0, 1.0];
    }
    [
        b[0] - 2.0 * unit,
        b[1] - 2.0 * unit,
        b[2] + 2.0 * unit,
        b[3] + 2.0 * unit,
    ]
}
