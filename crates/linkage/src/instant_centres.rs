//! Instant centres of velocity of every pair of links, found as the textbook finds
//! them: the primary centres at the joints (a revolute joint's pin; for a prismatic
//! joint, a centre at infinity perpendicular to the guide), then the others by
//! Kennedy's theorem (the three centres of any three links lie on one line), an
//! unknown centre P_ij being where the lines P_ik–P_kj and P_il–P_lj cross.
//!
//! A cam contact is a higher pair: its centre lies on the common normal at the
//! contact, and by Kennedy on the line of the cam's and the follower's centres with
//! ground.
//!
//! Kennedy's construction uses the pose alone, not the velocities, so its centres
//! check the velocity solution independently. Points are homogeneous coordinates
//! (x, y, w), so that a centre at infinity (two links in relative translation) is a
//! direction, and a line through it, or two parallel lines meeting there, need no
//! special case. At some poses every line through known centres that should fix a
//! centre is the same line (the quick-return shaper with its rocker upright: pivots,
//! block and rocker tip in one line); the textbook then turns to velocity ratios, and
//! so does this: such a centre is the point where the two links' velocity fields
//! agree, marked [`FoundBy::Velocities`].

use nalgebra::Vector3;
use serde::Serialize;

use crate::Solution;
use crate::ids::{LinkId, PointId};
use crate::model::Mechanism;
use crate::motion::Vec2;

/// Below this, a homogeneous cross product counts as zero (two centres that coincide,
/// or two lines that do), relative to the unit-scaled coordinates used here.
const DEGENERATE: f64 = 1e-9;

/// Where an instant centre is.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum Centre {
    /// A point, m.
    At([f64; 2]),
    /// At infinity: the two links translate relative to each other, at right angles
    /// to this unit direction (the centre lies along it, infinitely far).
    AtInfinity([f64; 2]),
}

/// How a centre was found.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum FoundBy {
    /// The pin of a revolute joint.
    Pin(PointId),
    /// A prismatic joint (index into `Mechanism::sliders`).
    Slide(usize),
    /// Kennedy's theorem through the centres of these two other links.
    Kennedy([LinkId; 2]),
    /// A cam contact (index into `Mechanism::cams`): the common normal at the contact
    /// crossed with the line of the cam's and the follower's centres with ground.
    CamContact(usize),
    /// Where the two links' velocities agree (Kennedy's lines all coincide here).
    Velocities,
}

/// The instant centre of two links.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct InstantCentre {
    /// The two links, indices into `Mechanism::links`, the lower first.
    pub links: [LinkId; 2],
    /// Where it is.
    pub centre: Centre,
    /// How it was found.
    pub found_by: FoundBy,
}

/// Every instant centre of a mechanism at one pose.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct InstantCentres {
    /// The centres found, n(n-1)/2 for n links where all are.
    pub centres: Vec<InstantCentre>,
    /// Pairs whose centre neither Kennedy's theorem nor the velocities fix: the two
    /// links move as one at this pose (a dead point of the chain, or no motion).
    pub unresolved: Vec<[LinkId; 2]>,
}

impl InstantCentres {
    /// The centre of links `i` and `j`, if found.
    pub fn between(&self, i: LinkId, j: LinkId) -> Option<&InstantCentre> {
        let key = [i.min(j), i.max(j)];
        self.centres.iter().find(|c| c.links == key)
    }
}

/// Every instant centre of `m` at the pose `s`.
pub fn instant_centres(m: &Mechanism, s: &Solution) -> InstantCentres {
    let n = m.links.len();
    // Coordinates scaled by the mechanism's size, so that the tolerances are relative.
    let scale = m.size_m.max(f64::MIN_POSITIVE);
    let mut table = Table::new(n);
    for r in &m.revolutes {
        let p = s.points[r.point].position / scale;
        table.set(
            r.a.index(),
            r.b.index(),
            Vector3::new(p.x, p.y, 1.0),
            FoundBy::Pin(r.point),
        );
    }
    for (i, slide) in m.sliders.iter().enumerate() {
        let g = slide.direction(&s.links);
        let normal = Vector3::new(-g.y, g.x, 0.0);
        table.set(
            slide.slider.index(),
            slide.guide.index(),
            normal,
            FoundBy::Slide(i),
        );
    }
    for (i, cam) in m.cams.iter().enumerate() {
        let contact = cam.contact(s.links[cam.cam].angle_rad());
        let at = contact.roller / scale;
        let normal = Vector3::new(at.x, at.y, 1.0).cross(&Vector3::new(
            contact.normal.x,
            contact.normal.y,
            0.0,
        ));
        let (c, f, g) = (cam.cam.index(), cam.follower.index(), m.ground.index());
        if let (Some(cg), Some(fg)) = (table.get(c, g), table.get(f, g)) {
            table.set(c, f, normal.cross(&cg.cross(&fg)), FoundBy::CamContact(i));
        }
    }
    while table.kennedy_pass() {}
    for i in 0..n {
        for j in i + 1..n {
            if table.get(i, j).is_none()
                && let Some(p) = from_velocities(s, i, j, scale)
            {
                table.set(i, j, p, FoundBy::Velocities);
            }
        }
    }
    table.finish(scale)
}

