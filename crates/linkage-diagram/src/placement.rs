//! Label placement: each label tries candidate places in order of preference — next
//! to its point or beside its arrow, then on rings further out with a leader line —
//! and takes the first that stays in the pane and overlaps no label placed before,
//! no arrow head and no vertex, crossing as few arrows as it can; a leader through
//! a label, or a label on a leader, counts as three arrows crossed (it reads as
//! striking the label out). Greedy placement
//! with candidates is what cartographic labelling does for point and line features;
//! the figures have tens of labels, so every candidate is checked directly.

use crate::geometry::{Pt, Rect, along, distance};

/// What a label must keep clear of.
#[derive(Clone, Debug)]
pub struct Obstacles {
    bounds: Rect,
    hard: Vec<Rect>,
    segments: Vec<[Pt; 2]>,
    /// The labels placed so far, each with its gap.
    labels: Vec<Rect>,
    /// The leaders drawn so far.
    leaders: Vec<[Pt; 2]>,
}

/// Where a label went.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placed {
    /// Its box.
    pub rect: Rect,
    /// A leader from the box to its anchor, when it is on an outer ring.
    pub leader: Option<[Pt; 2]>,
    /// Whether every candidate collided (the least bad one was taken).
    pub collides: bool,
    /// The arrows it crosses, weighted as [`Obstacles`] weighs them (0: clear of
    /// every line).
    pub cost: usize,
}

/// The free space kept round a placed label, pixels.
const LABEL_GAP: f64 = 1.5;

/// Radius of a vertex's dot, pixels.
pub const DOT_PX: f64 = 2.5;

impl Obstacles {
    /// Labels must stay inside `bounds`, off the arrows' heads (tip, left, right) and
    /// the vertices; the arrows' shafts `[tail, head]` are crossed as little as may be.
    pub fn new(bounds: Rect, shafts: &[[Pt; 2]], heads: &[[Pt; 3]], vertices: &[Pt]) -> Self {
        let heads = heads
            .iter()
            .copied()
            .filter_map(Rect::around)
            .map(|r| r.expand(1.0));
        let dots = vertices
            .iter()
            .map(|&v| Rect { min: v, max: v }.expand(DOT_PX + 1.0));
        Self {
            bounds,
            hard: heads.chain(dots).collect(),
            segments: shafts.to_vec(),
            labels: Vec::new(),
            leaders: Vec::new(),
        }
    }

