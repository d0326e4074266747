//! Flywheel sizing of the die cutter at δ = 0.05 by the energy method: 360 panels of
//! four Gauss points, the working stroke's switches and the surplus extremes found by
//! root-finding. Criterion times the whole sizing from a built `Kinematics`.
//! Target (issue 24): at most 5 ms.

use criterion::{Criterion, criterion_group, criterion_main};
use linkage::machine::size_flywheel;
use linkage::{Kinematics, Mechanism};

fn die_cutter_flywheel(c: &mut Criterion) {
    let path = format!(
        "{}/../../assets/scenes/die_cutter.ron",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut k = Kinematics::new(Mechanism::from_ron(&text).unwrap_or_else(|e| panic!("{e}")))
        .unwrap_or_else(|e| panic!("{e}"));
    c.bench_function("die_cutter_flywheel_delta_0_05", |b| {
        b.iter(|| size_flywheel(&mut k, 0.05).unwrap_or_else(|e| panic!("{e}")));
    });
}

criterion_group!(benches, die_cutter_flywheel);
criterion_main!(benches);
