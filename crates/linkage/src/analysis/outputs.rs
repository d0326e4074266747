//! The outputs whose extremes are sought: rockers (links pinned to ground) and sliders.

use crate::ids::LinkId;
use crate::motion::Solution;
use crate::solve::Kinematics;

/// An output whose extremes are sought: a link pinned to ground, or a slider.
#[derive(Clone, Debug, PartialEq)]
pub enum Output {
    /// Angle of a link pinned to ground (other than the input).
    Rocker {
        /// Link index.
        link: LinkId,
        /// Link name.
        name: String,
    },
    /// Displacement of a prismatic joint.
    Slide {
        /// Index into `Mechanism::sliders`.
        slider: usize,
        /// Slider link name.
        name: String,
    },
}

impl Output {
    /// Display name.
    pub fn name(&self) -> &str {
        match self {
            Self::Rocker { name, .. } | Self::Slide { name, .. } => name,
        }
    }

    /// Value at a solution (rad or m; rocker angles in (-π, π]).
    pub fn value(&self, s: &Solution) -> f64 {
        match self {
            Self::Rocker { link, .. } => s.links[*link].angle_rad(),
            Self::Slide { slider, .. } => s.slides[*slider].displacement_m,
        }
    }

    /// Rate at a solution (rad/s or m/s).
    pub fn rate(&self, s: &Solution) -> f64 {
        match self {
            Self::Rocker { link, .. } => s.links[*link].omega_rad_s,
            Self::Slide { slider, .. } => s.slides[*slider].velocity_m_s,
        }
    }

    /// Second derivative at a solution (rad/s² or m/s²).
    pub fn acceleration(&self, s: &Solution) -> f64 {
        match self {
            Self::Rocker { link, .. } => s.links[*link].alpha_rad_s2,
            Self::Slide { slider, .. } => s.slides[*slider].acceleration_m_s2,
        }
    }

    /// Whether the value is an angle (rad) rather than a displacement (m).
    pub fn is_angle(&self) -> bool {
        matches!(self, Self::Rocker { .. })
    }

    /// The rate as a pure number: per radian of input at unit input speed, and for a
    /// slider per metre of `size_m` too, so that thresholds on it hold at any scale.
    pub(super) fn relative_rate(&self, s: &Solution, size_m: f64) -> f64 {
        match self {
            Self::Rocker { .. } => self.rate(s),
            Self::Slide { .. } => self.rate(s) / size_m,
        }
    }
}

/// The outputs of a mechanism: rockers (links pinned to ground), then sliders.
pub fn outputs(k: &Kinematics) -> Vec<Output> {
    let m = k.mechanism();
    let mut out: Vec<Output> = m
        .moving_links()
        .filter(|&l| l != m.driver.link)
        .filter(|&l| m.ground_pivot_of(l).is_some())
        .map(|l| Output::Rocker {
            link: l,
            name: m.links[l].name.clone(),
        })
        .collect();
    out.extend(m.sliders.iter().enumerate().map(|(i, s)| Output::Slide {
        slider: i,
        name: m.links[s.slider].name.clone(),
    }));
    out
}
