//! The follower's outline (what the cam figures draw) against the cam it runs on, at
//! every 5 degrees of the turn, with the closed forms written here: a translating
//! follower's tip on its line x = e at y = √(r_p² − e²) + s(θ) (r_p the base radius
//! plus the roller's), its stem on that line; a roller one roller radius from the
//! profile's point, a knife edge on it; every contact of a flat face's turn on the
//! face drawn; an oscillating arm its given length from its given pivot. All to 1e-9
//! of the base radius.

use linkage::cam::{DiscCam, Face, Follower, Law, Program, Segment, SegmentKind};

const PI: f64 = std::f64::consts::PI;
const BASE: f64 = 0.05;
const LIFT: f64 = 0.02;
const TOL: f64 = 1e-9 * BASE;

/// A harmonic rise over 150°, a dwell, a harmonic return over 150°, a dwell.
fn program(lift: f64) -> Program {
    let part = |kind, deg: f64| Segment {
        kind,
        angle_rad: deg.to_radians(),
    };
    let law = Law::SimpleHarmonic;
    Program::new(vec![
        part(SegmentKind::Rise { law, lift }, 150.0),
        part(SegmentKind::Dwell, 30.0),
        part(SegmentKind::Return { law, lift }, 150.0),
        part(SegmentKind::Dwell, 30.0),
    ])
    .expect("a turn")
}

/// The harmonic program's lift at `theta`, written out.
fn lift_at(theta: f64) -> f64 {
    let deg = theta.to_degrees();
    let harmonic = |u: f64| LIFT * 0.5 * (1.0 - (PI * u).cos());
    match deg {
        d if d < 150.0 => harmonic(d / 150.0),
        d if d < 180.0 => LIFT,
        d if d < 330.0 => LIFT - harmonic((d - 180.0) / 150.0),
        _ => 0.0,
    }
}

fn angles() -> impl Iterator<Item = f64> {
    (0..72).map(|i| f64::from(i) * 5.0_f64.to_radians())
}

/// `p` (in the cam's own frame) where it is with the cam turned by `theta`.
fn in_frame([x, y]: [f64; 2], theta: f64) -> [f64; 2] {
    let (s, c) = theta.sin_cos();
    [c * x - s * y, s * x + c * y]
}

fn distance(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

#[test]
fn a_translating_follower_stands_on_its_line_touching_the_profile() {
    let e = 0.012;
    for (face, roller) in [
        (Face::Roller { radius_m: 0.01 }, 0.01),
        (Face::KnifeEdge, 0.0),
    ] {
        let follower = Follower::Translating { offset_m: e, face };
        let cam = DiscCam::new(program(LIFT), BASE, follower).expect("a cam");
        let rp: f64 = BASE + roller;
        for theta in angles() {
            let o = cam.follower_outline(theta);
            let y = (rp * rp - e * e).sqrt() + lift_at(theta);
            assert!(
                distance(o.tip_m, [e, y]) < TOL,
                "{face:?} at {theta}: tip {:?}",
                o.tip_m
            );
            assert!(
                o.stem_m.iter().all(|p| (p[0] - e).abs() < TOL),
                "stem {:?}",
                o.stem_m
            );
            assert!(
                o.stem_m[1][1] > o.stem_m[0][1],
                "the stem runs away from the cam"
            );
            let profile = in_frame(cam.at(theta).profile_m, theta);
            assert!(
                (distance(o.tip_m, profile) - roller).abs() < TOL,
                "{face:?} at {theta}"
            );
            assert_eq!(o.roller_radius_m, (roller > 0.0).then_some(roller));
            assert!(o.guide_m.is_some() && o.pivot_m.is_none() && o.flat_face_m.is_none());
        }
    }
}

#[test]
fn a_flat_face_is_wide_enough_for_every_contact_of_the_turn() {
    let e = 0.004;
    let follower = Follower::Translating {
        offset_m: e,
        face: Face::Flat,
    };
    let cam = DiscCam::new(program(LIFT), BASE, follower).expect("a cam");
    let face = cam.follower_outline(0.0).flat_face_m.expect("a flat face");
    for theta in angles() {
        let contact = in_frame(cam.at(theta).pitch_m, theta);
        // The face at this angle: the one drawn at 0, raised by the lift.
        let y = BASE + lift_at(theta);
        assert!(
            (contact[1] - y).abs() < TOL,
            "at {theta}: contact {contact:?}"
        );
        assert!(
            face[0][0] < contact[0] && contact[0] < face[1][0],
            "at {theta}: {contact:?} off {face:?}"
        );
        assert!((face[0][1] - BASE).abs() < TOL && (face[1][1] - BASE).abs() < TOL);
    }
}

#[test]
fn an_oscillating_arm_is_its_length_from_its_pivot() {
    let (pivot, arm) = (0.1, 0.08);
    let follower = Follower::Oscillating {
        pivot_m: pivot,
        arm_m: arm,
        face: Face::Roller { radius_m: 0.008 },
    };
    let cam = DiscCam::new(program(0.3), BASE, follower).expect("a cam");
    for theta in angles() {
        let o = cam.follower_outline(theta);
        assert_eq!(o.pivot_m, Some([pivot, 0.0]));
        assert!(
            (distance(o.tip_m, [pivot, 0.0]) - arm).abs() < TOL,
            "at {theta}"
        );
        assert_eq!(o.stem_m, [o.tip_m, [pivot, 0.0]]);
        let profile = in_frame(cam.at(theta).profile_m, theta);
        assert!(
            (distance(o.tip_m, profile) - 0.008).abs() < TOL,
            "at {theta}"
        );
    }
}
