//! A meshing pair's whole geometry (both gears' circles and thicknesses, the
//! working pressure angle from the shifts by the involute's inverse, the contact
//! ratio and every check): what an app redraws on each change of a slider. Criterion
//! times one shifted external pair and one internal pair; a train's speeds (the die
//! cutter's drive and a planetary set, from their files); and the solver's share of
//! a frame of the gear-cutting lab (12 teeth, the whole roll: the cutter at its 72
//! positions, and the cut tooth's thickness at the 2 × 41 radii the undercut marks
//! look at).

use criterion::{Criterion, criterion_group, criterion_main};
use linkage::gears::generation::{cut_tooth_thickness_at, cutter_outline};
use linkage::gears::train_file::TrainFile;
use linkage::gears::{CentreDistance, Gear, GearPair, GearSpec, PairSpec, Train};
use std::hint::black_box;

fn pairs(c: &mut Criterion) {
    let external = PairSpec {
        pinion: GearSpec::standard(0.002, 12).shifted(0.3),
        wheel: GearSpec::standard(0.002, 40).shifted(0.2),
        centre: CentreDistance::FromShifts,
    };
    let internal = PairSpec {
        pinion: GearSpec::standard(0.002, 20).shifted(0.3),
        wheel: GearSpec::standard(0.002, 64).shifted(0.1).internal(),
        centre: CentreDistance::FromShifts,
    };
    for (name, spec) in [
        ("gear_pair_external_shifted", external),
        ("gear_pair_internal_shifted", internal),
    ] {
        c.bench_function(name, |b| {
            b.iter(|| GearPair::new(black_box(spec)).unwrap_or_else(|e| panic!("{e}")));
        });
    }
}

fn trains(c: &mut Criterion) {
    for file in ["die_cutter_drive.ron", "planetary_ring_fixed.ron"] {
        let path = format!("{}/../../assets/trains/{file}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        let train_file = TrainFile::from_ron(&text).unwrap_or_else(|e| panic!("{e}"));
        let train = Train::new(train_file).unwrap_or_else(|e| panic!("{e}"));
        c.bench_function(&format!("train_speeds_{file}"), |b| {
            b.iter(|| black_box(&train).solve().unwrap_or_else(|e| panic!("{e}")));
        });
    }
}

/// The lab's frame while it rolls: as many cutter outlines as
/// `src/render/gear_shapes.rs` asks for at the roll's end (one a position, 72,
/// filled, traced and the last drawn again from the same); and a change of the gear,
/// which also searches the undercut (the cut tooth's thickness at the 33 radii of
/// one flank).
fn generation_frame(c: &mut Criterion) {
    let g = Gear::new(GearSpec::standard(0.01, 12)).unwrap_or_else(|e| panic!("{e}"));
    let positions = 72;
    let outlines = |g: &Gear| {
        let mut points = 0usize;
        for k in 0..positions {
            let phi = -1.0 + 2.0 * k as f64 / (positions - 1) as f64;
            let parts = cutter_outline(black_box(g), phi, 2, 8).unwrap_or_default();
            points += parts.iter().map(Vec::len).sum::<usize>();
        }
        points
    };
    c.bench_function("gear_lab_frame_rolling_12_teeth", |b| {
        b.iter(|| outlines(&g))
    });
    c.bench_function("gear_lab_undercut_search_12_teeth", |b| {
        b.iter(|| {
            let (lo, hi) = (g.root_radius_m, g.tip_radius_m);
            (0..=32)
                .filter_map(|k| {
                    cut_tooth_thickness_at(black_box(&g), lo + (hi - lo) * f64::from(k) / 32.0)
                })
                .sum::<f64>()
        });
    });
}

criterion_group!(benches, pairs, trains, generation_frame);
criterion_main!(benches);
