//! A polygon figure fitted to a pane: the scale that makes it fill the pane, arrow
//! heads sized in pixels, a round scale bar, and every label placed
//! ([`crate::placement`]). Pane coordinates are pixels, y down; the figure's are
//! m/s or m/s², y up.

use crate::figure::ArrowStyle;
pub use crate::figure::Figure;
use crate::geometry::{Pt, Rect, distance};
use crate::label::Label;
use crate::placement::{Anchor, Obstacles, place_all, place_vertex_label};

/// Sizes of the drawing, in pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sizes {
    /// Label font size.
    pub font_px: f64,
    /// Arrow head length (shorter on short arrows: at most 40 % of the arrow).
    pub head_px: f64,
}

impl Default for Sizes {
    fn default() -> Self {
        Self {
            font_px: 13.0,
            head_px: 9.0,
        }
    }
}

/// An arrow in pane pixels.
#[derive(Clone, Debug, PartialEq)]
pub struct LaidArrow {
    /// Tail.
    pub from: Pt,
    /// Head.
    pub to: Pt,
    /// The head's triangle (tip, left, right); none on an arrow under a pixel long.
    pub head: Option<[Pt; 3]>,
    /// Style.
    pub style: ArrowStyle,
    /// Index into the figure's arrows.
    pub index: usize,
}

/// What a label names.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LabelOwner {
    /// Points of the polygon that fall on one spot (indices into the figure's vertices).
    Vertices(Vec<usize>),
    /// An arrow (index into the figure's arrows).
    Arrow(usize),
}

/// A placed label.
#[derive(Clone, Debug, PartialEq)]
pub struct LaidLabel {
    /// The text.
    pub label: Label,
    /// Its box in the pane.
    pub rect: Rect,
    /// A line from the box to what it names, when the box had to move away from it.
    pub leader: Option<[Pt; 2]>,
    /// What it names.
    pub owner: LabelOwner,
    /// Whether no free place was found (it overlaps something).
    pub collides: bool,
}

/// The scale bar: a round length of the figure's unit.
#[derive(Clone, Debug, PartialEq)]
pub struct ScaleBar {
    /// Its length in the figure's unit: 1, 2 or 5 × 10^k.
    pub value: f64,
    /// Left end, pixels.
    pub from: Pt,
    /// Right end, pixels.
    pub to: Pt,
}

/// A polygon laid out in a pane.
#[derive(Clone, Debug, PartialEq)]
pub struct LaidPolygon {
    /// The pane.
    pub pane: Rect,
    /// Pixels per unit (m/s or m/s²); 0 for a polygon that is a point.
    pub px_per_unit: f64,
    /// Where the figure's origin (the pole) is, pixels.
    pub origin: Pt,
    /// Arrows.
    pub arrows: Vec<LaidArrow>,
    /// The vertices in pixels, indexed like the figure's.
    pub vertices: Vec<Pt>,
    /// Labels.
    pub labels: Vec<LaidLabel>,
    /// The scale bar; none for a polygon that is a point.
    pub scale_bar: Option<ScaleBar>,
}

impl LaidPolygon {
    /// A point of the figure (m/s or m/s², y up) in pane pixels (y down).
    pub fn to_px(&self, p: Pt) -> Pt {
        [
            self.origin[0] + p[0] * self.px_per_unit,
            self.origin[1] - p[1] * self.px_per_unit,
        ]
    }

    /// The box of the drawn figure (arrows and vertices), pixels.
    pub fn figure_box(&self) -> Option<Rect> {
        Rect::around(
            self.arrows
                .iter()
                .flat_map(|a| [a.from, a.to])
                .chain(self.vertices.iter().copied()),
        )
    }
}

/// A figure's units (y up) fitted into a pane's pixels (y down): the largest scale
/// that leaves room round the figure for labels and below it for the scale bar, the
/// figure centred. The polygons and the pose share it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fit {
    /// Pixels per unit; 0 where the figure has no extent.
    pub scale: f64,
    centre_px: Pt,
    centre_units: Pt,
}

impl Fit {
    /// `units` fitted into `pane`.
    pub fn new(units: Rect, pane: Rect, sizes: Sizes) -> Self {
        let side = 2.2 * sizes.font_px;
        let inner = Rect {
            min: [pane.min[0] + side, pane.min[1] + side],
            max: [pane.max[0] - side, pane.max[1] - side - 1.6 * sizes.font_px],
        };
        let fits = |w: f64, span: f64| if w > 0.0 { span / w } else { f64::INFINITY };
        let s = fits(units.width(), inner.width()).min(fits(units.height(), inner.height()));
        Self {
            scale: if s.is_finite() && s > 0.0 { s } else { 0.0 },
            centre_px: inner.centre(),
            centre_units: units.centre(),
        }
    }

