//! What the polygon pane costs each frame: both polygons of a position built and
//! laid out (fit, arrow heads, label placement) in a 340×260 pane, per shipped seed
//! scene at 30° (labels measured by the approximate metric; the app's egui
//! measurement is cached by egui). And the whole A4 sheet as SVG, made on export.

use criterion::{Criterion, criterion_group, criterion_main};
use linkage::instant_centres::instant_centres;
use linkage::polygon::{Quantity, polygons};
use linkage::{Kinematics, Mechanism};
use linkage_diagram::layout::Sizes;
use linkage_diagram::svg::{Parts, Position, sheet};
use linkage_diagram::words::Lang;
use linkage_diagram::{Label, PolygonFigure, Rect, layout_polygon};

fn kinematics(file: &str) -> Kinematics {
    let path = format!("{}/../../assets/scenes/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).expect("scene");
    Kinematics::new(Mechanism::from_ron(&text).expect("valid")).expect("kinematics")
}

fn bench(c: &mut Criterion) {
    let measure = |l: &Label| l.approximate_size(13.0);
    for file in [
        "paper_cup_feed.ron",
        "die_cutter.ron",
        "gravity_flipper.ron",
    ] {
        let mut k = kinematics(file);
        let input = if file == "gravity_flipper.ron" {
            70f64
        } else {
            30.0
        };
        let s = k.solve(input.to_radians()).expect("solves");
        let eqs = polygons(&k, &s);
        let m = k.mechanism().clone();
        let pane = Rect::from_min_size([0.0, 0.0], 340.0, 260.0);
        c.bench_function(&format!("{file}/both polygons laid out"), |b| {
            b.iter(|| {
                for q in [Quantity::Velocity, Quantity::Acceleration] {
                    let fig = PolygonFigure::of_position(q, &m, &s, &eqs);
                    std::hint::black_box(layout_polygon(&fig, pane, Sizes::default(), &measure));
                }
            });
        });
        let centres = instant_centres(&m, &s);
        let position = Position {
            mechanism: &m,
            solution: &s,
            equations: &eqs,
            centres: Some(&centres),
            forces: None,
        };
        c.bench_function(&format!("{file}/sheet svg"), |b| {
            b.iter(|| std::hint::black_box(sheet(&position, Parts::default(), Lang::English)));
        });
    }
}

/// The gear lab's train view each frame: the schematic laid out from the file and
/// the train solved (the die cutter's drive, the planetary set); and a ring's whole
/// cut outline by a pinion cutter (60 teeth, a cutter of 25), made when it changes.
fn gears(c: &mut Criterion) {
    use linkage::gears::train_file::TrainFile;
    use linkage::gears::{Gear, GearSpec, Train};
    for file in ["die_cutter_drive.ron", "planetary_ring_fixed.ron"] {
        let path = format!("{}/../../assets/trains/{file}", env!("CARGO_MANIFEST_DIR"));
        let train = TrainFile::from_ron(&std::fs::read_to_string(path).expect("train"))
            .expect("a train file");
        c.bench_function(&format!("train_view_frame/{file}"), |b| {
            b.iter(|| {
                let s = linkage_diagram::train_schematic::schematic(&train);
                let solved = Train::new(train.clone()).and_then(|t| t.solve());
                (s.bounds, solved.is_ok())
            })
        });
    }
    let ring = Gear::new(GearSpec::standard(0.002, 60).internal()).expect("a ring");
    c.bench_function("ring_outline/60_by_25", |b| {
        b.iter(|| linkage_diagram::gear_profile::ring_outline(&ring, 25, 30).len())
    });
}

criterion_group!(benches, bench, gears);
criterion_main!(benches);
