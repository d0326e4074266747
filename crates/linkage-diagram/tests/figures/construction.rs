//! The graphical construction of every vector equation of every scene file in
//! `assets/scenes`, at 36 inputs: the two unknown terms as the construction draws
//! them — from the ends of the known terms to the crossing of their direction lines,
//! a solution found by geometry from the known terms alone — equal the solver's to
//! 1e-9 of the equation's largest term, or of the mechanism's size times its crank
//! speed (squared for accelerations) where that is larger: a cam's follower at a
//! dwell has an equation of round-off only. Every equation of the shipped scenes has
//! a construction away from dead points.

use crate::common;

use common::{inputs, scenes};

use linkage::Kinematics;
use linkage::polygon::{Quantity, polygons};
use linkage_diagram::construction::{NoConstruction, construct};

#[test]
fn every_construction_crosses_where_the_solver_closes() {
    let (mut built, mut zero) = (0, 0);
    for (file, m) in scenes() {
        let mut k = Kinematics::new(m).expect("kinematics");
        for input in inputs(&k, 36) {
            let s = k.solve(input).expect("solves");
            if s.conditioning < 1e-3 {
                continue; // a dead point: the lines are (nearly) parallel
            }
            for eq in polygons(&k, &s) {
                let what = format!("{file} at {:.1}°: {}", input.to_degrees(), eq.equation);
                let pole = if eq.kind == Quantity::Velocity {
                    "p"
                } else {
                    "p'"
                };
                match construct(&eq, pole, "x") {
                    Ok(steps) => {
                        // The two unknowns, drawn last, from the lines' points to the
                        // crossing: each must be the solver's term.
                        let last = steps.last().expect("steps");
                        let w = k.mechanism().driver.speed_rad_s.abs();
                        let motion = match eq.kind {
                            Quantity::Velocity => k.mechanism().size_m * w,
                            _ => k.mechanism().size_m * w * w,
                        };
                        let scale = eq.largest_term().max(motion);
                        for arrow in &last.figure.arrows[last.figure.arrows.len() - 2..] {
                            let term = eq
                                .lhs
                                .iter()
                                .chain(&eq.rhs)
                                .find(|t| t.symbol == arrow.symbol)
                                .expect("a term");
                            assert!(
                                !(term.magnitude_known && term.direction_known),
                                "{what}: {} drawn last",
                                term.symbol
                            );
                            let v = [arrow.to[0] - arrow.from[0], arrow.to[1] - arrow.from[1]];
                            let err = (v[0] - term.vector[0]).hypot(v[1] - term.vector[1]);
                            assert!(
                                err <= 1e-9 * scale,
                                "{what}: {} constructed {v:?}, solver {:?}",
                                term.symbol,
                                term.vector
                            );
                        }
                        assert!(steps.len() >= 3, "{what}");
                        built += 1;
                    }
                    Err(NoConstruction::ZeroUnknown(_)) => zero += 1,
                    Err(e) => panic!("{what}: {e}"),
                }
            }
        }
    }
    println!("{built} constructions, {zero} with an unknown that is zero there");
    assert!(built >= 600, "{built}");
}