    /// A point of the figure in pixels.
    pub fn px(&self, p: Pt) -> Pt {
        let (c, u, s) = (self.centre_px, self.centre_units, self.scale);
        [c[0] + (p[0] - u[0]) * s, c[1] - (p[1] - u[1]) * s]
    }

    /// The scale bar at the pane's bottom left: a round length for a figure `extent`
    /// units across.
    pub fn scale_bar(&self, extent: f64, pane: Rect, sizes: Sizes) -> ScaleBar {
        let value = round_scale(extent);
        let y = pane.max[1] - 0.8 * sizes.font_px;
        let x = pane.min[0] + 0.8 * sizes.font_px;
        ScaleBar {
            value,
            from: [x, y],
            to: [x + value * self.scale, y],
        }
    }
}

/// A round length near a quarter of `extent`: 1, 2 or 5 × 10^k, at most a quarter.
pub fn round_scale(extent: f64) -> f64 {
    if !(extent.is_finite() && extent > 0.0) {
        return 0.0;
    }
    let target = extent / 4.0;
    let decade = 10f64.powf(target.log10().floor());
    [5.0, 2.0, 1.0]
        .into_iter()
        .map(|m| m * decade)
        .find(|&v| v <= target)
        .unwrap_or(decade)
}

/// Lays `fig` out in `pane`, labels measured by `measure` (width, height in pixels).
pub fn layout_polygon(
    fig: &dyn Figure,
    pane: Rect,
    sizes: Sizes,
    measure: &dyn Fn(&Label) -> [f64; 2],
) -> LaidPolygon {
    layout_polygon_fitting(fig, None, pane, sizes, measure)
}

/// As [`layout_polygon`], with the scale set by `fit` (figure units) instead of the
/// figure's own extent: the steps of a construction share the last step's scale.
pub fn layout_polygon_fitting(
    fig: &dyn Figure,
    fit: Option<Rect>,
    pane: Rect,
    sizes: Sizes,
    measure: &dyn Fn(&Label) -> [f64; 2],
) -> LaidPolygon {
    let units = fit.unwrap_or_else(|| fig.extent());
    let fitted = Fit::new(units, pane, sizes);
    let (s, px) = (fitted.scale, |p: Pt| fitted.px(p));
    let arrows: Vec<LaidArrow> = fig
        .arrow_ends()
        .into_iter()
        .enumerate()
        .map(|(index, (from, to, style))| {
            let (from, to) = (px(from), px(to));
            LaidArrow {
                from,
                to,
                head: head(from, to, sizes.head_px),
                style,
                index,
            }
        })
        .collect();
    let vertices: Vec<Pt> = fig.vertices().iter().map(|v| px(v.at)).collect();
    let shafts: Vec<[Pt; 2]> = arrows.iter().map(|a| [a.from, a.to]).collect();
    let heads: Vec<[Pt; 3]> = arrows.iter().filter_map(|a| a.head).collect();
    let mut obstacles = Obstacles::new(pane.expand(-2.0), &shafts, &heads, &vertices);
    let mut labels = vertex_labels(fig, &vertices, &mut obstacles, measure);
    labels.extend(arrow_labels(fig, &arrows, &obstacles, measure));
    let scale_bar =
        (s > 0.0).then(|| fitted.scale_bar(units.width().max(units.height()), pane, sizes));
    LaidPolygon {
        pane,
        px_per_unit: s,
        origin: px([0.0, 0.0]),
        arrows,
        vertices,
        labels,
        scale_bar,
    }
}

/// The head's triangle: `head_px` long, or 40 % of a short arrow.
fn head(from: Pt, to: Pt, head_px: f64) -> Option<[Pt; 3]> {
    let len = distance(from, to);
    if len < 1.0 {
        return None;
    }
    let h = head_px.min(0.4 * len);
    let u = [(to[0] - from[0]) / len, (to[1] - from[1]) / len];
    let n = [-u[1], u[0]];
    let base = [to[0] - h * u[0], to[1] - h * u[1]];
    let w = 0.4 * h;
    Some([
        to,
        [base[0] + w * n[0], base[1] + w * n[1]],
        [base[0] - w * n[0], base[1] - w * n[1]],
    ])
}

/// Vertices within this many pixels share one label ("p, a, d").
const SAME_SPOT_PX: f64 = 4.0;

