//! The external Geneva wheel against its geometry, written here: the pin at
//! a(cos α, sin α), the wheel's centre at (c, 0), c = a / sin(π/n); the wheel's
//! angle is the pin's bearing from the wheel's centre while the pin is within the
//! wheel's radius √(c² − a²). Its first and second derivatives against central
//! differences of that bearing; the dwell against the share of crank angles with the
//! pin outside the wheel; the peak acceleration against the textbook's figures
//! (5.409 ω² for 4 slots, 1.350 ω² for 6) and against a scan.

use linkage::cam::Geneva;

const PI: f64 = std::f64::consts::PI;

/// The pin's bearing from the wheel's centre, and whether it is in a slot.
fn bearing(g: &Geneva, alpha: f64) -> (f64, bool) {
    let a = g.crank_radius_m;
    let c = a / (PI / f64::from(g.slots)).sin();
    let (px, py) = (a * alpha.cos(), a * alpha.sin());
    let inside = (px - c).hypot(py) <= (c * c - a * a).sqrt() * (1.0 + 1e-12);
    (py.atan2(c - px), inside)
}

#[test]
fn the_wheel_follows_the_pins_bearing_and_its_derivatives() {
    for n in [3, 4, 5, 6, 8, 12] {
        let g = Geneva::new(n, 0.05).expect("valid");
        let half = g.half_index_rad();
        for i in 1..400 {
            let alpha = -half + 2.0 * half * i as f64 / 400.0;
            let m = g.at(alpha);
            let (beta, inside) = bearing(&g, alpha);
            assert!(inside && m.indexing, "{n} slots at {alpha}");
            assert!((m.wheel_rad - beta).abs() <= 1e-12, "{n} at {alpha}");
            let h = 1e-5;
            let (lo, hi) = (bearing(&g, alpha - h).0, bearing(&g, alpha + h).0);
            let ratio = (hi - lo) / (2.0 * h);
            let accel = (hi - 2.0 * beta + lo) / (h * h);
            let (_, peak) = g.peak_acceleration();
            assert!(
                (m.ratio - ratio).abs() <= 1e-8 * m.ratio.abs().max(1.0),
                "{n} at {alpha}: ratio"
            );
            assert!(
                (m.acceleration - accel).abs() <= 1e-4 * peak,
                "{n} at {alpha}: accel"
            );
        }
    }
}

#[test]
fn the_dwell_is_the_share_of_the_turn_with_the_pin_outside() {
    for n in [3, 4, 6, 8] {
        let g = Geneva::new(n, 0.05).expect("valid");
        let samples = 36_000;
        let outside = (0..samples)
            .filter(|&i| !bearing(&g, 2.0 * PI * (i as f64 + 0.5) / samples as f64).1)
            .count();
        let share = outside as f64 / samples as f64;
        assert!(
            (share - g.dwell_fraction()).abs() <= 2.0 / samples as f64,
            "{n}: {share}"
        );
        assert!((g.dwell_fraction() - (0.5 + 1.0 / f64::from(n))).abs() < 1e-15);
    }
}

#[test]
fn the_peak_acceleration_is_the_textbooks_and_the_largest_of_a_scan() {
    for (n, textbook) in [(4, 5.409), (6, 1.350)] {
        let g = Geneva::new(n, 0.05).expect("valid");
        let (_, peak) = g.peak_acceleration();
        assert!((peak - textbook).abs() <= 1e-3 * textbook, "{n}: {peak}");
    }
    for n in [3, 4, 5, 6, 8, 12] {
        let g = Geneva::new(n, 0.05).expect("valid");
        let (_, peak) = g.peak_acceleration();
        let half = g.half_index_rad();
        let scan = (0..=200_000)
            .map(|i| {
                g.at(-half + 2.0 * half * i as f64 / 200_000.0)
                    .acceleration
                    .abs()
            })
            .fold(0.0, f64::max);
        assert!(
            peak >= scan * (1.0 - 1e-12) && peak <= scan * (1.0 + 1e-9),
            "{n}: {peak} vs {scan}"
        );
    }
}

#[test]
fn a_wheel_of_two_slots_is_refused_by_name() {
    let e = Geneva::new(2, 0.05).expect_err("two slots");
    assert!(
        e.to_string()
            .contains("Geneva slots = 2 is invalid: at least 3"),
        "{e}"
    );
}
