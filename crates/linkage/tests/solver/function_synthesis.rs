//! Function generation by Freudenstein's equation, checked against independent
//! references: a known four-bar's own angles (the closed form of two circles written
//! here, not the module's) give back its lengths and constants, exactly for three
//! points and by least squares for more; a designed function generator, built as a
//! scene and solved by the general solver, passes through its precision points.

use linkage::synthesis::function::{
    PrecisionPoint, chebyshev_spacing, error_curve, freudenstein, structural_error,
};
use linkage::{Kinematics, LinkageError, Mechanism};

/// Rocker angle of the four-bar (A at the origin, D at (d, 0); crank a, coupler b,
/// rocker c) at crank angle θ, C above the line B→D: two circles intersected.
fn rocker_angle(a: f64, b: f64, c: f64, d: f64, theta: f64) -> f64 {
    let (bx, by) = (a * theta.cos(), a * theta.sin());
    let (dx, dy) = (d - bx, -by);
    let dist = dx.hypot(dy);
    // Along B→D to the chord, then perpendicular (to the left of B→D).
    let along = (b * b - c * c + dist * dist) / (2.0 * dist);
    let up = (b * b - along * along).sqrt();
    let (ux, uy) = (dx / dist, dy / dist);
    let (cx, cy) = (bx + along * ux - up * uy, by + along * uy + up * ux);
    cy.atan2(cx - d)
}

fn points_of(a: f64, b: f64, c: f64, d: f64, thetas_deg: &[f64]) -> Vec<PrecisionPoint> {
    thetas_deg
        .iter()
        .map(|t| {
            let theta = t.to_radians();
            PrecisionPoint {
                input_rad: theta,
                output_rad: rocker_angle(a, b, c, d, theta),
            }
        })
        .collect()
}

fn close(what: &str, x: f64, y: f64) {
    assert!(
        (x - y).abs() <= 1e-9 * y.abs().max(1.0),
        "{what}: {x} vs {y}"
    );
}

#[test]
fn three_angles_of_a_known_four_bar_give_back_its_lengths() {
    // Crank-rocker (Grashof: 0.4 + 1.0 < 0.9 + 0.7), and a double-rocker.
    for (a, b, c, d) in [(0.4, 0.9, 0.7, 1.0), (0.8, 0.5, 0.6, 0.9)] {
        let pts = points_of(a, b, c, d, &[40.0, 55.0, 70.0]);
        assert!(pts.iter().all(|p| p.output_rad.is_finite()), "assembles");
        let found = freudenstein(&pts, d).expect("designs");
        let [k1, k2, k3] = found.k;
        close("K1", k1, d / a);
        close("K2", k2, d / c);
        close("K3", k3, (a * a - b * b + c * c + d * d) / (2.0 * a * c));
        let [fa, fb, fc, fd] = found.lengths;
        close("a", fa, a);
        close("b", fb, b);
        close("c", fc, c);
        close("d", fd, d);
        assert!(structural_error(&found, &pts).expect("closes") < 1e-9);
    }
}

#[test]
fn more_angles_of_a_four_bar_are_met_by_least_squares_exactly() {
    let (a, b, c, d) = (0.4, 0.9, 0.7, 1.0);
    let pts = points_of(
        a,
        b,
        c,
        d,
        &[10.0, 30.0, 50.0, 70.0, 90.0, 110.0, 130.0, 150.0],
    );
    let found = freudenstein(&pts, 2.0 * d).expect("designs");
    // Scaled by the ground given: the same shape twice as large.
    for (x, y) in found.lengths.iter().zip([a, b, c, d]) {
        close("length", *x, 2.0 * y);
    }
    assert!(structural_error(&found, &pts).expect("closes") < 1e-9);
}