    /// Labels must stay inside `bounds`, off the `points` and the `shapes` (pivot
    /// and slider symbols); the `outlines` (links) are crossed as little as may be.
    pub fn for_points<'a>(
        bounds: Rect,
        outlines: &[Vec<Pt>],
        points: impl Iterator<Item = &'a Pt>,
        shapes: impl Iterator<Item = Rect>,
    ) -> Self {
        let segments = outlines
            .iter()
            .flat_map(|o| {
                let closed = o.len() > 2;
                (0..o.len()).filter_map(move |i| {
                    let j = i + 1;
                    if j < o.len() {
                        Some([o[i], o[j]])
                    } else if closed {
                        Some([o[i], o[0]])
                    } else {
                        None
                    }
                })
            })
            .collect();
        Self {
            bounds,
            hard: points
                .map(|&p| Rect { min: p, max: p }.expand(DOT_PX + 2.0))
                .chain(shapes)
                .collect(),
            segments,
            labels: Vec::new(),
            leaders: Vec::new(),
        }
    }

    /// Whether `r` is a free place: in bounds, overlapping nothing hard.
    fn free(&self, r: &Rect) -> bool {
        self.bounds.contains_rect(r) && !self.hard.iter().any(|h| h.overlaps(r))
    }

    /// How many leaders drawn before cross `r`, and how many labels placed before
    /// its own leader to `anchor` crosses.
    fn leader_conflicts(&self, r: &Rect, anchor: Option<Pt>) -> usize {
        let on_leaders = self
            .leaders
            .iter()
            .filter(|l| r.crosses_segment(l[0], l[1]))
            .count();
        let through_labels = anchor.map_or(0, |a| {
            let from = nearest_on(r, a);
            self.labels
                .iter()
                .filter(|l| l.crosses_segment(from, a))
                .count()
        });
        on_leaders + through_labels
    }

    /// How many arrows cross `r`, an arrow through its text's core (which strikes
    /// the text out, where one across its edge only grazes it) counting as
    /// [`STRUCK_OUT`] of them.
    fn crossings(&self, r: &Rect) -> usize {
        let core = text_core(r);
        self.segments
            .iter()
            .filter(|s| r.crosses_segment(s[0], s[1]))
            .map(|s| {
                if core.crosses_segment(s[0], s[1]) {
                    STRUCK_OUT
                } else {
                    1
                }
            })
            .sum()
    }

    /// How badly `r` collides: overlap area with hard obstacles and the outside.
    fn badness(&self, r: &Rect) -> f64 {
        let overlap = |h: &Rect| {
            let w = (r.max[0].min(h.max[0]) - r.min[0].max(h.min[0])).max(0.0);
            let t = (r.max[1].min(h.max[1]) - r.min[1].max(h.min[1])).max(0.0);
            w * t
        };
        let area = r.width() * r.height();
        let inside = overlap(&self.bounds);
        (area - inside) + self.hard.iter().map(overlap).sum::<f64>()
    }

    /// Chooses among `candidates` (box, anchor of the leader if any), in order of
    /// preference; the chosen box becomes an obstacle for later labels.
    fn choose(&mut self, candidates: impl IntoIterator<Item = (Rect, Option<Pt>)>) -> Placed {
        let mut best: Option<(usize, usize, Rect, Option<Pt>)> = None;
        let mut least_bad: Option<(f64, Rect, Option<Pt>)> = None;
        for (order, (rect, leader)) in candidates.into_iter().enumerate() {
            if self.free(&rect) {
                let cost = self.crossings(&rect) + 3 * self.leader_conflicts(&rect, leader);
                if best.as_ref().is_none_or(|b| (cost, order) < (b.0, b.1)) {
                    best = Some((cost, order, rect, leader));
                }
                if cost == 0 {
                    break;
                }
            } else if best.is_none() {
                let bad = self.badness(&rect);
                if least_bad.as_ref().is_none_or(|l| bad < l.0) {
                    least_bad = Some((bad, rect, leader));
                }
            }
        }
        let (rect, leader, collides, cost) = match (best, least_bad) {
            (Some((c, _, r, l)), _) => (r, l, false, c),
            (None, Some((_, r, l))) => (r, l, true, self.crossings(&r)),
            // The callers always give candidates; were there none, the label sits
            // at the pane's corner, marked as colliding, rather than stop the drawing.
            (None, None) => (
                Rect {
                    min: self.bounds.min,
                    max: self.bounds.min,
                },
                None,
                true,
                0,
            ),
        };
        // A gap between labels: the measure is approximate, and glyphs set in a real
        // face may reach a pixel past it.
        self.hard.push(rect.expand(LABEL_GAP));
        self.labels.push(rect.expand(LABEL_GAP));
        let leader = leader.map(|a| [nearest_on(&rect, a), a]);
        self.leaders.extend(leader);
        Placed {
            rect,
            leader,
            collides,
            cost,
        }
    }
}

/// What a line through a text's core costs, in arrows crossed: as a leader through
/// a label, it reads as striking the text out.
const STRUCK_OUT: usize = 3;

/// The middle of a label's box, where its glyphs' strokes are: the box less a tenth
/// of its width either side and 15 % of its height above and below (the
/// ascenders', descenders' and scripts' room, which a line may cross and leave the
/// text legible). Wider than the glyphs' core, as the box is an approximate measure.
fn text_core(r: &Rect) -> Rect {
    let (dx, dy) = (0.1 * r.width(), 0.15 * r.height());
    Rect {
        min: [r.min[0] + dx, r.min[1] + dy],
        max: [r.max[0] - dx, r.max[1] - dy],
    }
}

