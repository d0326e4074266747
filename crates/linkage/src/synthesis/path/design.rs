//! A path generator found by the search, in world units: its linkage, how closely
//! it meets the targets, its coupler curve, its scene, and its two cognates (the
//! other four-bars that trace the same curve).

use serde::Serialize;

use super::cognates::{TurnsWith, cognates};
use super::geometry::{CouplerFourBar, PARAMS};
use super::problem::Problem;
use crate::analysis::GrashofClass;
use crate::scene::SceneFile;

/// A four-bar with a coupler point P, placed in the world, and how it meets the
/// targets' places on its curve.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PathLinkage {
    /// Crank pivot A, m.
    pub pivot_a: [f64; 2],
    /// Rocker pivot D, m.
    pub pivot_d: [f64; 2],
    /// Crank AB, m.
    pub crank_m: f64,
    /// Coupler BC, m.
    pub coupler_m: f64,
    /// Rocker DC, m.
    pub rocker_m: f64,
    /// The coupler point P in the coupler's frame (origin B, x-axis along B→C), m.
    pub coupler_point_m: [f64; 2],
    /// Whether C is left of the directed line B→D (the assembly branch).
    pub c_left_of_bd: bool,
    /// The crank angle (from the x-axis) at which P meets each target, deg.
    pub crank_deg: Vec<f64>,
    /// Grashof class (which link is shortest, and whether any turns fully).
    pub grashof: GrashofClass,
    /// Whether the crank turns through a whole revolution.
    pub crank_turns: bool,
    /// Least transmission angle over the crank's travel through the targets, deg
    /// (`None` where that travel leaves the branch).
    pub min_transmission_deg: Option<f64>,
}

impl PathLinkage {
    /// `m` meeting the targets at crank angles `angles` (rad); `travel` gives its
    /// travel through them (in their order, or the shortest arc).
    fn new(m: &CouplerFourBar, angles: &[f64], travel: Option<(f64, f64)>) -> Self {
        let ground = (m.d - m.a).norm();
        Self {
            pivot_a: m.a.into(),
            pivot_d: m.d.into(),
            crank_m: m.crank,
            coupler_m: m.coupler,
            rocker_m: m.rocker,
            coupler_point_m: m.point.into(),
            c_left_of_bd: m.c_left_of_bd,
            crank_deg: angles.iter().map(|a| a.to_degrees()).collect(),
            grashof: GrashofClass::of_lengths([ground, m.crank, m.coupler, m.rocker]),
            crank_turns: m.crank_turns(),
            min_transmission_deg: travel
                .map(|(start, len)| m.least_transmission_over(start, len).to_degrees()),
        }
    }

    /// The linkage in world units.
    pub fn linkage(&self) -> CouplerFourBar {
        CouplerFourBar {
            a: self.pivot_a.into(),
            d: self.pivot_d.into(),
            crank: self.crank_m,
            coupler: self.coupler_m,
            rocker: self.rocker_m,
            point: self.coupler_point_m.into(),
            c_left_of_bd: self.c_left_of_bd,
        }
    }

    /// The coupler curve at `samples` crank angles over a revolution, split into
    /// the pieces over which the loop closes.
    pub fn curve(&self, samples: usize) -> Vec<Vec<[f64; 2]>> {
        let m = self.linkage();
        let start = self.crank_deg.first().map_or(0.0, |d| d.to_radians());
        let mut pieces: Vec<Vec<[f64; 2]>> = vec![];
        let mut open = false;
        for k in 0..=samples {
            let theta = start + std::f64::consts::TAU * k as f64 / samples.max(1) as f64;
            match m.point_at(theta) {
                Some(p) if open => pieces.last_mut().into_iter().for_each(|c| c.push(p.into())),
                Some(p) => {
                    pieces.push(vec![p.into()]);
                    open = true;
                }
                None => open = false,
            }
        }
        pieces
    }

