//! Cam motion laws against the textbooks and against their own derivatives:
//! - each law's peak coefficients C_v, C_a, C_j against closed forms written here
//!   (simple harmonic π/2, π²/2, π³/2; cycloidal 2, 2π, 4π²; 3-4-5 15/8, 10/√3, 60;
//!   4-5-6-7 35/16, 7.5132, 52.5) to 1e-9, and against the published values of the
//!   modified laws (Rothbart, Cam Design Handbook, table 3.1; Makino's MCV 50) to their
//!   four or five digits;
//! - v, a and j against central differences of s, v and a at 199 points of each law
//!   (to 1e-6 of the law's peak), which checks the closed-form integration of the
//!   modified laws piece by piece;
//! - each law's continuity class at its joins with dwells, and a program's follower
//!   motion per radian of cam.

use linkage::cam::{Continuity, Law, Program, Segment, SegmentKind, peak_coefficients};

const PI: f64 = std::f64::consts::PI;

fn close(got: f64, want: f64, rel: f64, what: &str) {
    assert!(
        (got - want).abs() <= rel * want.abs(),
        "{what}: {got} vs {want}"
    );
}

#[test]
fn peak_coefficients_are_the_textbooks() {
    let exact = [
        (
            Law::SimpleHarmonic,
            [PI / 2.0, PI * PI / 2.0, PI.powi(3) / 2.0],
        ),
        (Law::Cycloidal, [2.0, 2.0 * PI, 4.0 * PI * PI]),
        (Law::Polynomial345, [15.0 / 8.0, 10.0 / 3f64.sqrt(), 60.0]),
        (Law::Polynomial4567, [35.0 / 16.0, 7.513_188, 52.5]),
    ];
    for (law, [cv, ca, cj]) in exact {
        let p = peak_coefficients(law);
        close(p.velocity, cv, 1e-9, law.label());
        // The 4-5-6-7's C_a is 84/(5√5)·… ; its published value has 7 digits.
        let rel = if law == Law::Polynomial4567 {
            1e-7
        } else {
            1e-9
        };
        close(p.acceleration, ca, rel, law.label());
        close(p.jerk, cj, 1e-9, law.label());
    }
    let published = [
        (Law::ModifiedTrapezoid, [2.0, 4.8881, 61.426]),
        (Law::ModifiedSine, [1.7596, 5.5280, 69.466]),
        (Law::ModifiedConstantVelocity, [1.2753, 8.0127, 201.38]),
    ];
    for (law, [cv, ca, cj]) in published {
        let p = peak_coefficients(law);
        close(p.velocity, cv, 5e-5, law.label());
        close(p.acceleration, ca, 5e-5, law.label());
        close(p.jerk, cj, 5e-5, law.label());
    }
}

#[test]
fn each_derivative_is_the_difference_of_the_one_before() {
    for law in Law::ALL {
        let p = peak_coefficients(law);
        let h = 1e-6;
        for i in 1..200 {
            let u = i as f64 / 200.0;
            let (lo, mid, hi) = (law.at(u - h), law.at(u), law.at(u + h));
            let d = |a: f64, b: f64| (b - a) / (2.0 * h);
            let what = format!("{} at {u}", law.label());
            // Where a piece ends (u = k/16) the jerk steps: the central differences of
            // v and a straddle it.
            let at_corner = (u * 16.0 - (u * 16.0).round()).abs() < 1e-9;
            let dv = d(lo.s, hi.s) - mid.v;
            assert!(dv.abs() <= 1e-6 * p.velocity.max(1.0), "{what}: v");
            if !at_corner {
                let (da, dj) = (d(lo.v, hi.v) - mid.a, d(lo.a, hi.a) - mid.j);
                assert!(da.abs() <= 1e-6 * p.acceleration.max(1.0), "{what}: a");
                assert!(dj.abs() <= 1e-5 * p.jerk.max(1.0), "{what}: j");
            }
        }
        let (start, end) = (law.at(0.0), law.at(1.0));
        assert!(
            start.s.abs() <= 1e-12 && (end.s - 1.0).abs() <= 1e-12,
            "{}",
            law.label()
        );
    }
}

/// A rise by `law`, a dwell, a return by `law`, a dwell.
fn rise_dwell_return(law: Law) -> Program {
    let seg = |kind, deg: f64| Segment {
        kind,
        angle_rad: deg.to_radians(),
    };
    Program::new(vec![
        seg(SegmentKind::Rise { law, lift: 0.02 }, 120.0),
        seg(SegmentKind::Dwell, 60.0),
        seg(SegmentKind::Return { law, lift: 0.02 }, 90.0),
        seg(SegmentKind::Dwell, 90.0),
    ])
    .expect("a turn")
}

#[test]
fn each_law_joins_its_dwells_in_its_textbook_class() {
    let class = [
        (Law::ConstantVelocity, Continuity::C0),
        (Law::SimpleHarmonic, Continuity::C1),
        (Law::Cycloidal, Continuity::C2),
        (Law::Polynomial345, Continuity::C2),
        (Law::Polynomial4567, Continuity::C3),
        (Law::ModifiedTrapezoid, Continuity::C2),
        (Law::ModifiedSine, Continuity::C2),
        (Law::ModifiedConstantVelocity, Continuity::C2),
    ];
    for (law, want) in class {
        let joins = rise_dwell_return(law).joins();
        assert_eq!(joins.len(), 4);
        let worst = joins.iter().map(|j| j.continuity).min().expect("joins");
        assert_eq!(worst, want, "{}: {joins:?}", law.label());
    }
}

#[test]
fn a_program_scales_the_law_by_its_lift_and_angle() {
    let p = rise_dwell_return(Law::Cycloidal);
    let beta = 120f64.to_radians();
    // Half-way up the cycloidal rise: s = h/2, v = 2h/β, a = 0.
    let m = p.at(0.5 * beta);
    close(m.s, 0.01, 1e-12, "s");
    close(m.v, 2.0 * 0.02 / beta, 1e-12, "v");
    assert!(m.a.abs() <= 1e-12 * 0.02 / (beta * beta));
    // On the dwell the follower stands at the lift; half-way down the return (90°):
    // the cycloidal's velocity −2h/β.
    assert_eq!(p.at(150f64.to_radians()).s, 0.02);
    let back = p.at(225f64.to_radians());
    close(back.s, 0.01, 1e-12, "return s");
    close(back.v, -2.0 * 0.02 / 90f64.to_radians(), 1e-12, "return v");
    // The next turn repeats.
    let next = p.at(0.5 * beta + std::f64::consts::TAU);
    close(next.s, m.s, 1e-12, "next turn s");
    close(next.v, m.v, 1e-12, "next turn v");
}

#[test]
fn a_program_that_is_not_a_turn_is_refused_with_its_sum() {
    let e = Program::new(vec![Segment {
        kind: SegmentKind::Rise {
            law: Law::Cycloidal,
            lift: 0.01,
        },
        angle_rad: 3.0,
    }])
    .expect_err("3 rad is not a turn");
    let text = e.to_string();
    assert!(
        text.contains("sum of the segment angles") && text.contains("2π"),
        "{text}"
    );
    let e = Program::new(vec![Segment {
        kind: SegmentKind::Rise {
            law: Law::Cycloidal,
            lift: f64::NAN,
        },
        angle_rad: std::f64::consts::TAU,
    }])
    .expect_err("a NaN lift");
    assert!(e.to_string().contains("segment 0 lift"), "{e}");
}
