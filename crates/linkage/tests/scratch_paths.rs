use linkage::{Kinematics, Mechanism, scene::SolverPath};

#[test]
fn scratch() {
    for f in ["slider_crank.ron", "gravity_flipper.ron"] {
        let text = std::fs::read_to_string(format!(
            "{}/../../assets/scenes/{f}",
            env!("CARGO_MANIFEST_DIR")
        ))
        .unwrap();
        let m = Mechanism::from_ron(&text).unwrap();
        let mut cf = Kinematics::with_path(m.clone(), SolverPath::ClosedForm).unwrap();
        let mut nw = Kinematics::with_path(m.clone(), SolverPath::Newton).unwrap();
        let mut worst: f64 = 0.0;
        for i in 0..360 {
            let x = m.driver.start_rad + (i as f64).to_radians() * 0.1;
            let (a, b) = (cf.solve(x), nw.solve(x));
            match (a, b) {
                (Ok(a), Ok(b)) => {
                    for (p, q) in a.points.iter().zip(&b.points) {
                        worst = worst
                            .max((p.position - q.position).amax())
                            .max((p.velocity - q.velocity).amax())
                            .max((p.acceleration - q.acceleration).amax());
                    }
                }
                (a, b) => {
                    println!("{f} {x}: {:?} / {:?}", a.err(), b.err());
                    break;
                }
            }
        }
        println!("{f}: worst diff {worst:e}");
        let r = linkage::analysis::report(&mut cf).unwrap();
        println!("{r:#?}");
    }
}