    /// The linkage as a scene, starting where P meets the first target, with P on
    /// the coupler; `max_error_m` goes into its description.
    pub fn scene(&self, max_error_m: f64) -> SceneFile {
        let mut scene = super::super::four_bar(&super::super::FourBar {
            pivot_a: self.pivot_a,
            pivot_d: self.pivot_d,
            lengths_m: [self.crank_m, self.coupler_m, self.rocker_m],
            start_deg: self.crank_deg.first().copied().unwrap_or(0.0),
            c_left_of_bd: self.c_left_of_bd,
            coupler_point: Some(self.coupler_point_m),
        });
        scene.name = "Path generator".into();
        scene.description = format!(
            "Four-bar whose coupler point P passes through {} targets, missing by at most {:.3e} m.",
            self.crank_deg.len(),
            max_error_m
        );
        scene
    }
}

/// One of a design's two cognates: another four-bar whose coupler point traces the
/// same curve through the targets.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PathCognate {
    /// The cognate.
    #[serde(flatten)]
    pub linkage: PathLinkage,
    /// Which link of the design its crank turns with.
    pub turns_with: TurnsWith,
}

/// A four-bar whose coupler point P passes through (or near) the targets, with its
/// cognates.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PathDesign {
    /// The four-bar.
    #[serde(flatten)]
    pub linkage: PathLinkage,
    /// Largest distance of P from a target, m.
    pub max_error_m: f64,
    /// Root-mean-square distance of P from the targets, m.
    pub rms_error_m: f64,
    /// The largest distance over the targets' size (the diagonal of their bounding box).
    pub relative_error: f64,
    /// The two other four-bars through the same curve (Roberts–Chebyshev), where
    /// they could be built (none where the coupler point lies on B or C).
    pub cognates: Vec<PathCognate>,
}

impl PathDesign {
    /// The design of the normalised four-bar `params` on branch `left`, meeting the
    /// targets at crank angles `angles` (rad).
    pub(super) fn new(problem: &Problem, params: &[f64], left: bool, angles: &[f64]) -> Self {
        let s = problem.scale;
        let norm = CouplerFourBar::from_params(&params[..PARAMS], left);
        let misses: Vec<f64> = problem
            .targets
            .iter()
            .zip(angles)
            .map(|(t, &theta)| {
                norm.point_at(theta)
                    .map_or(f64::INFINITY, |p| (p - t).norm() * s)
            })
            .collect();
        let max = misses.iter().cloned().fold(0.0, f64::max);
        let rms = (misses.iter().map(|m| m * m).sum::<f64>() / misses.len() as f64).sqrt();
        let world = to_world(problem, &norm);
        let cognates = if max.is_finite() {
            cognates(&world, angles).map_or_else(Vec::new, |cs| {
                cs.iter()
                    .map(|c| PathCognate {
                        linkage: PathLinkage::new(
                            &c.linkage,
                            &c.angles,
                            problem
                                .travel(&c.linkage, &c.angles)
                                .filter(|_| c.one_branch),
                        ),
                        turns_with: c.turns_with,
                    })
                    .collect()
            })
        } else {
            Vec::new()
        };
        Self {
            linkage: PathLinkage::new(&world, angles, problem.travel(&norm, angles)),
            max_error_m: max,
            rms_error_m: rms,
            relative_error: max / s,
            cognates,
        }
    }

    /// The design's four-bar in world units.
    pub fn linkage(&self) -> CouplerFourBar {
        self.linkage.linkage()
    }

    /// The design's coupler curve (see [`PathLinkage::curve`]).
    pub fn curve(&self, samples: usize) -> Vec<Vec<[f64; 2]>> {
        self.linkage.curve(samples)
    }

    /// The design as a scene, starting where P meets the first target.
    pub fn scene(&self) -> SceneFile {
        self.linkage.scene(self.max_error_m)
    }

    /// Cognate `k` (0 or 1) as a scene, starting where P meets the first target.
    pub fn cognate_scene(&self, k: usize) -> Option<SceneFile> {
        let c = self.cognates.get(k)?;
        let mut scene = c.linkage.scene(self.max_error_m);
        scene.name = format!("Path generator, cognate {}", k + 1);
        Some(scene)
    }
}

/// The normalised four-bar `m` in world units.
fn to_world(problem: &Problem, m: &CouplerFourBar) -> CouplerFourBar {
    let s = problem.scale;
    m.similar(s, |p| problem.centre + p * s)
}
