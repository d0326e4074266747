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

use nalgebra::{SimdValue, Vector2};

use crate::ids::LinkId;
use crate::motion::{LinkMotion, PointMotion, SlideMotion, Solution, Vec2};
use crate::real::{LANES, Lanes};

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
    pub(crate) ground: LinkId,
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
    use crate::real::Real;

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
