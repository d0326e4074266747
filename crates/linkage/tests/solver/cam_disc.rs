//! Disc cams against closed forms written here, independent of the cam code:
//! - an offset translating roller follower with a cycloidal rise and a modified-sine
//!   return (both laws' s, s', s'' written out, the modified sine as Norton's three
//!   pieces): the profile point as the pitch point moved in by the roller along the
//!   normal at the pressure angle tan φ = (s' − e)/(d + s), d = √(r_p² − e²); the
//!   pitch curve's radius of curvature
//!   ρ = [(d+s)² + (s'−e)²]^{3/2} / [(d+s)² + (s'−e)(2s'−e) − (d+s)s''];
//! - an oscillating roller follower: the pitch curve's coordinates on the cam and
//!   their derivatives written out by the product rule, the pressure angle from the
//!   no-penetration condition tan φ = (l s' − d cos γ − l)/(d sin γ).
//!
//! Profile points to 1e-9 of the base radius, pressure angles and radii at every
//! sample to 1e-9 relative, and the largest pressure angle per segment and the
//! smallest radius of curvature (found by each side's own search) to 1e-9 relative.

use linkage::cam::{DiscCam, Face, Follower, Law, Program, Segment, SegmentKind};

const PI: f64 = std::f64::consts::PI;
const H: f64 = 0.02;
const RB: f64 = 0.04;
const RR: f64 = 0.01;
const E: f64 = 0.008;
const RISE: f64 = 120.0 * PI / 180.0;
const DWELL: f64 = 60.0 * PI / 180.0;
const FALL: f64 = 100.0 * PI / 180.0;

fn program(lift: f64) -> Program {
    let seg = |kind, angle_rad| Segment { kind, angle_rad };
    Program::new(vec![
        seg(
            SegmentKind::Rise {
                law: Law::Cycloidal,
                lift,
            },
            RISE,
        ),
        seg(SegmentKind::Dwell, DWELL),
        seg(
            SegmentKind::Return {
                law: Law::ModifiedSine,
                lift,
            },
            FALL,
        ),
        seg(SegmentKind::Dwell, 2.0 * PI - RISE - DWELL - FALL),
    ])
    .expect("a turn")
}

/// Cycloidal rise: s, s', s'' by u, for a lift of 1.
fn cycloidal(x: f64) -> [f64; 3] {
    let w = 2.0 * PI;
    [
        x - (w * x).sin() / w,
        1.0 - (w * x).cos(),
        w * (w * x).sin(),
    ]
}

/// Norton's modified sine (Design of Machinery, eq. 8.18), lift 1.
fn modified_sine(x: f64) -> [f64; 3] {
    let k = 4.0 + PI;
    if x <= 0.125 {
        let a = 4.0 * PI * x;
        [
            PI * x / k - a.sin() / (4.0 * k),
            PI / k * (1.0 - a.cos()),
            4.0 * PI * PI / k * a.sin(),
        ]
    } else if x <= 0.875 {
        let a = PI / 3.0 + 4.0 * PI * x / 3.0;
        [
            2.0 / k + PI * x / k - 9.0 * a.sin() / (4.0 * k),
            PI / k - 3.0 * PI / k * a.cos(),
            4.0 * PI * PI / k * a.sin(),
        ]
    } else {
        let a = 4.0 * PI * x;
        [
            4.0 / k + PI * x / k - a.sin() / (4.0 * k),
            PI / k * (1.0 - a.cos()),
            4.0 * PI * PI / k * a.sin(),
        ]
    }
}

/// s, ds/dθ, d²s/dθ² of the test's program (lift `h`) at θ.
fn motion(theta: f64, h: f64) -> [f64; 3] {
    let t = theta.rem_euclid(2.0 * PI);
    if t < RISE {
        let [s, v, a] = cycloidal(t / RISE);
        [h * s, h * v / RISE, h * a / (RISE * RISE)]
    } else if t < RISE + DWELL {
        [h, 0.0, 0.0]
    } else if t < RISE + DWELL + FALL {
        let [s, v, a] = modified_sine((t - RISE - DWELL) / FALL);
        [h - h * s, -h * v / FALL, -h * a / (FALL * FALL)]
    } else {
        [0.0, 0.0, 0.0]
    }
}

/// The offset roller follower's pressure angle, profile point (cam frame) and pitch
/// radius of curvature, from the textbook's formulas.
fn translating_reference(theta: f64) -> (f64, [f64; 2], f64) {
    let [s, v, a] = motion(theta, H);
    let rp = RB + RR;
    let d = (rp * rp - E * E).sqrt();
    let phi = ((v - E) / (d + s)).atan();
    // In the frame: the roller's centre, then in by the roller along the normal.
    let (x, y) = (E + RR * phi.sin(), d + s - RR * phi.cos());
    let (sn, cs) = theta.sin_cos();
    let profile = [cs * x + sn * y, -sn * x + cs * y];
    let num = ((d + s).powi(2) + (v - E).powi(2)).powf(1.5);
    let den = (d + s).powi(2) + (v - E) * (2.0 * v - E) - (d + s) * a;
    (phi, profile, num / den)
}

