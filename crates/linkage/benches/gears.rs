//! A meshing pair's whole geometry (both gears' circles and thicknesses, the
//! working pressure angle from the shifts by the involute's inverse, the contact
//! ratio and every check): what an app redraws on each change of a slider. Criterion
//! times one shifted external pair and one internal pair.

use criterion::{Criterion, criterion_group, criterion_main};
use linkage::gears::{CentreDistance, GearPair, GearSpec, PairSpec};
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

criterion_group!(benches, pairs);
criterion_main!(benches);