/// y = log10(x) on [1, 2] with θ over 60° from 30°, φ over 90° from 240° (a
/// textbook layout), three Chebyshev points: the generator passes through them, in
/// its own closed form and as a scene solved by the general solver; between them it
/// errs by its structural error (0.07° here).
#[test]
fn a_log_generator_passes_through_its_chebyshev_points() {
    let to_angles = |x: f64| PrecisionPoint {
        input_rad: (30.0 + 60.0 * (x - 1.0)).to_radians(),
        output_rad: (240.0 + 90.0 * x.log10() / 2f64.log10()).to_radians(),
    };
    let xs = chebyshev_spacing(1.0, 2.0, 3);
    close(
        "first node",
        xs[0],
        1.5 - 0.5 * (std::f64::consts::PI / 6.0).cos(),
    );
    let pts: Vec<PrecisionPoint> = xs.iter().map(|&x| to_angles(x)).collect();
    let found = freudenstein(&pts, 1.0).expect("designs");
    assert!(structural_error(&found, &pts).expect("closes") < 1e-9);

    // The general solver, from the scene: C where the precision point puts it.
    let scene = found.scene(pts[0]);
    let mut k = Kinematics::new(Mechanism::from_scene(&scene).expect("valid")).expect("solves");
    let c = k.mechanism().point_index("C").expect("C");
    let flip = if found.lengths[0] < 0.0 {
        std::f64::consts::PI
    } else {
        0.0
    };
    for p in &pts {
        let at = k.solve(p.input_rad + flip).expect("assembles").points[c].position;
        let (_, want) = found.pins(p.input_rad, p.output_rad);
        close("C x", at.x, want[0]);
        close("C y", at.y, want[1]);
    }

    // Between the points the error is the structural error: not zero, and small.
    let fine: Vec<PrecisionPoint> = (0..=100)
        .map(|i| to_angles(1.0 + f64::from(i) / 100.0))
        .collect();
    let three = structural_error(&found, &fine).expect("closes over the range");
    assert!(
        three > 1e-6 && three < 2f64.to_radians(),
        "{}°",
        three.to_degrees()
    );

    // The error curve: zero at the three points, the same largest error as
    // `structural_error` over the range, and changing sign at each point.
    let theta = |x: f64| to_angles(x).input_rad;
    let phi_of_theta = |t: f64| {
        let x = 1.0 + (t.to_degrees() - 30.0) / 60.0;
        to_angles(x).output_rad
    };
    let curve = error_curve(&found, pts[0], [theta(1.0), theta(2.0)], phi_of_theta, 100);
    assert_eq!(curve.len(), 101);
    let largest = curve.iter().map(|e| e[1].abs()).fold(0.0, f64::max);
    close("largest error", largest, three);
    for x in &xs {
        let at = error_curve(&found, pts[0], [theta(*x), theta(*x)], phi_of_theta, 1);
        assert!(at[0][1].abs() < 1e-9, "{at:?}");
    }
    let sign_changes = curve
        .windows(2)
        .filter(|w| (w[0][1] < 0.0) != (w[1][1] < 0.0))
        .count();
    assert_eq!(sign_changes, 3, "one at each precision point");
}

#[test]
fn bad_points_are_refused_with_the_reason() {
    let p = |t: f64, f: f64| PrecisionPoint {
        input_rad: t,
        output_rad: f,
    };
    let two = [p(0.1, 0.2), p(0.3, 0.4)];
    assert!(matches!(
        freudenstein(&two, 1.0),
        Err(LinkageError::InvalidParameter { .. })
    ));
    let nan = [p(0.1, 0.2), p(f64::NAN, 0.4), p(0.5, 0.6)];
    assert!(freudenstein(&nan, 1.0).is_err());
    let same = [p(0.1, 0.2), p(0.1, 0.2), p(0.5, 0.6)];
    let err = freudenstein(&same, 1.0).expect_err("no two alike");
    assert!(err.to_string().contains("no two alike"), "{err}");
    assert!(freudenstein(&[p(0.1, 0.2), p(0.3, 0.5), p(0.5, 0.6)], -1.0).is_err());
}
