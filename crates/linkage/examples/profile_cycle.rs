//! Runs 20 cycles of 3600 positions of the paper-cup four-bar for profilers:
//! `valgrind --tool=callgrind target/release/examples/profile_cycle [newton|lanes]`.
use linkage::LANES;
use linkage::{Kinematics, Mechanism};
fn main() {
    let text = include_str!("../benches/four_bar.ron");
    let arg = |name: &str| std::env::args().any(|a| a == name);
    let path = if arg("newton") {
        linkage::scene::SolverPath::Newton
    } else {
        linkage::scene::SolverPath::ClosedForm
    };
    let mut k = Kinematics::with_path(Mechanism::from_ron(text).expect("scene"), path).expect("k");
    let mut s = k.empty_solution();
    let mut lanes = k.empty_lane_solution();
    let mut acc = 0.0;
    for _ in 0..20 {
        if arg("lanes") {
            for i in (0..3600).step_by(LANES) {
                let x = std::array::from_fn(|l| std::f64::consts::TAU * (i + l) as f64 / 3600.0);
                if k.solve_lanes(x, 4.7, &mut lanes).is_ok() {
                    acc += lanes.points()[3].acceleration.x.0.to_array()[0];
                }
            }
        } else {
            for i in 0..3600 {
                let x = std::f64::consts::TAU * i as f64 / 3600.0;
                if k.solve_into(x, 4.7, &mut s).is_ok() {
                    acc += s.points[3].acceleration.x;
                }
            }
        }
    }
    println!("{acc}");
}