fn translating() -> DiscCam {
    let follower = Follower::Translating {
        offset_m: E,
        face: Face::Roller { radius_m: RR },
    };
    DiscCam::new(program(H), RB, follower).expect("fits")
}

/// The largest of `f` over [a, b]: a fine scan, then a ternary search round the best.
fn reference_largest(f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let n = 20_000;
    let at = |i: usize| a + (b - a) * i as f64 / n as f64;
    let best = (0..=n)
        .max_by(|&i, &k| f(at(i)).total_cmp(&f(at(k))))
        .expect("samples");
    let (mut lo, mut hi) = (at(best.saturating_sub(1)), at((best + 1).min(n)));
    for _ in 0..200 {
        let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
        if f(m1) < f(m2) { lo = m1 } else { hi = m2 }
    }
    f(0.5 * (lo + hi)).max(f(at(best)))
}

#[test]
fn an_offset_roller_cam_matches_the_textbook_at_every_angle() {
    let cam = translating();
    for i in 0..3600 {
        let theta = 2.0 * PI * i as f64 / 3600.0;
        let p = cam.at(theta);
        let (phi, profile, rho) = translating_reference(theta);
        let gap = (p.profile_m[0] - profile[0]).hypot(p.profile_m[1] - profile[1]);
        assert!(gap <= 1e-9 * RB, "at {theta}: profile off by {gap}");
        assert!(
            (p.pressure_angle_rad - phi).abs() <= 1e-9 * phi.abs().max(1e-3),
            "at {theta}: φ"
        );
        assert!(
            (p.pitch_radius_m - rho).abs() <= 1e-9 * rho.abs(),
            "at {theta}: ρ {} vs {rho}",
            p.pitch_radius_m
        );
        assert!(
            (p.profile_radius_m - (rho - RR)).abs() <= 1e-9 * rho.abs(),
            "at {theta}"
        );
    }
}

#[test]
fn the_largest_pressure_angles_and_the_smallest_radius_are_the_textbooks() {
    let cam = translating();
    let x = cam.extremes();
    let spans = [(0.0, RISE), (RISE + DWELL, RISE + DWELL + FALL)];
    for (seg, (a, b)) in [0, 2].into_iter().zip(spans) {
        let want = reference_largest(&|t| translating_reference(t).0.abs(), a, b);
        let got = x.pressure_by_segment[seg].value.abs();
        assert!(
            (got - want).abs() <= 1e-9 * want,
            "segment {seg}: {got} vs {want}"
        );
    }
    let want = -reference_largest(
        &|t| {
            let rho = translating_reference(t).2;
            if rho > 0.0 { -rho } else { f64::NEG_INFINITY }
        },
        0.0,
        2.0 * PI,
    );
    let got = x.smallest_pitch_radius.value;
    assert!((got - want).abs() <= 1e-9 * want, "{got} vs {want}");
    assert!(!x.undercut, "{x:?}");
}

const PIVOT: f64 = 0.12;
const ARM: f64 = 0.09;
const SWING: f64 = 0.35;

fn oscillating() -> DiscCam {
    let follower = Follower::Oscillating {
        pivot_m: PIVOT,
        arm_m: ARM,
        face: Face::Roller { radius_m: RR },
    };
    DiscCam::new(program(SWING), RB, follower).expect("fits")
}

/// The oscillating roller's pressure angle, profile point and pitch radius, with the
/// pitch curve's cam-frame coordinates differentiated by the product rule.
fn oscillating_reference(theta: f64) -> (f64, [f64; 2], f64) {
    let [s, v, a] = motion(theta, SWING);
    let rp = RB + RR;
    // The roller below the line of centres, a lift swinging it outward.
    let gamma0 = -((rp * rp - PIVOT * PIVOT - ARM * ARM) / (2.0 * PIVOT * ARM)).acos();
    let g = gamma0 + s;
    // The roller centre in the frame and its derivatives by θ.
    let (cx, cy) = (PIVOT + ARM * g.cos(), ARM * g.sin());
    let (cx1, cy1) = (-ARM * g.sin() * v, ARM * g.cos() * v);
    let (cx2, cy2) = (
        -ARM * g.cos() * v * v - ARM * g.sin() * a,
        -ARM * g.sin() * v * v + ARM * g.cos() * a,
    );
    // On the cam: x = cx cos θ + cy sin θ, y = −cx sin θ + cy cos θ.
    let (sn, cs) = theta.sin_cos();
    let x1 = cx1 * cs - cx * sn + cy1 * sn + cy * cs;
    let y1 = -cx1 * sn - cx * cs + cy1 * cs - cy * sn;
    let x2 = cx2 * cs - 2.0 * cx1 * sn - cx * cs + cy2 * sn + 2.0 * cy1 * cs - cy * sn;
    let y2 = -cx2 * sn - 2.0 * cx1 * cs + cx * sn + cy2 * cs - 2.0 * cy1 * sn - cy * cs;
    let speed = x1.hypot(y1);
    let rho = -speed.powi(3) / (x1 * y2 - y1 * x2);
    // The outward normal on the cam, the profile in by the roller.
    let (nx, ny) = (-y1 / speed, x1 / speed);
    let (px, py) = (cx * cs + cy * sn, -cx * sn + cy * cs);
    let profile = [px - RR * nx, py - RR * ny];
    let phi = ((ARM * v - PIVOT * g.cos() - ARM) / (PIVOT * g.sin())).atan();
    (phi, profile, rho)
}

