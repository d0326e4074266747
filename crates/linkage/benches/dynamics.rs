//! The flipper released at 69.5 deg and run to its end stop at 35 deg with DOP853 at
//! rtol 1e-8, atol 3e-10: the settings that the test `flipper_budget` holds to a phi
//! error of at most 1e-9 rad in at most 250 right-hand-side evaluations. Criterion
//! times the whole run (no output grid). Target: at most 0.1 ms.

use criterion::{Criterion, criterion_group, criterion_main};
use linkage::dynamics::{Method, Settings, simulate};
use linkage::{Kinematics, Mechanism};

fn flipper_to_the_stop(c: &mut Criterion) {
    let path = format!(
        "{}/../../assets/scenes/gravity_flipper.ron",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let k = Kinematics::new(Mechanism::from_ron(&text).unwrap_or_else(|e| panic!("{e}")))
        .unwrap_or_else(|e| panic!("{e}"));
    let mut settings = Settings::new(Method::Dop853);
    settings.rtol = 1e-8;
    settings.atol = 3e-10;
    settings.t_end = 2.0;
    c.bench_function("flipper_dop853_to_35_deg", |b| {
        b.iter(|| simulate(&k, &settings).unwrap_or_else(|e| panic!("{e}")));
    });
}

criterion_group!(benches, flipper_to_the_stop);
criterion_main!(benches);
