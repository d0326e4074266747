//! The mechanism at one position as a figure: each moving link as the outline of its
//! joints, ground pivots, sliders on their guides, joint names, and on request the
//! instant centres (I with the two links' numbers as subscript; a centre at infinity
//! as the direction it lies in). Units are metres, y up.

use linkage::instant_centres::{Centre, InstantCentres};
use linkage::{LinkId, Mechanism, PointId, Solution};

use crate::geometry::{Pt, Rect};
use crate::label::{Label, Run, Script};

/// A slider block on its guide.
#[derive(Clone, Debug, PartialEq)]
pub struct SliderShape {
    /// The block's centre, m.
    pub at: Pt,
    /// The guide's unit direction.
    pub direction: Pt,
}

/// An instant centre to draw.
#[derive(Clone, Debug, PartialEq)]
pub struct CentreMark {
    /// `I` with the links' numbers (1 the frame) as subscript.
    pub label: Label,
    /// Where it is.
    pub centre: Centre,
}

/// The pose of a mechanism as a figure.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PoseFigure {
    /// Per moving link in the scene's order (the i-th is numbered i + 2, as
    /// [`link_number`] numbers it), the outline through its joints (two points for a
    /// binary link).
    pub links: Vec<Vec<Pt>>,
    /// Pivots on the frame.
    pub ground_pivots: Vec<Pt>,
    /// Joints by name (uppercase, as in the scene).
    pub joints: Vec<(String, Pt)>,
    /// Sliders.
    pub sliders: Vec<SliderShape>,
    /// Instant centres, when asked for.
    pub centres: Vec<CentreMark>,
}

/// The number a link goes by in instant-centre names: the frame is 1, the moving
/// links follow in the scene's order.
pub fn link_number(m: &Mechanism, link: LinkId) -> usize {
    if link == m.ground {
        1
    } else {
        2 + m.moving_links().position(|l| l == link).unwrap_or(0)
    }
}

/// The joints of `link`: its revolutes' points, then its slider blocks'.
pub fn link_joints(m: &Mechanism, link: LinkId) -> Vec<PointId> {
    let mut pts: Vec<PointId> = m
        .revolutes
        .iter()
        .filter(|r| r.a == link || r.b == link)
        .map(|r| r.point)
        .chain(
            m.sliders
                .iter()
                .filter(|sl| sl.slider == link)
                .map(|sl| sl.point),
        )
        .collect();
    pts.dedup();
    pts
}

impl PoseFigure {
    /// The figure of `m` at `s`, with `centres` if given.
    pub fn new(m: &Mechanism, s: &Solution, centres: Option<&InstantCentres>) -> Self {
        let at = |p: PointId| {
            let q = s.points[p].position;
            [q.x, q.y]
        };
        let joints = m.joint_points();
        let links = m
            .moving_links()
            .map(|l| outline(link_joints(m, l).into_iter().map(at).collect()))
            .collect();
        let ground_pivots = m
            .revolutes
            .iter()
            .filter(|r| r.a == m.ground || r.b == m.ground)
            .map(|r| at(r.point))
            .collect();
        let sliders = m
            .sliders
            .iter()
            .map(|sl| {
                let d = sl.direction(&s.links);
                SliderShape {
                    at: at(sl.point),
                    direction: [d.x, d.y],
                }
            })
            .collect();
        let centres = centres
            .map(|c| {
                c.centres
                    .iter()
                    .map(|ic| CentreMark {
                        label: centre_label(
                            link_number(m, ic.links[0]),
                            link_number(m, ic.links[1]),
                        ),
                        centre: ic.centre,
                    })
                    .collect()
            })
            .unwrap_or_default();
        Self {
            links,
            ground_pivots,
            joints: joints
                .into_iter()
                .map(|p| (m.points[p].name.clone(), at(p)))
                .collect(),
            sliders,
            centres,
        }
    }

    /// The box of the links and joints, m (instant centres may lie far outside).
    pub fn mechanism_box(&self) -> Option<Rect> {
        Rect::around(
            self.links
                .iter()
                .flatten()
                .copied()
                .chain(self.joints.iter().map(|j| j.1)),
        )
    }
}

/// `I` with subscript `ij` (the smaller number first).
pub fn centre_label(i: usize, j: usize) -> Label {
    let (i, j) = (i.min(j), i.max(j));
    let sub = if i >= 10 || j >= 10 {
        format!("{i},{j}")
    } else {
        format!("{i}{j}")
    };
    Label {
        runs: vec![
            Run {
                text: "I".into(),
                script: Script::Base,
            },
            Run {
                text: sub,
                script: Script::Sub,
            },
        ],
    }
}

/// The points in order round their centroid, so that a ternary link's outline does
/// not cross itself.
fn outline(mut pts: Vec<Pt>) -> Vec<Pt> {
    if pts.len() < 3 {
        return pts;
    }
    let n = pts.len() as f64;
    let c = [
        pts.iter().map(|p| p[0]).sum::<f64>() / n,
        pts.iter().map(|p| p[1]).sum::<f64>() / n,
    ];
    pts.sort_by(|a, b| {
        (a[1] - c[1])
            .atan2(a[0] - c[0])
            .total_cmp(&(b[1] - c[1]).atan2(b[0] - c[0]))
    });
    pts
}
