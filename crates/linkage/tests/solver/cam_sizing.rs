//! Sizing a disc cam against closed forms written here:
//! - a flat-faced translating follower (pressure angle 0) on a cycloidal rise and
//!   return: its contact force m ω² s'' + k s + F₀ + P at every angle to 1e-9, and the
//!   least preload at the angle where d/du of −(m ω² s'' + k s) vanishes,
//!   cos 2πu = K / (K − 2πA) (A = m ω² h 2π/β², K = k h), to 1e-9;
//! - a radial roller follower's smallest base circle for a 30° pressure angle: at that
//!   circle the largest of atan(s' / (R_p + s)) is 30° to 1e-9, and a circle a
//!   millionth smaller exceeds it.

use linkage::cam::{DiscCam, Face, Follower, FollowerLoad, Law, Program, Segment, SegmentKind};

const PI: f64 = std::f64::consts::PI;
const H: f64 = 0.03;
const BETA: f64 = 100.0 * PI / 180.0;

fn program() -> Program {
    let seg = |kind, angle_rad| Segment { kind, angle_rad };
    Program::new(vec![
        seg(
            SegmentKind::Rise {
                law: Law::Cycloidal,
                lift: H,
            },
            BETA,
        ),
        seg(SegmentKind::Dwell, PI - 2.0 * BETA + 0.5),
        seg(
            SegmentKind::Return {
                law: Law::Cycloidal,
                lift: H,
            },
            BETA,
        ),
        seg(SegmentKind::Dwell, PI - 0.5),
    ])
    .expect("a turn")
}

/// The cycloidal rise's s and d²s/dθ² at cam angle θ within it.
fn rise(theta: f64) -> (f64, f64) {
    let u = theta / BETA;
    let w = 2.0 * PI;
    (
        H * (u - (w * u).sin() / w),
        H * w * (w * u).sin() / (BETA * BETA),
    )
}

#[test]
fn a_flat_faced_followers_contact_force_and_least_preload_are_the_closed_forms() {
    let cam = DiscCam::new(
        program(),
        0.05,
        Follower::Translating {
            offset_m: 0.0,
            face: Face::Flat,
        },
    )
    .expect("fits");
    let (mass, k, w) = (1.5, 2000.0, 30.0);
    let load = FollowerLoad {
        inertia: mass,
        spring_rate: k,
        preload: 40.0,
        load: 5.0,
    };
    for i in 0..200 {
        let theta = BETA * (i as f64 + 0.5) / 200.0;
        let (s, a) = rise(theta);
        let want = mass * w * w * a + k * s + 40.0 + 5.0;
        let got = cam.contact(theta, w, &load).force_n;
        assert!(
            (got - want).abs() <= 1e-9 * want.abs().max(1.0),
            "at {theta}: {got} vs {want}"
        );
    }
    // The least preload with no load: −(m ω² s'' + k s) is largest on the rise where
    // cos 2πu = K / (K − 2πA); the return is its mirror.
    let unloaded = FollowerLoad {
        load: 0.0,
        preload: 0.0,
        ..load
    };
    let a_amp = mass * w * w * H * 2.0 * PI / (BETA * BETA);
    let kk = k * H;
    let u = (kk / (kk - 2.0 * PI * a_amp)).acos() / (2.0 * PI);
    // Of the two roots in (0, 1) the one with sin 2πu > 0 is the hold-off's peak
    // (s'' < 0 on the rise's second half).
    let u = if (2.0 * PI * u).sin() < 0.0 {
        u
    } else {
        1.0 - u
    };
    let (s, a) = rise(u * BETA);
    let want = -(mass * w * w * a + k * s);
    let got = cam.least_preload(w, &unloaded);
    assert!((got - want).abs() <= 1e-9 * want, "{got} vs {want}");
    // With that preload the contact force touches zero and never goes below.
    let held = FollowerLoad {
        preload: got,
        ..unloaded
    };
    let least = (0..3600)
        .map(|i| cam.contact(2.0 * PI * i as f64 / 3600.0, w, &held).force_n)
        .fold(f64::INFINITY, f64::min);
    assert!(least >= -1e-9 * want && least <= 1e-3 * want, "{least}");
}

#[test]
fn the_smallest_base_circle_meets_the_pressure_angle_limit() {
    let rr = 0.008;
    let follower = Follower::Translating {
        offset_m: 0.0,
        face: Face::Roller { radius_m: rr },
    };
    let cam = DiscCam::new(program(), 0.05, follower).expect("fits");
    let limit = 30f64.to_radians();
    let rb = cam.smallest_base_radius(limit).expect("a radius");
    // The largest pressure angle on the rise (the return mirrors it) for a prime
    // radius rp: a scan and a ternary search of atan(s'/(rp + s)).
    let worst = |rp: f64| {
        let phi = |t: f64| {
            let u = t / BETA;
            let s = H * (u - (2.0 * PI * u).sin() / (2.0 * PI));
            let v = H * (1.0 - (2.0 * PI * u).cos()) / BETA;
            (v / (rp + s)).atan()
        };
        let n = 20_000;
        let at = |i: usize| BETA * i as f64 / n as f64;
        let best = (0..=n)
            .max_by(|&i, &j| phi(at(i)).total_cmp(&phi(at(j))))
            .expect("samples");
        let (mut lo, mut hi) = (at(best.saturating_sub(1)), at((best + 1).min(n)));
        for _ in 0..200 {
            let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
            if phi(m1) < phi(m2) { lo = m1 } else { hi = m2 }
        }
        phi(0.5 * (lo + hi))
    };
    assert!(
        (worst(rb + rr) - limit).abs() <= 1e-9 * limit,
        "{}",
        worst(rb + rr).to_degrees()
    );
    assert!(worst(rb * (1.0 - 1e-6) + rr) > limit);
    let e = cam
        .smallest_base_radius(95f64.to_radians())
        .expect_err("past 90°");
    assert!(e.to_string().contains("between 0 and 90"), "{e}");
}

/// A roller that keeps the pressure angle within the limit on its own (a small lift
/// on a large roller) gives the search's floor, at once: the search used to halve
/// towards a base circle of zero and never end (found by `cam_random.rs`).
#[test]
fn a_roller_that_meets_the_limit_alone_gives_the_floor() {
    let rr = 0.02;
    let follower = Follower::Translating {
        offset_m: -0.0008,
        face: Face::Roller { radius_m: rr },
    };
    let seg = |kind, angle_rad| Segment { kind, angle_rad };
    let small = Program::new(vec![
        seg(
            SegmentKind::Rise {
                law: Law::ModifiedSine,
                lift: 0.0005,
            },
            3.0,
        ),
        seg(
            SegmentKind::Return {
                law: Law::SimpleHarmonic,
                lift: 0.0005,
            },
            2.0 * PI - 3.0,
        ),
    ])
    .expect("a turn");
    let cam = DiscCam::new(small, 0.0035, follower).expect("fits");
    let rb = cam
        .smallest_base_radius(40f64.to_radians())
        .expect("a radius");
    assert!(rb > 0.0 && rb <= 1e-9 * 0.0035 * 1.000001, "{rb}");
    let sized = DiscCam::new(cam.program.clone(), rb, follower).expect("a cam");
    let worst = sized
        .extremes()
        .pressure_by_segment
        .iter()
        .map(|e| e.value.abs())
        .fold(0.0, f64::max);
    assert!(worst <= 40f64.to_radians(), "{}", worst.to_degrees());
}