/// The centre of `i` and `j` from their velocity fields, in scaled homogeneous
/// coordinates: v_j(x) − v_i(x) = Δv(0) + Δω perp(x) vanishes at x; with Δω = 0 the
/// links translate relative to each other and the centre is at infinity across Δv.
fn from_velocities(s: &Solution, i: usize, j: usize, scale: f64) -> Option<Vector3<f64>> {
    let origin = Vec2::zeros();
    let velocity = |k: usize| s.links[k].material_point_at(&origin).velocity;
    let dv = velocity(j) - velocity(i);
    let dw = s.links[j].omega_rad_s - s.links[i].omega_rad_s;
    // (x, y, w) = (−Δv_y, Δv_x, Δω·scale): the point (−Δv_y/Δω, Δv_x/Δω) in metres,
    // scaled, and at Δω = 0 the direction across Δv.
    let p = Vector3::new(-dv.y, dv.x, dw * scale);
    (p.norm() > 0.0 && p.iter().all(|c| c.is_finite())).then_some(p)
}

/// The centres known so far, by pair, in scaled homogeneous coordinates.
struct Table {
    n: usize,
    known: Vec<Option<(Vector3<f64>, FoundBy)>>,
}

impl Table {
    fn new(n: usize) -> Self {
        Self {
            n,
            known: vec![None; n * n],
        }
    }

    fn get(&self, i: usize, j: usize) -> Option<Vector3<f64>> {
        self.known[i * self.n + j].map(|(p, _)| p)
    }

    /// Keeps the first centre found for a pair (a second joint between the same two
    /// links would make them one).
    fn set(&mut self, i: usize, j: usize, p: Vector3<f64>, by: FoundBy) {
        if i == j || self.known[i * self.n + j].is_some() {
            return;
        }
        let p = normalised(p);
        self.known[i * self.n + j] = Some((p, by));
        self.known[j * self.n + i] = Some((p, by));
    }

    /// Finds every centre that two known lines fix now; whether it found any.
    fn kennedy_pass(&mut self) -> bool {
        let mut found = false;
        for i in 0..self.n {
            for j in i + 1..self.n {
                if self.get(i, j).is_none()
                    && let Some((p, via)) = self.kennedy(i, j)
                {
                    self.set(i, j, p, FoundBy::Kennedy(via.map(LinkId)));
                    found = true;
                }
            }
        }
        found
    }

    /// P_ij as the crossing of the best-conditioned pair of lines P_ik–P_kj: the pair
    /// at the largest angle, where a small error in a line moves the crossing least.
    fn kennedy(&self, i: usize, j: usize) -> Option<(Vector3<f64>, [usize; 2])> {
        let lines: Vec<(usize, Vector3<f64>)> = (0..self.n)
            .filter(|&k| k != i && k != j)
            .filter_map(|k| {
                let line = self.get(i, k)?.cross(&self.get(k, j)?);
                (line.norm() > DEGENERATE).then(|| (k, line.normalize()))
            })
            .collect();
        let mut best: Option<(f64, Vector3<f64>, [usize; 2])> = None;
        for (a, (k, first)) in lines.iter().enumerate() {
            for (l, second) in &lines[a + 1..] {
                let p = first.cross(second);
                let sine = p.norm();
                if sine > DEGENERATE && best.is_none_or(|(s, _, _)| sine > s) {
                    best = Some((sine, p, [*k, *l]));
                }
            }
        }
        best.map(|(_, p, via)| (p, via))
    }

    fn finish(&self, scale: f64) -> InstantCentres {
        let mut out = InstantCentres::default();
        for i in 0..self.n {
            for j in i + 1..self.n {
                match self.known[i * self.n + j] {
                    Some((p, found_by)) => out.centres.push(InstantCentre {
                        links: [LinkId(i), LinkId(j)],
                        centre: to_centre(p, scale),
                        found_by,
                    }),
                    None => out.unresolved.push([LinkId(i), LinkId(j)]),
                }
            }
        }
        out
    }
}

/// Unit length, and w ≥ 0 (a point and its negation are the same point).
fn normalised(p: Vector3<f64>) -> Vector3<f64> {
    let p = p / p.norm();
    if p.z < 0.0 { -p } else { p }
}

/// Back to metres; a point whose w is lost in round-off (farther than about 1e9
/// mechanism sizes) is at infinity for every purpose of a drawing or a velocity.
fn to_centre(p: Vector3<f64>, scale: f64) -> Centre {
    let direction = Vec2::new(p.x, p.y);
    if p.z.abs() <= DEGENERATE * direction.norm() {
        let d = direction.normalize();
        Centre::AtInfinity([d.x, d.y])
    } else {
        let at = direction * (scale / p.z);
        Centre::At([at.x, at.y])
    }
}