/// How a candidate box keeps its gap from the anchor.
#[derive(Clone, Copy)]
enum Clear {
    /// From the point (a vertex): the box's side or corner `gap` from it.
    Point,
    /// From the line through it at right angles to the direction (an arrow): the
    /// whole box `gap` beyond that line, so that a slanted arrow does not cut its corner.
    Line,
}

/// The box of `size` `gap` from `anchor` in direction `d`.
fn box_towards(anchor: Pt, d: Pt, gap: f64, size: [f64; 2], clear: Clear) -> Rect {
    let n = d[0].hypot(d[1]);
    let d = if n > 0.0 {
        [d[0] / n, d[1] / n]
    } else {
        [1.0, 0.0]
    };
    let (hx, hy) = (0.5 * size[0] * d[0].abs(), 0.5 * size[1] * d[1].abs());
    let reach = gap
        + match clear {
            Clear::Point => hx.max(hy),
            // The box's half-extent along d (its support function).
            Clear::Line => hx + hy,
        };
    let c = along(anchor, d, reach);
    Rect::from_min_size(
        [c[0] - 0.5 * size[0], c[1] - 0.5 * size[1]],
        size[0],
        size[1],
    )
}

/// `n` directions round the circle, starting at `first` and alternating either side.
fn directions(first: Pt, n: usize) -> impl Iterator<Item = Pt> {
    let a0 = first[1].atan2(first[0]);
    let step = std::f64::consts::TAU / n as f64;
    (0..n).map(move |k| {
        let side = if k % 2 == 1 { 1.0 } else { -1.0 };
        let a = a0 + side * step * k.div_ceil(2) as f64;
        [a.cos(), a.sin()]
    })
}

/// Rings further out for a label with a leader, pixels: tried in turn with
/// [`RING_DIRECTIONS`] directions, then, where none of them was clear, the outer
/// ones again halfway between those directions and on two rings further still
/// (a crowded spot: a polygon's vertex among its labels, a plan's web of positions).
const RINGS_PX: [f64; 5] = [12.0, 20.0, 32.0, 48.0, 70.0];

/// Directions on each ring.
const RING_DIRECTIONS: usize = 16;

/// The rings of the second pass, pixels.
const SECOND_RINGS_PX: [f64; 4] = [48.0, 70.0, 100.0, 140.0];

/// The ring candidates round `anchor` (first pass, then the second), each with its
/// leader to `anchor`: from `first` on, alternating either side.
fn ring_candidates(
    anchor: Pt,
    first: Pt,
    size: [f64; 2],
) -> impl Iterator<Item = (Rect, Option<Pt>)> {
    // By its angle, as `first` may be zero (a zero-length arrow's normal), which
    // `directions` reads as the angle 0.
    let half_step = std::f64::consts::PI / RING_DIRECTIONS as f64;
    let (s, c) = (first[1].atan2(first[0]) + half_step).sin_cos();
    let between = [c, s];
    let on = move |rings: &'static [f64], from: Pt| {
        rings.iter().flat_map(move |&r| {
            directions(from, RING_DIRECTIONS)
                .map(move |d| (box_towards(anchor, d, r, size, Clear::Point), Some(anchor)))
        })
    };
    let last_two = &SECOND_RINGS_PX[2..];
    on(&RINGS_PX, first)
        .chain(on(&SECOND_RINGS_PX[..2], between))
        .chain(on(last_two, first))
        .chain(on(last_two, between))
}

/// Places a vertex's label next to it, preferring direction `away`.
pub fn place_vertex_label(anchor: Pt, away: Pt, size: [f64; 2], o: &mut Obstacles) -> Placed {
    let away = if away[0].hypot(away[1]) > 0.0 {
        away
    } else {
        [1.0, -1.0]
    };
    let near = directions(away, 8).map(move |d| {
        (
            box_towards(anchor, d, DOT_PX + 2.0, size, Clear::Point),
            None,
        )
    });
    o.choose(near.chain(ring_candidates(anchor, away, size)))
}

