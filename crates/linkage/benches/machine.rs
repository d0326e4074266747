//! The die cutter as a machine. Flywheel sizing at δ = 0.05 by the energy method
//! (360 panels of four Gauss points, the working stroke's switches and the surplus
//! extremes by root-finding); target (issue 24) at most 5 ms. The steady state with
//! that flywheel and a linear motor through the reduction of 29
//! (`docs/examples/die_cutter_linear_motor.ron`: shooting, one DOP853 turn per try,
//! and the sampled cycle); target at most 50 ms. The force polygons of one position
//! (what the app redoes on every change of the pose): well under a frame. Criterion
//! times each from a built `Kinematics`.

use criterion::{Criterion, criterion_group, criterion_main};
use linkage::force_polygon::force_polygons;
use linkage::kinetostatics::Kinetostatics;
use linkage::machine::{size_flywheel, steady_state};
use linkage::{Kinematics, Mechanism};

/// A scene of the repository, relative to its root, solved.
fn scene(path: &str) -> Kinematics {
    let path = format!("{}/../../{path}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    Kinematics::new(Mechanism::from_ron(&text).unwrap_or_else(|e| panic!("{e}")))
        .unwrap_or_else(|e| panic!("{e}"))
}

fn die_cutter_flywheel(c: &mut Criterion) {
    let mut k = scene("assets/scenes/die_cutter.ron");
    c.bench_function("die_cutter_flywheel_delta_0_05", |b| {
        b.iter(|| size_flywheel(&mut k, 0.05).unwrap_or_else(|e| panic!("{e}")));
    });
}

fn die_cutter_steady_state(c: &mut Criterion) {
    let k = scene("docs/examples/die_cutter_linear_motor.ron");
    c.bench_function("die_cutter_steady_state_linear_motor", |b| {
        b.iter(|| steady_state(&k).unwrap_or_else(|e| panic!("{e}")));
    });
}

fn die_cutter_force_polygons(c: &mut Criterion) {
    let mut k = scene("assets/scenes/die_cutter.ron");
    let mut ks = Kinetostatics::new(&mut k).unwrap_or_else(|e| panic!("{e}"));
    c.bench_function("die_cutter_force_polygons_one_position", |b| {
        b.iter(|| force_polygons(&mut k, &mut ks, 1.0).unwrap_or_else(|e| panic!("{e}")));
    });
}

criterion_group!(
    benches,
    die_cutter_flywheel,
    die_cutter_steady_state,
    die_cutter_force_polygons
);
criterion_main!(benches);
