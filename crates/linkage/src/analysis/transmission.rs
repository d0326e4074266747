//! The transmission angle of each dyad, at one position and its extremes over the
//! assembly ranges, and joints that lie on one line.

use serde::Serialize;

use super::TAU;
use crate::assembly::AssemblyRanges;
use crate::dyad::GroupLabel;
use crate::ids::{LinkId, PointId};
use crate::motion::{Solution, Vec2, cross, perp};
use crate::roots_util::{refine, sign_changes};
use crate::solve::Group;
use crate::solve::Kinematics;

/// Acute transmission angle summary, rad.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TransmissionAngle {
    /// Smallest transmission angle over the cycle (0 = locked, π/2 = ideal).
    pub min: f64,
    /// Largest.
    pub max: f64,
    /// Input angle where the minimum occurs, rad.
    pub at: f64,
    /// Input angle where the maximum occurs, rad.
    pub at_max: f64,
    /// The group where the minimum occurs.
    pub group: GroupLabel,
}

/// The two lines whose acute angle is a group's transmission angle, with their
/// angular velocities: RRR: the two links at the inner joint; RRP: the coupler and
/// the normal of the guide (90° minus the pressure angle).
fn transmission_lines(k: &Kinematics, g: usize, s: &Solution) -> Option<(Vec2, f64, Vec2, f64)> {
    let cf = k.closed_form()?;
    match &cf.groups[g] {
        Group::Rrr(d) => {
            let mid = s.links[d.i].world(&d.mid_on_i);
            let a = s.links[d.a.link].world(&d.a.local);
            let c = s.links[d.c.link].world(&d.c.local);
            Some((
                mid - a,
                s.links[d.i].omega_rad_s,
                mid - c,
                s.links[d.j].omega_rad_s,
            ))
        }
        Group::Rrp(d) => {
            let mid = s.links[d.j].world(&d.mid_on_j);
            let a = s.links[d.a.link].world(&d.a.local);
            let guide = &s.links[d.slide.guide];
            let u = guide.rotation * d.slide.direction_local;
            Some((
                mid - a,
                s.links[d.i].omega_rad_s,
                perp(&u),
                guide.omega_rad_s,
            ))
        }
        _ => None,
    }
}

fn acute(l1: &Vec2, l2: &Vec2) -> f64 {
    cross(l1, l2).abs().atan2(l1.dot(l2).abs())
}

/// Transmission angle at one solved position, rad in [0, π/2]: the smallest over the
/// chain's dyads (the one that transmits worst), `None` for a chain without dyads.
pub fn transmission_angle_at(k: &Kinematics, s: &Solution) -> Option<f64> {
    (0..k.group_count())
        .filter_map(|g| transmission_lines(k, g, s))
        .map(|(l1, _, l2, _)| acute(&l1, &l2))
        .min_by(f64::total_cmp)
}

