//! Per-position cost of a full cycle of 3600 positions with positions, velocities and
//! accelerations, for a four-bar (the flipper's geometry on a crank-rocker: the
//! paper-cup feed's four-bar) and the die cutter's six-bar, on both solver paths.
//!
//! Criterion reports the time for one cycle; divide by 3600 for the per-position
//! figure (the README and issue notes quote both). The closed form runs twice: one
//! input per call (`solve_into`) and four per call in SIMD lanes (`solve_lanes`,
//! how sweeps solve a cycle); Newton follows its branch from one input to the next,
//! so it solves one per call.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use linkage::LANES;
use linkage::scene::SolverPath;
use linkage::{Kinematics, Mechanism};

const POSITIONS: usize = 3600;

fn scene(file: &str) -> Mechanism {
    let path = format!("{}/../../assets/scenes/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    Mechanism::from_ron(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// A crank-rocker four-bar: the paper-cup feed without its slider.
fn four_bar() -> Mechanism {
    let text = include_str!("four_bar.ron");
    Mechanism::from_ron(text).unwrap_or_else(|e| panic!("{e}"))
}

fn cycle(c: &mut Criterion) {
    let mut group = c.benchmark_group("cycle_3600_positions_pva");
    group.throughput(Throughput::Elements(POSITIONS as u64));
    for (name, mech) in [
        ("four_bar", four_bar()),
        ("die_cutter_six_bar", scene("die_cutter.ron")),
        // A cam and a four-bar on one shaft: the cam's follower is placed lane by
        // lane (its program branches on the angle).
        ("paper_cup_cam_feed", scene("paper_cup_cam_feed.ron")),
    ] {
        for path in [SolverPath::ClosedForm, SolverPath::Newton] {
            let mut k = Kinematics::with_path(mech.clone(), path).unwrap_or_else(|e| panic!("{e}"));
            let mut sol = k.empty_solution();
            let w = mech.driver.speed_rad_s;
            let label = format!("{name}/{}", k.path().label().replace(' ', "_"));
            group.bench_function(label, |b| {
                b.iter(|| {
                    let mut checksum = 0.0;
                    for i in 0..POSITIONS {
                        let x = std::f64::consts::TAU * i as f64 / POSITIONS as f64;
                        if k.solve_into(x, w, &mut sol).is_ok() {
                            checksum += sol.points[sol.points.len() - 1].acceleration.x;
                        }
                    }
                    std::hint::black_box(checksum)
                })
            });
            if path == SolverPath::ClosedForm {
                // The same cycle, LANES positions per call (Kinematics::solve_lanes).
                let mut lanes = k.empty_lane_solution();
                group.bench_function(format!("{name}/closed_form_lanes"), |b| {
                    b.iter(|| {
                        let mut checksum = 0.0;
                        for i in (0..POSITIONS).step_by(LANES) {
                            let x = std::array::from_fn(|l| {
                                std::f64::consts::TAU * (i + l) as f64 / POSITIONS as f64
                            });
                            if k.solve_lanes(x, w, &mut lanes).is_ok() {
                                let last = &lanes.points()[lanes.points().len() - 1];
                                checksum += last.acceleration.x.0.to_array().iter().sum::<f64>();
                            }
                        }
                        std::hint::black_box(checksum)
                    })
                });
            }
        }
    }
    group.finish();
}

criterion_group!(benches, cycle);
criterion_main!(benches);
