//! The pose fitted to a pane: links, pivots, sliders and joint names in pixels, the
//! instant centres that fall near the mechanism, and a round scale bar in metres.

use linkage::instant_centres::Centre;

use crate::geometry::{Pt, Rect};
use crate::label::Label;
use crate::layout::{Fit, ScaleBar, Sizes};
use crate::placement::{Obstacles, Placed, place_arrow_label, place_vertex_label};
use crate::pose_figure::PoseFigure;

/// A placed label of the pose.
#[derive(Clone, Debug, PartialEq)]
pub struct PoseLabel {
    /// Its text.
    pub label: Label,
    /// Where it went.
    pub placed: Placed,
}

/// The pose laid out in a pane.
#[derive(Clone, Debug, PartialEq)]
pub struct LaidPose {
    /// The pane.
    pub pane: Rect,
    /// Pixels per metre.
    pub px_per_m: f64,
    /// Link outlines, pixels.
    pub links: Vec<Vec<Pt>>,
    /// Ground pivots, pixels.
    pub ground_pivots: Vec<Pt>,
    /// Joints, pixels.
    pub joints: Vec<Pt>,
    /// Slider blocks: the four corners, pixels.
    pub sliders: Vec<[Pt; 4]>,
    /// Instant centres on the figure, pixels.
    pub centres: Vec<Pt>,
    /// Joint names, then the centres' labels.
    pub labels: Vec<PoseLabel>,
    /// The moving links' numbers (2, 3, …: the frame is 1), the numbers the force
    /// tables and the instant centres name them by, beside each link.
    pub link_numbers: Vec<PoseLabel>,
    /// Centres not drawn: at infinity (with their direction), or far off the figure.
    pub centres_off: Vec<(Label, Centre)>,
    /// The scale bar, metres.
    pub scale_bar: Option<ScaleBar>,
}

/// The box of the ground symbol drawn under a pivot at `p`: a triangle 14 px wide
/// and 11 px high with a base line 20 px wide, and [`SYMBOL_CLEARANCE`] either side:
/// a joint letter placed flush against the symbol's box was drawn a little wider
/// than its estimate, over the base line's end.
pub fn pivot_symbol_box(p: Pt) -> Rect {
    Rect {
        min: [p[0] - 10.0 - SYMBOL_CLEARANCE, p[1]],
        max: [p[0] + 10.0 + SYMBOL_CLEARANCE, p[1] + 12.0],
    }
}

/// Room kept between a ground symbol's base line and a letter beside it, px.
const SYMBOL_CLEARANCE: f64 = 2.5;

/// A centre farther from the mechanism's box than this many times its size is
/// listed instead of drawn (it would shrink the mechanism to a speck).
const CENTRE_REACH: f64 = 1.5;

/// The centres listed, not drawn, with where they are.
type CentresOff = Vec<(Label, Centre)>;

/// The instant centres within [`CENTRE_REACH`] of the mechanism's box (of size
/// `size`), to draw, and the others, to list.
fn centres_near(fig: &PoseFigure, mech: Rect, size: f64) -> (Vec<(Label, Pt)>, CentresOff) {
    let reach = mech.expand(CENTRE_REACH * size);
    let mut shown = Vec::new();
    let mut centres_off = Vec::new();
    for c in &fig.centres {
        match c.centre {
            Centre::At(p) if reach.contains_rect(&Rect { min: p, max: p }) => {
                shown.push((c.label.clone(), p))
            }
            other => centres_off.push((c.label.clone(), other)),
        }
    }
    (shown, centres_off)
}

/// A slider block's four corners at `at` (pixels), 2.8 `half` along its guide's
/// `direction` (in metres, y up) and 2 `half` across.
fn slider_block(at: Pt, direction: [f64; 2], half: f64) -> [Pt; 4] {
    // y flips: the guide's direction in pixels.
    let d = [direction[0], -direction[1]];
    let n = [-d[1], d[0]];
    let corner = |a: f64, b: f64| {
        [
            at[0] + a * 1.4 * half * d[0] + b * half * n[0],
            at[1] + a * 1.4 * half * d[1] + b * half * n[1],
        ]
    };
    [
        corner(-1.0, -1.0),
        corner(1.0, -1.0),
        corner(1.0, 1.0),
        corner(-1.0, 1.0),
    ]
}