/// Transmission angle extremes over the assembly ranges (root-finding on the
/// angle's rate, plus the crossings of 90° and the ends of limited ranges).
pub fn transmission_angle(
    k: &mut Kinematics,
    ranges: &AssemblyRanges,
) -> Option<TransmissionAngle> {
    let groups = k.group_count();
    let start = k.mechanism().driver.start_rad;
    let names: Vec<GroupLabel> = (0..groups).map(|g| k.group_name(g)).collect();
    // (input, angle, group) over all groups: the extremes are taken over all of them.
    let mut all: Vec<(f64, f64, usize)> = Vec::new();
    let mut sol = k.empty_solution();
    for g in 0..names.len() {
        let mut candidates: Vec<(f64, f64)> = Vec::new();
        let eval = |k: &mut Kinematics, x: f64, sol: &mut Solution| -> Option<(f64, f64, f64)> {
            k.solve_into(x, 1.0, sol).ok()?;
            let (l1, w1, l2, w2) = transmission_lines(k, g, sol)?;
            Some((acute(&l1, &l2), w1 - w2, l1.dot(&l2)))
        };
        for xs in ranges.grids(start) {
            let vals: Vec<Option<(f64, f64, f64)>> =
                xs.iter().map(|&x| eval(k, x, &mut sol)).collect();
            if vals.iter().all(Option::is_none) {
                continue;
            }
            for (x, v) in xs.iter().zip(&vals) {
                if let (Some((mu, _, _)), true) = (v, !ranges.full_rotation) {
                    candidates.push((*x, *mu));
                }
            }
            let rate: Vec<f64> = vals.iter().map(|v| v.map_or(f64::NAN, |t| t.1)).collect();
            let dot: Vec<f64> = vals.iter().map(|v| v.map_or(f64::NAN, |t| t.2)).collect();
            for (series, which) in [(rate, 1), (dot, 2)] {
                for i in sign_changes(&series) {
                    let root = refine(xs[i], xs[i + 1], |x| {
                        eval(k, x, &mut sol)
                            .map_or(f64::NAN, |t| if which == 1 { t.1 } else { t.2 })
                    });
                    if let Some(r) = root
                        && let Some((mu, _, _)) = eval(k, r, &mut sol)
                    {
                        candidates.push((r.rem_euclid(TAU), mu));
                    }
                }
            }
            if candidates.is_empty() {
                // Constant angle (e.g. a rocker whose coupler keeps its angle).
                if let Some((mu, _, _)) = vals.iter().flatten().next() {
                    candidates.push((xs[0], *mu));
                }
            }
        }
        all.extend(candidates.into_iter().map(|(x, mu)| (x, mu, g)));
    }
    let &(at, min, group) = all.iter().min_by(|a, b| a.1.total_cmp(&b.1))?;
    let &(at_max, max, _) = all.iter().max_by(|a, b| a.1.total_cmp(&b.1))?;
    Some(TransmissionAngle {
        min,
        max,
        at,
        at_max,
        group: names[group].clone(),
    })
}

/// A joint whose two moving links lie on one line: a toggle's or a dead point's
/// witness. It is written in a report as "C (crank-coupler, 0.0000 deg)".
#[derive(Clone, Debug, PartialEq)]
pub struct CollinearJoint {
    /// The joint's point.
    pub point: String,
    /// The two links.
    pub links: [String; 2],
    /// The acute angle between them there, rad.
    pub angle_rad: f64,
}

impl std::fmt::Display for CollinearJoint {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let [a, b] = &self.links;
        write!(
            f,
            "{} ({a}-{b}, {:.4} deg)",
            self.point,
            self.angle_rad.to_degrees()
        )
    }
}

// The report's JSON has carried each joint as its label since it was first written:
// programs that read it keep reading it.
impl serde::Serialize for CollinearJoint {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

/// Points where two moving links meet and lie on one line (within `tol_rad`): each
/// link's direction is taken from the point to its next joint point.
pub fn collinear_joints(k: &Kinematics, s: &Solution, tol_rad: f64) -> Vec<CollinearJoint> {
    let m = k.mechanism();
    let other_joint = |link: LinkId, not: PointId| -> Option<Vec2> {
        m.links[link]
            .points
            .iter()
            .find(|(p, _)| *p != not && m.revolutes.iter().any(|r| r.point == *p))
            .map(|(_, local)| s.links[link].world(local))
    };
    let mut found = Vec::new();
    for (pi, point) in m.point_ids().zip(&m.points) {
        let users: Vec<LinkId> = m
            .moving_links()
            .filter(|&l| m.links[l].local(pi).is_some())
            .collect();
        for (n, &a) in users.iter().enumerate() {
            for &b in &users[n + 1..] {
                let j = s.points[pi].position;
                let (Some(pa), Some(pb)) = (other_joint(a, pi), other_joint(b, pi)) else {
                    continue;
                };
                let angle = acute(&(pa - j), &(pb - j));
                if angle <= tol_rad {
                    found.push(CollinearJoint {
                        point: point.name.clone(),
                        links: [m.links[a].name.clone(), m.links[b].name.clone()],
                        angle_rad: angle,
                    });
                }
            }
        }
    }
    found
}
