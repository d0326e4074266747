//! A crank-rocker from rocker length, swing and time ratio K (the construction of
//! the die-cutter paper): with the rocker's two limit positions C1, C2 about D, the
//! crank pivot A lies on the circle through C1 and C2 on which the chord C1C2
//! subtends θ = π(K − 1)/(K + 1); at the limits A, B, C are collinear, so
//! AB = (AC_far − AC_near)/2 and BC = (AC_far + AC_near)/2. The place of A on that
//! circle is the free choice: by default the one with the best minimum transmission
//! angle.

use serde::Serialize;

use crate::error::{LinkageError, Param, Result, Valid};
use crate::motion::{Vec2, cross};

/// A synthesized crank-rocker, SI units, D at the origin.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CrankRocker {
    /// Crank AB, m.
    pub crank_m: f64,
    /// Coupler BC, m.
    pub coupler_m: f64,
    /// Rocker CD, m.
    pub rocker_m: f64,
    /// Ground AD, m.
    pub ground_m: f64,
    /// Crank pivot A, m.
    pub pivot_a: [f64; 2],
    /// Rocker pivot D, m (the origin).
    pub pivot_d: [f64; 2],
    /// Rocker limit position at the start angle, m.
    pub c1: [f64; 2],
    /// Rocker limit position at start + swing, m.
    pub c2: [f64; 2],
    /// Crank angle between the two limit positions, rad.
    pub theta_rad: f64,
    /// Minimum transmission angle of the design (crank collinear with ground), rad.
    pub min_transmission_rad: f64,
    /// The free choice: A's angle on the synthesis circle about its centre, rad.
    pub arc_rad: f64,
    /// Which of the two mirror circles A lies on (+1: centre left of C1→C2).
    pub side: i8,
    /// True when C is left of the line B→D on the assembly branch.
    pub c_left_of_bd: bool,
}

/// Design at A on the circle of `side` at angle `t`; `None` where no crank-rocker results.
fn design_at(c1: Vec2, c2: Vec2, rocker: f64, theta: f64, side: i8, t: f64) -> Option<CrankRocker> {
    let mid = (c1 + c2) * 0.5;
    let half = (c2 - c1).norm() * 0.5;
    let n = Vec2::new(-(c2 - c1).y, (c2 - c1).x) / (2.0 * half);
    let radius = half / theta.sin();
    let centre = mid + n * (f64::from(side) * half / theta.tan());
    let a = centre + Vec2::new(t.cos(), t.sin()) * radius;
    let (r1, r2) = (c1 - a, c2 - a);
    // Only the major arc sees the chord under θ (the minor arc under π − θ).
    let seen = cross(&r1, &r2).abs().atan2(r1.dot(&r2));
    if (seen - theta).abs() > 1e-6 {
        return None;
    }
    let (near, far) = if r1.norm() < r2.norm() {
        (c1, c2)
    } else {
        (c2, c1)
    };
    let (dn, df) = ((near - a).norm(), (far - a).norm());
    let crank = 0.5 * (df - dn);
    let coupler = 0.5 * (df + dn);
    let ground = a.norm();
    let lengths = [crank, coupler, rocker, ground];
    let longest = lengths.iter().cloned().fold(0.0, f64::max);
    if crank.is_nan()
        || crank <= 1e-9 * rocker
        || lengths[1..].iter().any(|&l| l <= crank)
        || crank + longest >= lengths.iter().sum::<f64>() - crank - longest
    {
        return None;
    }
    // Same assembly branch at both limits, or the rocker cannot reach both.
    let b_ext = a + (far - a) * (crank / df);
    let b_fold = a - (near - a) * (crank / dn);
    let side_ext = cross(&(-b_ext), &(far - b_ext));
    let side_fold = cross(&(-b_fold), &(near - b_fold));
    if side_ext * side_fold <= 0.0 {
        return None;
    }
    let mu = |bd: f64| {
        let c = ((coupler * coupler + rocker * rocker - bd * bd) / (2.0 * coupler * rocker))
            .clamp(-1.0, 1.0);
        let m = c.acos();
        m.min(std::f64::consts::PI - m)
    };
    Some(CrankRocker {
        crank_m: crank,
        coupler_m: coupler,
        rocker_m: rocker,
        ground_m: ground,
        pivot_a: [a.x, a.y],
        pivot_d: [0.0, 0.0],
        c1: [c1.x, c1.y],
        c2: [c2.x, c2.y],
        theta_rad: theta,
        min_transmission_rad: mu(ground - crank).min(mu(ground + crank)),
        arc_rad: t.rem_euclid(std::f64::consts::TAU),
        side,
        c_left_of_bd: side_ext > 0.0,
    })
}