#[test]
fn an_oscillating_roller_cam_matches_its_closed_form_at_every_angle() {
    let cam = oscillating();
    for i in 0..3600 {
        let theta = 2.0 * PI * i as f64 / 3600.0;
        let p = cam.at(theta);
        let (phi, profile, rho) = oscillating_reference(theta);
        let gap = (p.profile_m[0] - profile[0]).hypot(p.profile_m[1] - profile[1]);
        assert!(gap <= 1e-9 * RB, "at {theta}: profile off by {gap}");
        let dphi = p.pressure_angle_rad.abs() - phi.abs();
        assert!(
            dphi.abs() <= 1e-9 * phi.abs().max(1e-3),
            "at {theta}: φ {} vs {phi}",
            p.pressure_angle_rad
        );
        assert!(
            (p.pitch_radius_m - rho).abs() <= 1e-9 * rho.abs(),
            "at {theta}: ρ"
        );
    }
    let x = cam.extremes();
    let spans = [(0.0, RISE), (RISE + DWELL, RISE + DWELL + FALL)];
    for (seg, (a, b)) in [0, 2].into_iter().zip(spans) {
        let want = reference_largest(&|t| oscillating_reference(t).0.abs(), a, b);
        let got = x.pressure_by_segment[seg].value.abs();
        assert!(
            (got - want).abs() <= 1e-9 * want,
            "segment {seg}: {got} vs {want}"
        );
    }
    let convex = |t: f64| {
        let rho = oscillating_reference(t).2;
        if rho > 0.0 { -rho } else { f64::NEG_INFINITY }
    };
    let want = -reference_largest(&convex, 0.0, 2.0 * PI);
    let got = x.smallest_pitch_radius.value;
    assert!((got - want).abs() <= 1e-9 * want, "{got} vs {want}");
}

#[test]
fn a_roller_bigger_than_the_pitch_curve_is_an_undercut_and_bad_sizes_are_named() {
    let big = Follower::Translating {
        offset_m: 0.0,
        face: Face::Roller { radius_m: 0.03 },
    };
    // A steep rise on a small cam: its pitch curve turns tighter than the roller.
    let seg = |kind, angle_rad| Segment { kind, angle_rad };
    let steep = Program::new(vec![
        seg(
            SegmentKind::Rise {
                law: Law::Cycloidal,
                lift: 0.05,
            },
            0.6,
        ),
        seg(
            SegmentKind::Return {
                law: Law::Cycloidal,
                lift: 0.05,
            },
            0.6,
        ),
        seg(SegmentKind::Dwell, 2.0 * PI - 1.2),
    ])
    .expect("a turn");
    let cam = DiscCam::new(steep, 0.01, big).expect("fits");
    assert!(cam.extremes().undercut);
    let off = Follower::Translating {
        offset_m: 0.2,
        face: Face::KnifeEdge,
    };
    let e = DiscCam::new(program(H), RB, off).expect_err("offset past the circle");
    assert!(e.to_string().contains("follower offset"), "{e}");
}

/// A lift moves the roller away from the cam's centre, for either follower: the
/// profile never comes inside the base circle, and touches it where the lift is 0.
#[test]
fn a_lift_moves_the_roller_outward_and_the_profile_stays_on_or_outside_the_base_circle() {
    let translating = DiscCam::new(
        program(H),
        RB,
        Follower::Translating {
            offset_m: 0.3 * RB,
            face: Face::Roller { radius_m: RR },
        },
    )
    .expect("fits");
    for cam in [oscillating(), translating] {
        let mut least = f64::INFINITY;
        for i in 0..3600 {
            let p = cam.at(2.0 * PI * i as f64 / 3600.0);
            let r = p.profile_m[0].hypot(p.profile_m[1]);
            assert!(r >= RB * (1.0 - 1e-12), "{r} inside the base circle {RB}");
            let pitch = p.pitch_m[0].hypot(p.pitch_m[1]);
            let outward = pitch - (RB + RR);
            assert!(
                outward >= -1e-12 * RB,
                "the pitch curve inside the prime circle"
            );
            if p.motion.s > 0.1 * H.min(SWING) {
                assert!(outward > 0.0, "a lift that does not move the roller out");
            }
            least = least.min(r);
        }
        assert!((least - RB).abs() < 1e-9 * RB, "{least}");
    }
}
