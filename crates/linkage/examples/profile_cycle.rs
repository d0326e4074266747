//! Runs 20 cycles of 3600 positions of the paper-cup four-bar for profilers:
//! `valgrind --tool=callgrind target/release/examples/profile_cycle [newton]`.
use linkage::{Kinematics, Mechanism};
fn main() {
    let text = r#"Scene(name: "four-bar", models: Kinematics, length_unit: Millimetre,
        links: [
            (name: "ground", ground: true, points: {"A": (0.0, 0.0), "D": (200.0, 0.0)}),
            (name: "crank", points: {"A": (0.0, 0.0), "B": (50.0, 0.0)}),
            (name: "coupler", points: {"B": (0.0, 0.0), "C": (180.0, 0.0)}),
            (name: "rocker", points: {"D": (0.0, 0.0), "C": (120.0, 0.0)}),
        ],
        driver: (link: "crank", speed: Rpm(45.0)),
        branches: {"C": Left("B", "D")})"#;
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
