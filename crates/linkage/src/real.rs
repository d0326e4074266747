//! The solver's number type: `f64` for one position, [`Lanes`] of `f64` for several
//! at once (see [`crate::LaneSolution`]), with the operations the solver needs of both. A
//! leaf module: the motion types and the solvers are generic over [`Real`].

use nalgebra::{SimdRealField, SimdValue, Vector2};

/// A number the solver can compute with: `f64`, or [`Lanes`] of `f64`.
pub trait Real: SimdRealField<Element = f64> + Copy {
    /// Sine and cosine (of an input angle).
    fn sin_cos_of(self) -> (Self, Self);
}

impl Real for f64 {
    #[inline(always)]
    fn sin_cos_of(self) -> (f64, f64) {
        self.sin_cos()
    }
}

impl Real for Lanes {
    #[inline(always)]
    fn sin_cos_of(self) -> (Lanes, Lanes) {
        lanes_sin_cos(self)
    }
}

/// Largest |x| that [`lanes_sin_cos`] reduces itself (the quadrant count times the
/// first part of π/2 stays exact below 2^20 quadrants); larger inputs go lane by
/// lane through the standard library.
const REDUCED_UP_TO: f64 = 1.0e6;

/// Sine and cosine of four lanes with float operations only: Cody–Waite reduction
/// by π/2 in three parts, then fdlibm's minimax kernels on [-π/4, π/4] (under an
/// ulp; the tests hold it within 2 ulp of the standard library). wide's own
/// `sin_cos` converts the quadrant to 64-bit integers, which SSE2 lacks, and
/// that emulation was a fifth of a four-bar position's time.
#[inline(always)]
fn lanes_sin_cos(x: Lanes) -> (Lanes, Lanes) {
    use nalgebra::{SimdBool, SimdComplexField, SimdPartialOrd};
    if !x.simd_abs().simd_le(splat(REDUCED_UP_TO)).all() {
        let mut sin = x;
        let mut cos = x;
        for k in 0..LANES {
            let (s, c) = x.extract(k).sin_cos();
            sin.replace(k, s);
            cos.replace(k, c);
        }
        return (sin, cos);
    }
    // Round to nearest by the 1.5·2^52 trick (no integer conversion needed).
    let magic = splat::<Lanes>(6_755_399_441_055_744.0);
    let n = (x * splat(std::f64::consts::FRAC_2_PI) + magic) - magic;
    let r = ((x - n * splat(1.570_796_326_734_125_6)) - n * splat(6.077_100_506_303_966e-11))
        - n * splat(2.022_266_248_711_166_5e-21);
    let z = r * r;
    let sin_r = r + r
        * z
        * (splat::<Lanes>(-1.666_666_666_666_663_2e-1)
            + z * (splat::<Lanes>(8.333_333_333_322_49e-3)
                + z * (splat::<Lanes>(-1.984_126_982_985_795e-4)
                    + z * (splat::<Lanes>(2.755_731_370_707_006_8e-6)
                        + z * (splat::<Lanes>(-2.505_076_025_340_686_3e-8)
                            + z * splat::<Lanes>(1.589_690_995_211_55e-10))))));
    let poly = z
        * (splat::<Lanes>(4.166_666_666_666_66e-2)
            + z * (splat::<Lanes>(-1.388_888_888_887_411e-3)
                + z * (splat::<Lanes>(2.480_158_728_947_673e-5)
                    + z * (splat::<Lanes>(-2.755_731_435_139_066_3e-7)
                        + z * (splat::<Lanes>(2.087_572_321_298_175e-9)
                            + z * splat::<Lanes>(-1.135_964_755_778_819_5e-11))))));
    let (one, two) = (splat::<Lanes>(1.0), splat::<Lanes>(2.0));
    let half_z = z * splat(0.5);
    let w = one - half_z;
    let cos_r = w + (((one - w) - half_z) + z * poly);
    // Quadrant n mod 4 as -2..=2 (n minus the nearest multiple of 4).
    let q = n - ((n * splat(0.25) + magic) - magic) * splat(4.0);
    let half_turn = q.simd_abs().simd_eq(two);
    let odd = q.simd_abs().simd_eq(one);
    let sin_negative = half_turn | q.simd_eq(-one);
    let cos_negative = half_turn | q.simd_eq(one);
    let sin = sin_r.select(!odd, cos_r);
    let cos = cos_r.select(!odd, sin_r);
    (
        (-sin).select(sin_negative, sin),
        (-cos).select(cos_negative, cos),
    )
}

/// Four `f64` lanes (SSE2/AVX on x86-64, plain arrays where the target has no SIMD).
pub type Lanes = simba::simd::WideF64x4;

/// Number of lanes in [`Lanes`].
pub const LANES: usize = 4;

/// `x` in every lane.
#[inline(always)]
pub fn splat<T: Real>(x: f64) -> T {
    T::splat(x)
}

/// `v` in every lane.
#[inline(always)]
pub fn splat_vec<T: Real>(v: &Vector2<f64>) -> Vector2<T> {
    Vector2::new(T::splat(v.x), T::splat(v.y))
}
