//! Runs 20 cycles of 3600 positions of the paper-cup four-bar for profilers:
//! `valgrind --tool=callgrind target/release/examples/profile_cycle [newton]`.
use linkage::{Kinematics, Mechanism};
fn main() {
    let text = include_str!("../benches/four_bar.ron");
    let path = if std::env::args().any(|a| a == "newton") {
        linkage::scene::SolverPath::Newton
    } else {
        linkage::scene::SolverPath::ClosedForm
    };
    let mut k = Kinematics::with_path(Mechanism::from_ron(text).expect("scene"), path).expect("k");
    let mut s = k.empty_solution();
    let mut acc = 0.0;
    for _ in 0..20 {
        for i in 0..3600 {
            let x = std::f64::consts::TAU * i as f64 / 3600.0;
            if k.solve_into(x, 4.7, &mut s).is_ok() {
                acc += s.points[3].acceleration.x;
            }
        }
    }
    println!("{acc}");
}
