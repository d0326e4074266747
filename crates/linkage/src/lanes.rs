//! Several positions in SIMD lanes.
//!
//! The closed-form solver and the motion types are generic over their number type
//! ([`Real`]): `f64` solves one position, [`Lanes`] solves [`LANES`] positions at
//! once with the same code. A full cycle is mostly independent positions of one
//! chain, so lanes turn the per-position arithmetic (two square roots and two
//! divisions per dyad, a few dozen products) into packed SIMD instructions. nalgebra
//! supports this layout (array of structures of SIMD lanes) through simba; `wide`
//! supplies the lanes, on SSE2 and AVX natively and on wasm32 as plain arrays.
//!
//! Branch tests become lane masks: a group that fails in any lane fails for the
//! whole batch, and [`crate::Kinematics::solve_lanes`] then solves that batch lane
//! by lane to name the failing position exactly.

use nalgebra::{SimdRealField, SimdValue, Vector2};

use crate::motion::{LinkMotion, PointMotion, SlideMotion, Solution, Vec2};

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
pub fn splat_vec<T: Real>(v: &Vec2) -> Vector2<T> {
    Vector2::new(T::splat(v.x), T::splat(v.y))
}

/// Lane `k` of a vector.
#[inline]
fn lane_vec(v: &Vector2<Lanes>, k: usize) -> Vec2 {
    Vec2::new(v.x.extract(k), v.y.extract(k))
}

/// Lane `k` of a point's motion.
pub fn point_lane(p: &PointMotion<Lanes>, k: usize) -> PointMotion {
    PointMotion {
        position: lane_vec(&p.position, k),
        velocity: lane_vec(&p.velocity, k),
        acceleration: lane_vec(&p.acceleration, k),
    }
}

/// Lane `k` of a link's motion.
pub fn link_lane(l: &LinkMotion<Lanes>, k: usize) -> LinkMotion {
    let (c, s) = (l.rotation.re.extract(k), l.rotation.im.extract(k));
    LinkMotion {
        rotation: nalgebra::UnitComplex::from_cos_sin_unchecked(c, s),
        omega_rad_s: l.omega_rad_s.extract(k),
        alpha_rad_s2: l.alpha_rad_s2.extract(k),
        origin: point_lane(&l.origin, k),
    }
}

/// [`LANES`] solved positions of one mechanism, lane `k` being input `inputs[k]`.
#[derive(Clone, Debug, Default)]
pub struct LaneSolution {
    /// Input angle of each lane, rad.
    pub inputs: [f64; LANES],
    /// Input angular speed, rad/s (the same in every lane).
    pub input_speed_rad_s: f64,
    /// Motion of every link (private: the solver keeps the ground's at rest and
    /// does not rewrite it).
    pub(crate) links: Vec<LinkMotion<Lanes>>,
    pub(crate) points: Vec<PointMotion<Lanes>>,
    pub(crate) slides: Vec<SlideMotion<Lanes>>,
    /// Index of the ground link these buffers were made for.
    pub(crate) ground: usize,
    /// Conditioning of each lane (see [`Solution::conditioning`]).
    pub conditioning: [f64; LANES],
}

impl LaneSolution {
    /// Motion of every link, indexed like `Mechanism::links` (ground included).
    pub fn links(&self) -> &[LinkMotion<Lanes>] {
        &self.links
    }

    /// Motion of every named point, indexed like `Mechanism::points`.
    pub fn points(&self) -> &[PointMotion<Lanes>] {
        &self.points
    }

    /// Relative motion of every prismatic joint, indexed like `Mechanism::sliders`.
    pub fn slides(&self) -> &[SlideMotion<Lanes>] {
        &self.slides
    }

