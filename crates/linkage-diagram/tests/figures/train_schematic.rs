//! The gear trains' schematics, for every shipped train and for odd files: gears
//! in mesh touch at their pitch lines (external pairs' axes r₁ + r₂ apart, an
//! internal pair's r_ring − r_pinion), a planetary set's central gears and carrier
//! share one axis, blocks of different members in one column do not overlap, every
//! shaft reaches its gears, names stand apart, and nothing is non-finite; each file
//! also with its meshes written the other way round.

use linkage::gears::train_file::TrainFile;
use linkage_diagram::train_schematic::{Block, Schematic, schematic};

fn shipped() -> Vec<(String, TrainFile)> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../assets/trains");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .expect("assets/trains")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "ron"))
        .collect();
    files.sort();
    assert!(files.len() >= 4, "{files:?}");
    // Each as written and with every mesh named the other way round (a ring
    // first): the layout must not depend on the order a user writes.
    files
        .into_iter()
        .flat_map(|p| {
            let text = std::fs::read_to_string(&p).expect("read");
            let file = TrainFile::from_ron(&text).expect("a train file");
            let mut swapped = file.clone();
            for mesh in &mut swapped.meshes {
                *mesh = (mesh.1.clone(), mesh.0.clone());
            }
            let name = p.display().to_string();
            [
                (name.clone(), file),
                (format!("{name}, meshes reversed"), swapped),
            ]
        })
        .collect()
}

fn gear_block(s: &Schematic, gear: usize) -> &Block {
    s.blocks
        .iter()
        .find(|b| b.gear == Some(gear))
        .expect("a block for every gear")
}

#[test]
fn meshing_gears_touch_at_their_pitch_lines() {
    for (name, file) in shipped() {
        let s = schematic(&file);
        for (a, b) in &file.meshes {
            let ga = file.gears.iter().position(|g| &g.name == a).expect("gear");
            let gb = file.gears.iter().position(|g| &g.name == b).expect("gear");
            let (ba, bb) = (gear_block(&s, ga), gear_block(&s, gb));
            assert_eq!(ba.x, bb.x, "{name}: {a} and {b} in one column");
            let apart = (ba.centres_y[0] - bb.centres_y[0]).abs();
            let (za, zb) = (
                f64::from(file.gears[ga].teeth),
                f64::from(file.gears[gb].teeth),
            );
            let want = if file.gears[ga].internal || file.gears[gb].internal {
                (za - zb).abs() / 2.0
            } else {
                (za + zb) / 2.0
            };
            assert!(
                (apart - want).abs() <= 1e-12 * want,
                "{name}: {a}-{b} {apart} vs {want}"
            );
        }
    }
}

#[test]
fn a_planetary_sets_central_gears_and_carrier_share_one_axis() {
    for (name, file) in shipped() {
        let s = schematic(&file);
        for arm in &s.arms {
            let carrier = &file.members[arm.member].name;
            let centrals: Vec<f64> = s
                .members
                .iter()
                .filter(|l| !l.on_carrier && l.member != arm.member)
                .filter(|l| {
                    s.blocks
                        .iter()
                        .any(|b| b.member == l.member && b.gear.is_some() && b.x == s.blocks[0].x)
                })
                .map(|l| l.y)
                .collect();
            assert!(centrals.len() >= 2, "{name}: {carrier}'s sun and ring");
            for y in centrals {
                assert!(
                    (y - arm.hub[1]).abs() <= 1e-12 * s.unit,
                    "{name}: {y} vs {:?}",
                    arm.hub
                );
            }
            // Four planets: drawn twice, above and mirrored below.
            assert_eq!(arm.pins.len(), 2, "{name}");
            assert!((arm.pins[0][1] + arm.pins[1][1] - 2.0 * arm.hub[1]).abs() <= 1e-9 * s.unit);
        }
    }
}

/// The y ranges a block fills (an internal gear's teeth lie outside its pitch
/// radius, one unit deep, above and below).
fn spans(b: &Block, unit: f64) -> Vec<[f64; 2]> {
    b.centres_y
        .iter()
        .flat_map(|&y| {
            if b.internal {
                vec![
                    [y + b.radius, y + b.radius + unit],
                    [y - b.radius - unit, y - b.radius],
                ]
            } else {
                vec![[y - b.radius, y + b.radius]]
            }
        })
        .collect()
}

#[test]
fn blocks_of_different_members_in_one_column_do_not_overlap() {
    for (name, file) in shipped() {
        let s = schematic(&file);
        for (i, a) in s.blocks.iter().enumerate() {
            for b in &s.blocks[i + 1..] {
                if a.member == b.member || (a.x - b.x).abs() > a.half_width + b.half_width {
                    continue;
                }
                for sa in spans(a, s.unit) {
                    for sb in spans(b, s.unit) {
                        let overlap = sa[1].min(sb[1]) - sa[0].max(sb[0]);
                        assert!(
                            overlap <= 1e-9 * s.unit,
                            "{name}: {a:?} and {b:?} overlap by {overlap}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn every_shaft_reaches_its_gears_and_names_stand_apart() {
    for (name, file) in shipped() {
        let s = schematic(&file);
        assert_eq!(
            s.members.len(),
            file.members.len(),
            "{name}: every member drawn"
        );
        for b in &s.blocks {
            let line = s
                .members
                .iter()
                .find(|l| l.member == b.member)
                .expect("its shaft");
            assert!(
                line.x[0] <= b.hub_x && b.hub_x <= line.x[1],
                "{name}: {line:?} {b:?}"
            );
        }
        // Names read outwards from their shafts' free ends on one line; a hollow
        // shaft's name stands above its end, off the line.
        let named: Vec<_> = s.members.iter().filter(|l| l.label_at.is_some()).collect();
        for (i, a) in named.iter().enumerate() {
            for b in &named[i + 1..] {
                let (p, q) = (a.label_at.expect("named"), b.label_at.expect("named"));
                let one_line = (p[1] - q[1]).abs() < 4.0 * s.unit && a.hollow == b.hollow;
                assert!(
                    !(one_line && a.label_left == b.label_left),
                    "{name}: names at {p:?} and {q:?} on one line, one side"
                );
            }
        }
        let [x0, y0, x1, y1] = s.bounds;
        assert!(x0 < x1 && y0 < y1 && [x0, y0, x1, y1].iter().all(|v| v.is_finite()));
    }
}

/// Files a user might write: no gears, a name that is not a member, a lone gear,
/// an empty train. Laid out without a panic and without a non-finite number.
#[test]
fn odd_files_are_laid_out_finite() {
    for text in [
        "(name: \"empty\", members: [])",
        "(name: \"belts\", members: [(name: \"a\"), (name: \"b\")], stages: [(kind: Belt, from: \"a\", to: \"b\", ratio: 0.0)])",
        "(name: \"lone\", members: [(name: \"a\")], gears: [(name: \"g\", member: \"a\", teeth: 1)])",
        "(name: \"bad\", members: [(name: \"a\")], gears: [(name: \"g\", member: \"nobody\", teeth: 20)], meshes: [(\"g\", \"h\")])",
    ] {
        let file = TrainFile::from_ron(text).expect("parses");
        let s = schematic(&file);
        let mut numbers = s
            .bounds
            .into_iter()
            .chain(s.members.iter().flat_map(|l| [l.y, l.x[0], l.x[1]]))
            .chain(s.blocks.iter().flat_map(|b| [b.x, b.radius, b.hub_x]));
        assert!(numbers.all(f64::is_finite), "{text}: {s:?}");
    }
}
