//! An input speed too high for the numbers: velocities grow with the speed and
//! accelerations with its square, so at about 1e150 rad/s (1e300 rpm gives 1e299)
//! an acceleration is no longer a finite number. Rather than "a non-finite value in
//! column 17", the cause is named with the largest speed that stays finite.

use crate::error::{LinkageError, Result};
use crate::motion::Solution;
use crate::solve::Kinematics;

/// The largest |rate| of any velocity (and of any acceleration) in `s`: point
/// components, link speeds, slider rates.
fn largest_rates(s: &Solution) -> (f64, f64) {
    let mut v: f64 = 0.0;
    let mut a: f64 = 0.0;
    for p in &s.points {
        v = v.max(p.velocity.amax());
        a = a.max(p.acceleration.amax());
    }
    for l in &s.links {
        v = v.max(l.omega_rad_s.abs());
        a = a.max(l.alpha_rad_s2.abs());
    }
    for sl in &s.slides {
        v = v.max(sl.velocity_m_s.abs());
        a = a.max(sl.acceleration_m_s2.abs());
    }
    (v, a)
}

/// Whether every velocity and acceleration of `s` is a finite number (a NaN too is
/// not: `f64::max` would pass over it).
fn finite(s: &Solution) -> bool {
    s.points.iter().all(|p| {
        p.velocity
            .iter()
            .chain(p.acceleration.iter())
            .all(|v| v.is_finite())
    }) && s
        .links
        .iter()
        .all(|l| l.omega_rad_s.is_finite() && l.alpha_rad_s2.is_finite())
        && s.slides
            .iter()
            .all(|sl| sl.velocity_m_s.is_finite() && sl.acceleration_m_s2.is_finite())
}

/// The largest input speed, rad/s, at which the velocities and accelerations of the
/// sweep's range stay finite, halved to spare (rates grow between the 360 positions
/// looked at): from the rates at unit speed, velocities scaling with the speed and
/// accelerations (at a constant input speed) with its square.
pub fn speed_limit(k: &mut Kinematics) -> Result<f64> {
    let ([a, b], _) = crate::ranges::sweep_range(k)?;
    let mut s = k.empty_solution();
    let (mut v1, mut a1): (f64, f64) = (0.0, 0.0);
    for i in 0..360 {
        let x = a + (b - a) * f64::from(i) / 359.0;
        if k.solve_into(x, 1.0, &mut s).is_ok() {
            let (v, acc) = largest_rates(&s);
            v1 = v1.max(v);
            a1 = a1.max(acc);
        }
    }
    // Each a quotient of square roots or of numbers below MAX: none overflows.
    let by_velocity = if v1 > 1.0 { f64::MAX / v1 } else { f64::MAX };
    let by_acceleration = if a1 > 0.0 {
        f64::MAX.sqrt() / a1.sqrt()
    } else {
        f64::MAX
    };
    Ok(0.5 * by_velocity.min(by_acceleration))
}

/// `Ok` where the velocities and accelerations of `s` (solved at the input speed
/// `speed_rad_s`) are finite, else [`LinkageError::SpeedOverflow`] with the largest
/// speed that keeps them so.
///
/// # Errors
/// As said, or the solver's error while finding the limit.
pub fn check(k: &mut Kinematics, s: &Solution) -> Result<()> {
    if finite(s) {
        return Ok(());
    }
    Err(LinkageError::SpeedOverflow {
        speed_rad_s: s.input_speed_rad_s,
        most_rad_s: speed_limit(k)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Mechanism;

    /// The limit is where the largest acceleration, which grows with the square of the
    /// speed, reaches the largest double: against the rates at unit speed, written
    /// out here; and a solve at twice the limit overflows while one at the limit does
    /// not.
    #[test]
    fn the_speed_limit_is_where_accelerations_reach_the_largest_double() {
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../assets/scenes/slider_crank.ron"
        ))
        .unwrap_or_default();
        let mut k = Kinematics::new(Mechanism::from_ron(&text).expect("ships")).expect("solves");
        let limit = speed_limit(&mut k).expect("assembles");
        let mut s = k.empty_solution();
        let mut a1: f64 = 0.0;
        for i in 0..360 {
            k.solve_into(f64::from(i).to_radians(), 1.0, &mut s)
                .expect("turns");
            a1 = a1.max(largest_rates(&s).1);
        }
        let want = 0.5 * (f64::MAX / a1).sqrt();
        assert!((limit - want).abs() <= 1e-3 * want, "{limit:e} vs {want:e}");
        k.solve_into(0.3, limit, &mut s).expect("solves");
        assert!(check(&mut k, &s).is_ok());
        k.solve_into(0.3, 4.0 * limit, &mut s).expect("solves");
        assert!(matches!(
            check(&mut k, &s),
            Err(LinkageError::SpeedOverflow { .. })
        ));
    }
}
