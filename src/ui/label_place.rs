//! Where a joint's name goes in the mechanism view: beside its pin, on the side
//! where it covers nothing. Each of eight places around the pin is scored by what
//! it would cover (another joint's pin, a link, a velocity or acceleration arrow or
//! its tip, a name already placed) and the clearest is taken; ties keep the
//! textbook's place, above and to the right. Before, every name sat above and to the
//! right, and at 60° on the die cutter "A" covered B's pin; on a phone "A" sat at the
//! tip of C's velocity arrow (read as "the velocity of A"), and zoomed in, names hid
//! under pins drawn larger than the fixed clearance.

use eframe::egui::{Pos2, Rect, Vec2, pos2, vec2};

/// What a name must keep clear of, in screen points.
#[derive(Clone, Debug, Default)]
pub struct Obstacles {
    /// Pins (their centres): a name never covers one.
    pub pins: Vec<Pos2>,
    /// Other named points (marks drawn as dots, a spring's end, a guide's point): a
    /// name does not cover one, nor sit nearer one than its own point.
    pub points: Vec<Pos2>,
    /// Links and arrows, as segments: a name avoids crossing them.
    pub segments: Vec<[Pos2; 2]>,
    /// Names already placed.
    pub names: Vec<Rect>,
    /// The tips of the arrows: a name at one reads as the arrow's point.
    pub tips: Vec<Pos2>,
    /// The pins' drawn radius, points (they grow as the view zooms in); a name keeps
    /// this far from a pin's centre, and at least [`PIN_CLEARANCE`].
    pub pin_radius: f32,
}

impl Obstacles {
    /// How far a name keeps from a pin's centre, points.
    fn pin_clearance(&self) -> f32 {
        (self.pin_radius + 3.0).max(PIN_CLEARANCE)
    }
}

/// A pin's drawn radius with a margin, points: a name keeps this far from any pin's
/// centre.
pub const PIN_CLEARANCE: f32 = 9.0;
/// Half a link's drawn width with a margin, points: a name keeps this far from a
/// link's centre line.
const LINK_HALF_WIDTH: f32 = 6.0;
/// The gap between a pin and its own name, points.
const GAP: f32 = 4.0;
/// How much farther from the pin the outer ring of places is, points (a fixed step:
/// as a multiple, a slider block's name went 60 points from its pin).
const FARTHER: f32 = 12.0;
/// How far a name keeps from another named point's dot, points.
const POINT_CLEARANCE: f32 = 4.0;
/// What a place in the outer ring costs beyond what it covers: less than crossing a
/// link or an arrow (10), more than nothing.
const FARTHER_COST: f32 = 5.0;
/// What a place nearer another pin than the name's own costs: as much as crossing
/// a link or an arrow.
const AMBIGUOUS_COST: f32 = 10.0;
/// How far a name keeps from an arrow's tip, points: the head (9 points long) and a
/// margin.
pub const TIP_CLEARANCE: f32 = 10.0;

/// The eight places around a pin, the textbook's first (above right).
const PLACES: [(f32, f32); 8] = [
    (1.0, -1.0),
    (1.0, 1.0),
    (-1.0, -1.0),
    (-1.0, 1.0),
    (0.0, -1.0),
    (1.0, 0.0),
    (0.0, 1.0),
    (-1.0, 0.0),
];

/// The rectangle for a name of `size` beside the pin at `pin`, where it covers the
/// least of `obstacles` (the pin itself excluded).
pub fn place(pin: Pos2, size: Vec2, obstacles: &Obstacles) -> Rect {
    place_clear_of(pin, 0.0, size, obstacles)
}

/// As [`place`], for a pin drawn inside a shape `radius` points around it (a slider's
/// block): the name goes outside that shape.
pub fn place_clear_of(pin: Pos2, radius: f32, size: Vec2, obstacles: &Obstacles) -> Rect {
    let reach = radius.max(obstacles.pin_clearance()) + GAP;
    // The eight places beside the pin, then eight a little farther out: a clear
    // place there beats one on a link or an arrow (at crank 0 the die cutter's "A",
    // hemmed in by its pivot, the crank, the coupler and B's arrow, sat on the
    // arrow), but not a clear place beside the pin.
    let candidates = [(reach, 0.0), (reach + FARTHER, FARTHER_COST)]
        .into_iter()
        .flat_map(|(ring, extra)| {
            PLACES
                .iter()
                .map(move |&(dx, dy)| (candidate(pin, ring, size, dx, dy), extra))
        });
    let mut best = None;
    for (order, (rect, extra)) in candidates.enumerate() {
        let cost = cost(rect, pin, obstacles) + extra + order as f32 * 0.01;
        if best.is_none_or(|(c, _)| cost < c) {
            best = Some((cost, rect));
        }
    }
    best.map_or_else(|| candidate(pin, reach, size, 1.0, -1.0), |(_, r)| r)
}

/// The name's rectangle in direction (`dx`, `dy`) from the pin, `reach` from it.
fn candidate(pin: Pos2, reach: f32, size: Vec2, dx: f32, dy: f32) -> Rect {
    // The corner (or edge midpoint) nearest the pin sits `reach` away from it.
    let anchor = pin + vec2(dx, dy) * reach;
    let min = pos2(
        match dx {
            d if d > 0.0 => anchor.x,
            d if d < 0.0 => anchor.x - size.x,
            _ => anchor.x - size.x / 2.0,
        },
        match dy {
            d if d > 0.0 => anchor.y,
            d if d < 0.0 => anchor.y - size.y,
            _ => anchor.y - size.y / 2.0,
        },
    );
    Rect::from_min_size(min, size)
}

