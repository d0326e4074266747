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

/// A group of the chain as a report names it: a dyad by its links and inner point,
/// or, in a chain solved by Newton alone, its number. Written in a report as
/// "RRR dyad (coupler, rocker) at C" or "group 2"; each edge words it its own way.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum GroupLabel {
    /// A dyad of the closed-form decomposition.
    Dyad(DyadLabel),
    /// A group with no dyad to name, by its number.
    Numbered(usize),
}

impl std::fmt::Display for GroupLabel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Dyad(d) => d.fmt(f),
            Self::Numbered(g) => write!(f, "group {g}"),
        }
    }
}

// Reports written as JSON have carried the label since they were first written.
impl serde::Serialize for GroupLabel {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

/// How a dyad that does not close falls short, in the mechanism's own terms: the
/// points its user named and lengths in metres. What a refusal tells the user
/// instead of an assembly margin.
#[derive(Clone, Debug, PartialEq)]
pub enum Shortfall {
    /// Two links pinned at their far ends `ends` meet at `inner`: `lengths` are
    /// their pin-to-pin lengths (from each end to `inner`), `apart` the distance
    /// between the ends, more than the lengths together or less than their
    /// difference.
    Apart {
        /// The far pins, on the first and the second link.
        ends: [String; 2],
        /// The pin the two links share.
        inner: String,
        /// Each link's length from its end to `inner`, m.
        lengths: [f64; 2],
        /// How far apart the ends are, m.
        apart: f64,
    },
    /// A link pinned at `end` carries at `inner` a slider whose guide's line lies
    /// `offset` from `end`, farther than the link's `length`.
    Guide {
        /// The link's known pin.
        end: String,
        /// The slider's pin.
        inner: String,
        /// The link's length from `end` to `inner`, m.
        length: f64,
        /// The distance from `end` to the guide's line, m.
        offset: f64,
    },
    /// A guide pinned at `guide_pin` must pass through the slider's pin
    /// `slider_pin` at `offset` from its line, but the two pins are only `apart`.
    Slot {
        /// The guide's pin.
        guide_pin: String,
        /// The slider's pin.
        slider_pin: String,
        /// The guide line's distance from its pin, m.
        offset: f64,
        /// How far apart the two pins are, m.
        apart: f64,
    },
}

/// A link named by two of its points as a textbook does: `BC` for one-letter
/// names, `O2-A` otherwise.
pub fn pair_name(a: &str, b: &str) -> String {
    if a.chars().count() == 1 && b.chars().count() == 1 {
        format!("{a}{b}")
    } else {
        format!("{a}-{b}")
    }
}

impl Shortfall {
    /// The shortfall in words, lengths given by `length` (a value in metres
    /// written with its unit: the solver writes metres, the app the scene's unit).
    pub fn words(&self, length: &dyn Fn(f64) -> String) -> String {
        match self {
            Self::Apart {
                ends: [a, c],
                inner,
                lengths: [l1, l2],
                apart,
            } => {
                let (ab, bc) = (pair_name(a, inner), pair_name(c, inner));
                let why = if *apart > l1 + l2 {
                    format!("more than the {} of the two together", length(l1 + l2))
                } else {
                    format!(
                        "less than the {} between their lengths",
                        length((l1 - l2).abs())
                    )
                };
                format!(
                    "{ab} ({}) and {bc} ({}) cannot meet at {inner}: {a} and {c} are {} apart, {why}",
                    length(*l1),
                    length(*l2),
                    length(*apart)
                )
            }
            Self::Guide {
                end,
                inner,
                length: l,
                offset,
            } => format!(
                "{} ({}) cannot reach the guide of the slider at {inner}: {end} is {} from its line",
                pair_name(end, inner),
                length(*l),
                length(*offset)
            ),
            Self::Slot {
                guide_pin,
                slider_pin,
                offset,
                apart,
            } => format!(
                "the guide pinned at {guide_pin} cannot pass through {slider_pin}: the pins are {} apart, less than the guide's offset {}",
                length(*apart),
                length(*offset)
            ),
        }
    }
}

impl std::fmt::Display for Shortfall {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.words(&|m| format!("{} m", round_4(m))))
    }
}

/// Four significant digits, without trailing zeros.
fn round_4(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let decimals = (3 - v.abs().log10().floor() as i32).max(0) as usize;
    let t = format!("{v:.decimals$}");
    if t.contains('.') {
        t.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        t
    }
}
