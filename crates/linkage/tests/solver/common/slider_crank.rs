//! The in-line slider-crank in closed form, the reference the machine tests check
//! against: crank `r`, rod `l`, the slider on the line through the crank pivot.

/// The slider's position s(φ) = r cos φ + √(l² − r² sin² φ) from the pivot, and its
/// first two derivatives by the crank angle, s'(φ) and s''(φ).
pub fn slide(r: f64, l: f64, phi: f64) -> (f64, f64, f64) {
    let (sn, cs) = phi.sin_cos();
    let d = (l * l - r * r * sn * sn).sqrt();
    let s = r * cs + d;
    let s1 = -r * sn - r * r * sn * cs / d;
    let s2 = -r * cs - r * r * (2.0 * phi).cos() / d - r.powi(4) * sn * sn * cs * cs / d.powi(3);
    (s, s1, s2)
}