/// Places an arrow's label beside it, near its middle first.
pub fn place_arrow_label(from: Pt, to: Pt, size: [f64; 2], o: &mut Obstacles) -> Placed {
    let len = distance(from, to).max(1e-9);
    let n = [-(to[1] - from[1]) / len, (to[0] - from[0]) / len];
    let beside = [0.5, 0.35, 0.65, 0.2, 0.8].into_iter().flat_map(move |t| {
        let at = along(from, [to[0] - from[0], to[1] - from[1]], t);
        [n, [-n[0], -n[1]]]
            .into_iter()
            .map(move |side| (box_towards(at, side, 3.0, size, Clear::Line), None))
    });
    let mid = along(from, [to[0] - from[0], to[1] - from[1]], 0.5);
    o.choose(beside.chain(ring_candidates(mid, n, size)))
}

/// The point of `r`'s outline nearest to `p`.
fn nearest_on(r: &Rect, p: Pt) -> Pt {
    [
        p[0].clamp(r.min[0], r.max[0]),
        p[1].clamp(r.min[1], r.max[1]),
    ]
}

/// Where a label goes: by a vertex (preferring the direction `away`) or beside an
/// arrow or a line.
#[derive(Clone, Copy, Debug)]
pub enum Anchor {
    /// A point: a joint, a polygon's vertex, a position's pin.
    Vertex {
        /// The point.
        at: Pt,
        /// The direction preferred, away from the figure's middle.
        away: Pt,
    },
    /// An arrow or a link's side, from `from` to `to`.
    Arrow {
        /// Its tail.
        from: Pt,
        /// Its head.
        to: Pt,
    },
}

/// Tries of [`place_all`] beyond the first, from each end of the given order.
const REPAIR_TRIES: usize = 3;

/// What a label over another or past the pane costs in [`place_all`]'s totals.
const COLLIDES: usize = 1000;

/// Places a label of each size at its anchor, clear of `obstacles` and of each
/// other, returned in the order given. Greedy placement in one order leaves the
/// last labels the worst places; where a label is left crossed by a line (a crowded
/// corner), the crossed labels go first in a new try, up to [`REPAIR_TRIES`] times
/// from the order given and as many from its reverse, and the try whose labels
/// cross the fewest lines is kept.
pub fn place_all(obstacles: &Obstacles, labels: &[(Anchor, [f64; 2])]) -> Vec<Placed> {
    let given: Vec<usize> = (0..labels.len()).collect();
    let mut best = place_in(obstacles, labels, &given);
    for start in [given.clone(), given.into_iter().rev().collect()] {
        let mut order = start;
        for _ in 0..REPAIR_TRIES {
            if best.1 == 0 {
                break;
            }
            let (crossed, rest): (Vec<usize>, Vec<usize>) =
                order.iter().partition(|&&i| best.0[i].cost > 0);
            order = crossed.into_iter().chain(rest).collect();
            let next = place_in(obstacles, labels, &order);
            if next.1 < best.1 {
                best = next;
            }
        }
    }
    best.0
}

/// The labels placed in `order` among a copy of `obstacles`, in the order given,
/// with their total cost.
fn place_in(
    obstacles: &Obstacles,
    labels: &[(Anchor, [f64; 2])],
    order: &[usize],
) -> (Vec<Placed>, usize) {
    let mut o = obstacles.clone();
    let mut placed = vec![None; labels.len()];
    for &i in order {
        let (anchor, size) = labels[i];
        placed[i] = Some(match anchor {
            Anchor::Vertex { at, away } => place_vertex_label(at, away, size, &mut o),
            Anchor::Arrow { from, to } => place_arrow_label(from, to, size, &mut o),
        });
    }
    let placed: Vec<Placed> = placed.into_iter().flatten().collect();
    let total = placed
        .iter()
        .map(|p| if p.collides { COLLIDES } else { p.cost })
        .sum();
    (placed, total)
}