/// Each label placed by its point (pixels), in turn, away from the mechanism's
/// `middle`.
fn place_labels(
    named: impl Iterator<Item = (Label, Pt)>,
    middle: Pt,
    measure: &dyn Fn(&Label) -> [f64; 2],
    obstacles: &mut Obstacles,
) -> Vec<PoseLabel> {
    named
        .map(|(label, at)| {
            let away = [at[0] - middle[0], at[1] - middle[1]];
            let placed = place_vertex_label(at, away, measure(&label), obstacles);
            PoseLabel { label, placed }
        })
        .collect()
}

/// Each moving link's number (2 for the first: the frame is 1) beside its first
/// side, or by its one joint.
fn number_links(
    links: &[Vec<Pt>],
    measure: &dyn Fn(&Label) -> [f64; 2],
    obstacles: &mut Obstacles,
) -> Vec<PoseLabel> {
    links
        .iter()
        .enumerate()
        .filter_map(|(i, l)| {
            let label = Label::plain((i + 2).to_string());
            let size = measure(&label);
            let placed = match l[..] {
                [a, b, ..] => place_arrow_label(a, b, size, obstacles),
                [a] => place_vertex_label(a, [1.0, -1.0], size, obstacles),
                [] => return None,
            };
            Some(PoseLabel { label, placed })
        })
        .collect()
}

/// Lays the pose out in `pane`.
pub fn layout_pose(
    fig: &PoseFigure,
    pane: Rect,
    sizes: Sizes,
    measure: &dyn Fn(&Label) -> [f64; 2],
) -> LaidPose {
    let mech = fig.mechanism_box().unwrap_or(Rect {
        min: [0.0; 2],
        max: [0.0; 2],
    });
    let size = mech.width().max(mech.height()).max(1e-9);
    let (shown, centres_off) = centres_near(fig, mech, size);
    let all = Rect::around(
        [mech.min, mech.max]
            .into_iter()
            .chain(shown.iter().map(|c| c.1)),
    )
    .unwrap_or(mech);
    let mut fitted = Fit::new(all, pane, sizes);
    if fitted.scale == 0.0 {
        // A mechanism that is a point: drawn at a pixel per metre.
        fitted.scale = 1.0;
    }
    let (s, px) = (fitted.scale, |p: Pt| fitted.px(p));
    let links: Vec<Vec<Pt>> = fig
        .links
        .iter()
        .map(|l| l.iter().map(|&p| px(p)).collect())
        .collect();
    let joints: Vec<Pt> = fig.joints.iter().map(|j| px(j.1)).collect();
    let centres: Vec<Pt> = shown.iter().map(|c| px(c.1)).collect();
    let half = 0.9 * sizes.font_px;
    let sliders: Vec<[Pt; 4]> = fig
        .sliders
        .iter()
        .map(|sl| slider_block(px(sl.at), sl.direction, half))
        .collect();
    let ground_pivots: Vec<Pt> = fig.ground_pivots.iter().map(|&p| px(p)).collect();
    let shapes = ground_pivots
        .iter()
        .map(|&p| pivot_symbol_box(p))
        .chain(sliders.iter().filter_map(|c: &[Pt; 4]| Rect::around(*c)))
        .collect::<Vec<_>>();
    let mut obstacles = Obstacles::for_points(
        pane.expand(-2.0),
        &links,
        joints.iter().chain(&centres),
        shapes.into_iter(),
    );
    let names = fig
        .joints
        .iter()
        .map(|(name, _)| Label::plain(name.clone()));
    let named = names.zip(joints.iter().copied()).chain(
        shown
            .iter()
            .map(|c| c.0.clone())
            .zip(centres.iter().copied()),
    );
    let labels = place_labels(named, px(mech.centre()), measure, &mut obstacles);
    let link_numbers = number_links(&links, measure, &mut obstacles);
    LaidPose {
        pane,
        px_per_m: s,
        links,
        ground_pivots,
        joints,
        sliders,
        centres,
        labels,
        link_numbers,
        centres_off,
        scale_bar: Some(fitted.scale_bar(size, pane, sizes)),
    }
}