/// One label per spot: vertices closer than [`SAME_SPOT_PX`] share it, pole first.
fn vertex_labels(
    fig: &dyn Figure,
    at: &[Pt],
    obstacles: &mut Obstacles,
    measure: &dyn Fn(&Label) -> [f64; 2],
) -> Vec<LaidLabel> {
    let mut spot_of: Vec<Option<usize>> = vec![None; at.len()];
    let mut spots: Vec<Vec<usize>> = Vec::new();
    for i in 0..at.len() {
        if spot_of[i].is_some() {
            continue;
        }
        let members: Vec<usize> = (i..at.len())
            .filter(|&j| spot_of[j].is_none() && distance(at[i], at[j]) < SAME_SPOT_PX)
            .collect();
        for &j in &members {
            spot_of[j] = Some(spots.len());
        }
        spots.push(members);
    }
    spots
        .into_iter()
        .map(|members| {
            let names: Vec<&str> = members
                .iter()
                .map(|&j| fig.vertices()[j].name.as_str())
                .collect();
            let label = Label::plain(names.join(", "));
            let anchor = at[members[0]];
            // Away from the pole: where the absolute vector would go on.
            let pole = at[0];
            let away = [anchor[0] - pole[0], anchor[1] - pole[1]];
            let placed = place_vertex_label(anchor, away, measure(&label), obstacles);
            LaidLabel {
                label,
                rect: placed.rect,
                leader: placed.leader,
                owner: LabelOwner::Vertices(members),
                collides: placed.collides,
            }
        })
        .collect()
}

/// The arrows that carry labels, shortest (least room) first. Lengths are compared
/// to a millionth of a pixel, then by index: arrows equal in length (the die
/// cutter's a_C^t and a_EC^t, since CD = CE) would otherwise fall in the order of
/// their last bits, which the browser's and the native sine and cosine round
/// apart, and the app's sheet would differ from `linkage diagram`'s.
fn label_order(arrows: &[LaidArrow]) -> Vec<&LaidArrow> {
    let mut order: Vec<&LaidArrow> = arrows
        .iter()
        .filter(|a| a.style != ArrowStyle::Absolute)
        .collect();
    order.sort_by_key(|a| ((distance(a.from, a.to) * 1e6).round() as i64, a.index));
    order
}

/// A label per relative or component arrow, placed among `obstacles` the shortest
/// (least room) first, then in the orders [`place_all`] tries where a label is
/// left crossed by a line.
fn arrow_labels(
    fig: &dyn Figure,
    arrows: &[LaidArrow],
    obstacles: &Obstacles,
    measure: &dyn Fn(&Label) -> [f64; 2],
) -> Vec<LaidLabel> {
    let labelled: Vec<(&LaidArrow, Label)> = label_order(arrows)
        .into_iter()
        .filter_map(|a| Some((a, fig.arrow_label(a.index)?)))
        .collect();
    let anchors: Vec<(Anchor, [f64; 2])> = labelled
        .iter()
        .map(|(a, label)| {
            let anchor = Anchor::Arrow {
                from: a.from,
                to: a.to,
            };
            (anchor, measure(label))
        })
        .collect();
    let placed = place_all(obstacles, &anchors);
    labelled
        .into_iter()
        .zip(placed)
        .map(|((a, label), placed)| LaidLabel {
            label,
            rect: placed.rect,
            leader: placed.leader,
            owner: LabelOwner::Arrow(a.index),
            collides: placed.collides,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scale_is_round_and_at_most_a_quarter() {
        assert_eq!(round_scale(10.0), 2.0);
        assert_eq!(round_scale(0.37), 0.05);
        assert_eq!(round_scale(0.0), 0.0);
        assert_eq!(round_scale(f64::NAN), 0.0);
    }

    #[test]
    fn arrows_of_one_length_are_labelled_in_index_order_whatever_their_last_bits() {
        let arrow = |index: usize, x: f64| LaidArrow {
            from: [0.0, 0.0],
            to: [x, 0.0],
            head: None,
            style: ArrowStyle::Relative,
            index,
        };
        let ten = 10.0f64;
        let above = f64::from_bits(ten.to_bits() + 1);
        for arrows in [
            [arrow(0, 20.0), arrow(1, above), arrow(2, ten)],
            [arrow(0, 20.0), arrow(1, ten), arrow(2, above)],
        ] {
            let order: Vec<usize> = label_order(&arrows).iter().map(|a| a.index).collect();
            assert_eq!(order, [1, 2, 0]);
        }
    }

    #[test]
    fn a_head_is_at_most_forty_percent_of_a_short_arrow() {
        let h = head([0.0, 0.0], [10.0, 0.0], 9.0).expect("head");
        assert!((h[1][0] - 6.0).abs() < 1e-12);
        assert!(head([0.0, 0.0], [0.5, 0.0], 9.0).is_none());
    }
}
