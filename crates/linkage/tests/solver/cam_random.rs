//! Cams nobody chose: random programs (two to six segments, any law, lifts from
//! 1e-5 to 10 m scaled with the base circle, angles that add up to a turn) on random
//! followers (translating with any offset that fits, knife edge, roller or flat; an
//! oscillating roller whose arm reaches the prime circle). Every cam angle gives
//! finite points and figures, the pressure angle lies in [−90°, 90°], the
//! program's joins are classed, the extremes are finite, the least preload is not
//! negative, and a reachable pressure-angle limit gives a base circle that meets it.
//! `LINKAGE_CAM_CASES` sets the cases per generator (64 by default).

use linkage::cam::{DiscCam, Face, Follower, FollowerLoad, Law, Program, Segment, SegmentKind};
use proptest::prelude::*;

const TAU: f64 = std::f64::consts::TAU;

fn cases() -> u32 {
    std::env::var("LINKAGE_CAM_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(64)
}

/// A program from weights (for the angles), kinds and laws, rising and returning by
/// `lift` in turn so that it closes.
fn program(weights: &[f64], laws: &[usize], lift: f64) -> Program {
    let total: f64 = weights.iter().sum();
    let mut up = true;
    let segments = weights
        .iter()
        .zip(laws)
        .enumerate()
        .map(|(i, (&w, &l))| {
            let law = Law::ALL[l % Law::ALL.len()];
            // Odd counts end on a dwell so that every rise has its return.
            let last_odd = weights.len() % 2 == 1 && i == weights.len() - 1;
            let kind = if last_odd {
                SegmentKind::Dwell
            } else if up {
                SegmentKind::Rise { law, lift }
            } else {
                SegmentKind::Return { law, lift }
            };
            up = !up;
            Segment {
                kind,
                angle_rad: TAU * w / total,
            }
        })
        .collect();
    Program::new(segments).expect("a turn")
}

fn check(cam: &DiscCam) -> Result<(), TestCaseError> {
    for i in 0..720 {
        let p = cam.at(TAU * i as f64 / 720.0);
        let all = [
            p.pitch_m[0],
            p.pitch_m[1],
            p.profile_m[0],
            p.profile_m[1],
            p.pressure_angle_rad,
        ];
        prop_assert!(all.iter().all(|v| v.is_finite()), "{p:?}");
        prop_assert!(p.pressure_angle_rad.abs() <= 0.5 * std::f64::consts::PI + 1e-12);
        prop_assert!(!p.pitch_radius_m.is_nan() && !p.profile_radius_m.is_nan());
    }
    prop_assert_eq!(cam.program.joins().len(), cam.program.segments().len());
    let x = cam.extremes();
    prop_assert!(x.pressure_by_segment.iter().all(|e| e.value.is_finite()));
    let load = FollowerLoad {
        inertia: 2.0,
        spring_rate: 1e3,
        preload: 0.0,
        load: 0.0,
    };
    let preload = cam.least_preload(10.0, &load);
    prop_assert!(preload.is_finite() && preload >= 0.0);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), .. ProptestConfig::default() })]

    #[test]
    fn random_translating_cams(
        weights in prop::collection::vec(0.2f64..3.0, 2..7),
        laws in prop::collection::vec(0usize..8, 6),
        scale in -3.0f64..1.0,
        lift_share in 0.05f64..2.0,
        offset_share in -0.9f64..0.9,
        face in 0usize..3,
        roller_share in 0.05f64..0.8,
    ) {
        let rb = 10f64.powf(scale);
        let face = match face {
            0 => Face::KnifeEdge,
            1 => Face::Roller { radius_m: roller_share * rb },
            _ => Face::Flat,
        };
        let offset = if face == Face::Flat { 0.0 } else { offset_share * rb };
        let follower = Follower::Translating { offset_m: offset, face };
        let cam = DiscCam::new(program(&weights, &laws[..weights.len()], lift_share * rb), rb, follower)
            .expect("fits");
        check(&cam)?;
        if face != Face::Flat {
            let limit = 40f64.to_radians();
            let r = cam.smallest_base_radius(limit).expect("reachable");
            let sized = DiscCam::new(cam.program.clone(), r, follower).expect("fits");
            let worst = sized
                .extremes()
                .pressure_by_segment
                .iter()
                .map(|e| e.value.abs())
                .fold(0.0, f64::max);
            prop_assert!(worst <= limit * (1.0 + 1e-9), "{} at {r}", worst.to_degrees());
        }
    }

    #[test]
    fn random_oscillating_cams(
        weights in prop::collection::vec(0.2f64..3.0, 2..7),
        laws in prop::collection::vec(0usize..8, 6),
        scale in -3.0f64..1.0,
        swing_deg in 1.0f64..30.0,
        arm_share in 1.0f64..4.0,
        roller_share in 0.05f64..0.8,
    ) {
        let rb = 10f64.powf(scale);
        let rr = roller_share * rb;
        let arm = arm_share * rb;
        // The pivot where the arm stands at right angles to the radius at the base.
        let pivot = ((rb + rr).powi(2) + arm * arm).sqrt();
        let follower = Follower::Oscillating { pivot_m: pivot, arm_m: arm, face: Face::Roller { radius_m: rr } };
        let cam = DiscCam::new(
            program(&weights, &laws[..weights.len()], swing_deg.to_radians()),
            rb,
            follower,
        )
        .expect("fits");
        check(&cam)?;
    }
}