/// What a name at `rect` would cover: a pin, a name or an arrow's tip counts most, a
/// segment less.
fn cost(rect: Rect, own: Pos2, obstacles: &Obstacles) -> f32 {
    let near = rect.expand(obstacles.pin_clearance());
    let pins = obstacles
        .pins
        .iter()
        .filter(|p| p.distance(own) > 0.5 && near.contains(**p))
        .count();
    let tips = obstacles
        .tips
        .iter()
        .filter(|t| rect.expand(TIP_CLEARANCE).contains(**t))
        .count();
    let names = obstacles
        .names
        .iter()
        .filter(|n| n.intersects(rect.expand(1.0)))
        .count();
    let segments = obstacles
        .segments
        .iter()
        .filter(|&&[a, b]| crosses(rect.expand(LINK_HALF_WIDTH), a, b))
        .count();
    let points = obstacles
        .points
        .iter()
        .filter(|p| p.distance(own) > 0.5 && rect.expand(POINT_CLEARANCE).contains(**p))
        .count();
    // A name nearer another pin or named point than its own reads as that one's.
    let own_distance = rect.center().distance(own);
    let nearer_other = obstacles
        .pins
        .iter()
        .chain(&obstacles.points)
        .any(|p| p.distance(own) > 0.5 && rect.center().distance(*p) < own_distance);
    100.0 * (pins + names + tips + points) as f32
        + 10.0 * segments as f32
        + if nearer_other { AMBIGUOUS_COST } else { 0.0 }
}

/// Whether the segment from `a` to `b` passes through `rect` (sampled finely
/// enough for names a few points high).
fn crosses(rect: Rect, a: Pos2, b: Pos2) -> bool {
    let steps = ((b - a).length() / 3.0).ceil().clamp(1.0, 400.0) as usize;
    (0..=steps).any(|k| rect.contains(a.lerp(b, k as f32 / steps as f32)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A pin just above and to the right of another: the name goes elsewhere.
    #[test]
    fn a_name_keeps_off_a_neighbouring_pin() {
        let a = pos2(100.0, 100.0);
        let b = pos2(114.0, 86.0);
        let obstacles = Obstacles {
            pins: vec![a, b],
            segments: vec![[a, b]],
            ..Obstacles::default()
        };
        let rect = place(a, vec2(10.0, 14.0), &obstacles);
        assert!(!rect.expand(PIN_CLEARANCE).contains(b), "{rect:?}");
        assert!(rect.center().distance(a) < 40.0, "stays beside its pin");
    }

    /// With nothing around, the textbook's place: above and to the right.
    #[test]
    fn alone_a_name_sits_above_right() {
        let a = pos2(50.0, 50.0);
        let rect = place(a, vec2(10.0, 14.0), &Obstacles::default());
        assert!(rect.min.x > a.x && rect.max.y < a.y, "{rect:?}");
    }

    /// A link leaving the pin up and to the right: the name takes another side.
    #[test]
    fn a_name_avoids_the_links_at_its_pin() {
        let a = pos2(50.0, 50.0);
        let obstacles = Obstacles {
            pins: vec![a],
            segments: vec![[a, pos2(150.0, -50.0)]],
            ..Obstacles::default()
        };
        let rect = place(a, vec2(10.0, 14.0), &obstacles);
        assert!(!crosses(rect, a, pos2(150.0, -50.0)), "{rect:?}");
    }

    /// Another arrow's tip just above and to the right: the name goes elsewhere.
    #[test]
    fn a_name_keeps_off_an_arrows_tip() {
        let a = pos2(50.0, 50.0);
        let tip = pos2(66.0, 36.0);
        let obstacles = Obstacles {
            pins: vec![a],
            segments: vec![[pos2(66.0, 96.0), tip]],
            tips: vec![tip],
            ..Obstacles::default()
        };
        let rect = place(a, vec2(10.0, 14.0), &obstacles);
        assert!(!rect.expand(TIP_CLEARANCE).contains(tip), "{rect:?}");
    }

    /// Pins drawn larger (zoomed in): the name goes outside the drawn pin.
    #[test]
    fn a_name_clears_a_large_pin() {
        let a = pos2(200.0, 200.0);
        let obstacles = Obstacles {
            pins: vec![a],
            pin_radius: 30.0,
            ..Obstacles::default()
        };
        let rect = place(a, vec2(10.0, 14.0), &obstacles);
        let nearest = pos2(
            a.x.clamp(rect.min.x, rect.max.x),
            a.y.clamp(rect.min.y, rect.max.y),
        );
        assert!(nearest.distance(a) > 30.0, "{rect:?}");
    }

    /// Another pin a little to the right: the name goes where it is nearer its own
    /// pin (above right, it read as the other's).
    #[test]
    fn a_name_is_nearer_its_own_pin_than_any_other() {
        let (a, b) = (pos2(100.0, 100.0), pos2(132.0, 100.0));
        let obstacles = Obstacles {
            pins: vec![a, b],
            ..Obstacles::default()
        };
        let rect = place(a, vec2(10.0, 14.0), &obstacles);
        assert!(
            rect.center().distance(a) < rect.center().distance(b),
            "{rect:?}"
        );
    }

    /// A named point (a mark, a spring's end) is kept clear of and not read as the
    /// name's: the cam feed's "B" had sat nearer the roller R than its own pin.
    #[test]
    fn a_name_keeps_off_and_away_from_other_named_points() {
        let (a, r) = (pos2(100.0, 100.0), pos2(118.0, 84.0));
        let obstacles = Obstacles {
            pins: vec![a],
            points: vec![r],
            ..Obstacles::default()
        };
        let rect = place(a, vec2(10.0, 14.0), &obstacles);
        assert!(!rect.expand(POINT_CLEARANCE).contains(r), "{rect:?}");
        assert!(
            rect.center().distance(a) < rect.center().distance(r),
            "{rect:?}"
        );
    }
}
