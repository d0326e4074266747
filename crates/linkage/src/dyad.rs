//! A dyad's type and its label as data, for the decomposition, the errors and the
//! reports. A leaf module: the errors name dyads without depending on the solver.

/// A dyad's type in Assur notation: its joints in order from one known link through
/// the inner joint to the other, R revolute and P prismatic.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DyadKind {
    /// Three pins: the four-bar's coupler and rocker.
    Rrr,
    /// Pin, pin, slider: the slider-crank's rod and slider.
    Rrp,
    /// A slider between two pins: the inverted slider-crank.
    Rpr,
    /// A pin between two sliders.
    Prp,
    /// Not a dyad: a cam's follower, one link placed by the cam.
    CamFollower,
}

impl std::fmt::Display for DyadKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            DyadKind::Rrr => "RRR",
            DyadKind::Rrp => "RRP",
            DyadKind::Rpr => "RPR",
            DyadKind::Prp => "PRP",
            DyadKind::CamFollower => "cam",
        })
    }
}

/// One dyad of a mechanism, named as its user knows it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DyadLabel {
    /// Its type.
    pub kind: DyadKind,
    /// Its two links' names.
    pub links: [String; 2],
    /// The name of its inner joint's point.
    pub inner_point: String,
}

/// "RRR dyad (coupler, rocker) at C".
impl std::fmt::Display for DyadLabel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let [a, b] = &self.links;
        if self.kind == DyadKind::CamFollower {
            return write!(f, "cam follower {a} at {}", self.inner_point);
        }
        write!(f, "{} dyad ({a}, {b}) at {}", self.kind, self.inner_point)
    }
}