    /// Lane `k` as a one-position [`Solution`], written into `out` (no allocation
    /// when `out` already has the right sizes).
    pub fn lane_into(&self, k: usize, out: &mut Solution) {
        out.input_rad = self.inputs[k];
        out.input_speed_rad_s = self.input_speed_rad_s;
        out.conditioning = self.conditioning[k];
        out.links.clear();
        out.links.extend(self.links.iter().map(|l| link_lane(l, k)));
        out.points.clear();
        out.points
            .extend(self.points.iter().map(|p| point_lane(p, k)));
        out.slides.clear();
        out.slides.extend(self.slides.iter().map(|s| SlideMotion {
            displacement_m: s.displacement_m.extract(k),
            velocity_m_s: s.velocity_m_s.extract(k),
            acceleration_m_s2: s.acceleration_m_s2.extract(k),
        }));
    }

    /// Writes the one-position solution `s` into lane `k`.
    pub fn set_lane(&mut self, k: usize, s: &Solution) {
        fn put(v: &mut Vector2<Lanes>, k: usize, x: &Vec2) {
            v.x.replace(k, x.x);
            v.y.replace(k, x.y);
        }
        fn put_point(p: &mut PointMotion<Lanes>, k: usize, x: &PointMotion) {
            put(&mut p.position, k, &x.position);
            put(&mut p.velocity, k, &x.velocity);
            put(&mut p.acceleration, k, &x.acceleration);
        }
        self.inputs[k] = s.input_rad;
        self.input_speed_rad_s = s.input_speed_rad_s;
        self.conditioning[k] = s.conditioning;
        for (l, x) in self.links.iter_mut().zip(&s.links) {
            let mut rotation = *l.rotation.as_ref();
            rotation.re.replace(k, x.rotation.re);
            rotation.im.replace(k, x.rotation.im);
            l.rotation = nalgebra::UnitComplex::new_unchecked(rotation);
            l.omega_rad_s.replace(k, x.omega_rad_s);
            l.alpha_rad_s2.replace(k, x.alpha_rad_s2);
            put_point(&mut l.origin, k, &x.origin);
        }
        for (p, x) in self.points.iter_mut().zip(&s.points) {
            put_point(p, k, x);
        }
        for (sl, x) in self.slides.iter_mut().zip(&s.slides) {
            sl.displacement_m.replace(k, x.displacement_m);
            sl.velocity_m_s.replace(k, x.velocity_m_s);
            sl.acceleration_m_s2.replace(k, x.acceleration_m_s2);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Within 2 ulp of the standard library's sine and cosine (absolute 2.3e-16 for
    /// these magnitudes), over many turns both ways, at quadrant boundaries and beyond
    /// the reduced range; NaN stays NaN.
    #[test]
    fn lanes_sin_cos_matches_std() {
        let mut inputs: Vec<f64> = (0..40_000)
            .map(|i| (i as f64 - 20_000.0) * 0.000_917_3 * std::f64::consts::PI)
            .collect();
        for k in -40..=40 {
            let edge = k as f64 * std::f64::consts::FRAC_PI_4;
            inputs.extend([edge, edge.next_up(), edge.next_down()]);
        }
        inputs.extend([1e-300, -0.0, 123_456.789, 2e6, -3.5e9, 1e300]);
        while !inputs.len().is_multiple_of(LANES) {
            inputs.push(0.5);
        }
        let mut worst: f64 = 0.0;
        for chunk in inputs.chunks_exact(LANES) {
            let x: [f64; LANES] = chunk.try_into().expect("LANES values");
            let (sin, cos) = Lanes::from(x).sin_cos_of();
            for (k, v) in x.iter().enumerate() {
                let (s, c) = v.sin_cos();
                worst = worst
                    .max((sin.extract(k) - s).abs())
                    .max((cos.extract(k) - c).abs());
            }
        }
        assert!(worst <= 2.3e-16, "lanes sin_cos off by {worst:e}");
        let (sin, cos) = Lanes::from([f64::NAN, 0.0, 1.0, 2.0]).sin_cos_of();
        assert!(sin.extract(0).is_nan() && cos.extract(0).is_nan());
        assert_eq!(cos.extract(1), 1.0);
    }
}