/// Crank-rocker with rocker `rocker_m` swinging `swing_rad` from `rocker_start_rad`
/// (angle of C1 about D) and time ratio `k`. `arc_rad`/`side` fix A on the circle;
/// `None` picks the best minimum transmission angle.
pub fn crank_rocker(
    rocker_m: f64,
    swing_rad: f64,
    k: f64,
    rocker_start_rad: f64,
    choice: Option<(f64, i8)>,
) -> Result<CrankRocker> {
    check_crank_rocker(rocker_m, swing_rad, k, rocker_start_rad)?;
    let theta = std::f64::consts::PI * (k - 1.0) / (k + 1.0);
    let at = |phi: f64| Vec2::new(phi.cos(), phi.sin()) * rocker_m;
    let (c1, c2) = (at(rocker_start_rad), at(rocker_start_rad + swing_rad));
    if let Some((t, side)) = choice {
        return design_at(c1, c2, rocker_m, theta, side, t).ok_or_else(|| {
            LinkageError::invalid(Param::Arc, t.to_degrees(), Valid::ArcGivesDesign)
        });
    }
    const SAMPLES: usize = 3600;
    let mut best: Option<CrankRocker> = None;
    for side in [1i8, -1] {
        for i in 0..SAMPLES {
            let t = std::f64::consts::TAU * i as f64 / SAMPLES as f64;
            if let Some(d) = design_at(c1, c2, rocker_m, theta, side, t)
                && best
                    .as_ref()
                    .is_none_or(|b| d.min_transmission_rad > b.min_transmission_rad)
            {
                best = Some(d);
            }
        }
    }
    let coarse = best.ok_or_else(|| {
        LinkageError::invalid(
            Param::Swing,
            swing_rad.to_degrees(),
            Valid::SwingAdmitsDesign,
        )
    })?;
    // Golden-section refinement within one grid step either side.
    let step = std::f64::consts::TAU / SAMPLES as f64;
    let score = |t: f64| {
        design_at(c1, c2, rocker_m, theta, coarse.side, t).map_or(-1.0, |d| d.min_transmission_rad)
    };
    let (mut lo, mut hi) = (coarse.arc_rad - step, coarse.arc_rad + step);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..80 {
        let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if score(x1) < score(x2) {
            lo = x1
        } else {
            hi = x2
        }
    }
    Ok(design_at(c1, c2, rocker_m, theta, coarse.side, 0.5 * (lo + hi)).unwrap_or(coarse))
}

/// The crank-rocker's requirements, each within its valid range.
fn check_crank_rocker(rocker_m: f64, swing_rad: f64, k: f64, rocker_start_rad: f64) -> Result<()> {
    if !(rocker_m.is_finite() && rocker_m > 0.0) {
        return Err(LinkageError::invalid(
            Param::RockerLength,
            rocker_m,
            Valid::PositiveOnly,
        ));
    }
    if !(swing_rad > 0.0 && swing_rad < std::f64::consts::PI) {
        return Err(LinkageError::invalid(
            Param::Swing,
            swing_rad.to_degrees(),
            Valid::SwingRange,
        ));
    }
    if !(k.is_finite() && k > 1.0 && k < 1e3) {
        return Err(LinkageError::invalid(Param::TimeRatio, k, Valid::TimeRatio));
    }
    if !rocker_start_rad.is_finite() {
        return Err(LinkageError::invalid(
            Param::RockerStartAngle,
            rocker_start_rad,
            Valid::FiniteShort,
        ));
    }
    Ok(())
}
