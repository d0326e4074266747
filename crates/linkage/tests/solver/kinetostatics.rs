//! Kinetostatics of the die cutter (paper 2): the input torque by virtual work and by
//! Newton–Euler agree to 1e-9 of the cycle's peak; with the 2 MN pressing force the
//! torque times the force amplification gives back the pressing force (the links'
//! inertia at 50 rpm is negligible beside it); the amplification grows without bound
//! at the toggle and is never reported as infinity.

use crate::common;

use common::{kinematics, mechanism};
use linkage::kinetostatics::Kinetostatics;
use linkage::scene::SolverPath;
use linkage::{Kinematics, LinkageError, SceneProblem};

#[test]
fn virtual_work_and_newton_euler_agree_over_the_cycle() {
    for path in [SolverPath::ClosedForm, SolverPath::Newton] {
        let mut k = kinematics("die_cutter.ron", path);
        let mut ks = Kinetostatics::new(&mut k).expect("kinetostatics");
        let states: Vec<_> = (0..720)
            .map(|i| {
                ks.at(&mut k, f64::from(i) * 0.5f64.to_radians())
                    .expect("state")
            })
            .collect();
        let peak = states
            .iter()
            .map(|s| s.torque_newton_euler.abs())
            .fold(0.0, f64::max);
        assert!(peak > 4e4 && peak < 6e4, "peak torque {peak} N·m");
        for s in &states {
            let diff = (s.torque_newton_euler - s.torque_virtual_work).abs();
            assert!(diff <= 1e-9 * peak, "at {} rad: {diff:e} N·m", s.input_rad);
            assert!(
                s.joints
                    .iter()
                    .all(|j| j.force.0.is_finite() && j.force.1.is_finite())
            );
        }
    }
}

#[test]
fn torque_times_amplification_is_the_pressing_force() {
    let mut k = kinematics("die_cutter.ron", SolverPath::Auto);
    let mut ks = Kinetostatics::new(&mut k).expect("kinetostatics");
    let mut working = 0;
    for i in 0..360 {
        let s = ks.at(&mut k, f64::from(i).to_radians()).expect("state");
        let Some(amp) = s.amplification else { continue };
        let output_force = s.torque_newton_euler * amp;
        if output_force.abs() > 1e5 {
            // Working stroke: 2 MN plus the die's weight (1.2 kN) and inertia.
            working += 1;
            assert!(
                (output_force / 2e6 - 1.0).abs() < 2e-3,
                "at {i} deg: {output_force} N"
            );
        } else {
            // Return stroke: only the die's 120 kg moves the torque.
            assert!(output_force.abs() < 3e3, "at {i} deg: {output_force} N");
        }
    }
    assert!(working > 100, "{working} working positions");
}

#[test]
fn amplification_peaks_at_the_toggle_and_stays_finite() {
    let mut k = kinematics("die_cutter.ron", SolverPath::Auto);
    let mut ks = Kinetostatics::new(&mut k).expect("kinetostatics");
    let amps: Vec<Option<f64>> = (0..3600)
        .map(|i| {
            ks.at(&mut k, f64::from(i) * 0.1f64.to_radians())
                .expect("state")
                .amplification
        })
        .collect();
    assert!(amps.iter().flatten().all(|a| a.is_finite() && *a > 0.0));
    let top = amps.iter().flatten().fold(0.0_f64, |a, &b| a.max(b));
    assert!(top > 1e5, "peak amplification {top} N per N·m");
}

#[test]
fn a_kinematics_only_scene_is_refused_with_the_reason() {
    let mut k = Kinematics::new(mechanism("slider_crank.ron")).expect("scene");
    let err = Kinetostatics::new(&mut k).err().expect("refused");
    assert!(
        matches!(&err, LinkageError::SceneInvalid(why)
            if matches!(&**why, SceneProblem::KinematicsOnly { scene } if !scene.is_empty())),
        "{err}"
    );
}
