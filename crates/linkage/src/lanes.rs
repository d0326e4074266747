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
pub trait Real: SimdRealField<Element = f64> + Copy {}

impl<T: SimdRealField<Element = f64> + Copy> Real for T {}

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
