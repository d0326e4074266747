//! The applied loads one by one: each weight, spring, damper, external force and
//! torque with the link it acts on and where, as a force polygon draws them. The
//! per-link resultants of [`ForceModel::applied_loads`] are their sums, so the
//! polygons and the Newton–Euler solution see the same loads.

use super::forces::{Damper, ForceModel, Load, couple};
use crate::ids::{LinkId, PointId};
use crate::motion::cross;
use crate::motion::{PointMotion, Solution, Vec2};
use crate::scene::ForceWhen;

/// Which force element a load comes from (an index into the scene's list of that
/// element).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LoadSource {
    /// The link's weight, at its centroid.
    Weight,
    /// Spring `n` of the scene.
    Spring(usize),
    /// Damper `n` of the scene.
    Damper(usize),
    /// External force `n` of the scene, at its point.
    PointForce {
        /// Its index in the scene's forces.
        index: usize,
        /// The point it acts at.
        point: PointId,
    },
    /// Torque element `n` of the scene.
    Torque(usize),
}

/// What a load does to its link.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Action {
    /// A force through a point.
    Force {
        /// The point of application, m.
        at: Vec2,
        /// That point's velocity, m/s (for the power).
        velocity: Vec2,
        /// The force, N.
        force: Vec2,
    },
    /// A couple, N·m.
    Couple {
        /// Its moment, counter-clockwise positive.
        moment: f64,
    },
}

/// One applied load on one link.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LoadTerm {
    /// The link it acts on.
    pub link: LinkId,
    /// The element it comes from.
    pub source: LoadSource,
    /// The force or couple.
    pub action: Action,
}

impl ForceModel {
    /// Applied loads on every link at the motion `sol` (real speeds): per link the
    /// resultant force, its moment about the world origin and its power. Ground's
    /// entry is computed like any other and ignored by callers.
    pub fn applied_loads(&self, sol: &Solution) -> Vec<Load> {
        let mut loads = vec![Load::default(); sol.links.len()];
        for term in self.load_terms(sol) {
            let l = &mut loads[term.link];
            match term.action {
                Action::Force {
                    at,
                    velocity,
                    force,
                } => {
                    l.force += force;
                    l.moment += cross(&at, &force);
                    l.power += force.dot(&velocity);
                }
                Action::Couple { moment } => couple(l, moment, sol.links[term.link].omega_rad_s),
            }
        }
        loads
    }

    /// Every applied load at the motion `sol`, in the order weights, springs,
    /// dampers, external forces, torques. A working-stroke force that is off at `sol`
    /// is left out; a spring or damper whose ends meet gives nothing.
    pub fn load_terms(&self, sol: &Solution) -> Vec<LoadTerm> {
        let mut out = Vec::new();
        let force = |link: LinkId, source: LoadSource, point: &PointMotion, f: Vec2| LoadTerm {
            link,
            source,
            action: Action::Force {
                at: point.position,
                velocity: point.velocity,
                force: f,
            },
        };
        let couple = |link: LinkId, source: LoadSource, moment: f64| LoadTerm {
            link,
            source,
            action: Action::Couple { moment },
        };
        if let Some(g) = self.gravity {
            for b in &self.bodies {
                let at = sol.links[b.link].point(&b.centroid);
                out.push(force(b.link, LoadSource::Weight, &at, g * b.mass_kg));
            }
        }
        let link_of = |point: PointId| self.point_links[point];
        for (i, s) in self.springs.iter().enumerate() {
            let (pa, pb) = (&sol.points[s.a], &sol.points[s.b]);
            let d = pa.position - pb.position;
            let len = d.norm();
            if len > 0.0 {
                let pull = d * (s.k * (len - s.free_length_m) / len);
                out.push(force(link_of(s.a), LoadSource::Spring(i), pa, -pull));
                out.push(force(link_of(s.b), LoadSource::Spring(i), pb, pull));
            }
        }
        for (i, d) in self.dampers.iter().enumerate() {
            match *d {
                Damper::Linear { a, b, c } => {
                    let (pa, pb) = (&sol.points[a], &sol.points[b]);
                    let dd = pa.position - pb.position;
                    let len = dd.norm();
                    if len > 0.0 {
                        let u = dd / len;
                        let f = u * (c * u.dot(&(pa.velocity - pb.velocity)));
                        out.push(force(link_of(a), LoadSource::Damper(i), pa, -f));
                        out.push(force(link_of(b), LoadSource::Damper(i), pb, f));
                    }
                }
                Damper::Rotational { a, b, c } => {
                    let t = c * (sol.links[a].omega_rad_s - sol.links[b].omega_rad_s);
                    out.push(couple(a, LoadSource::Damper(i), -t));
                    out.push(couple(b, LoadSource::Damper(i), t));
                }
            }
        }
        for (index, p) in self.point_forces.iter().enumerate() {
            let at = &sol.points[p.point];
            let acts = match p.when {
                ForceWhen::Always => true,
                // Acts while the point moves against the force, as in `reduce`.
                ForceWhen::WorkingStroke => p.force.dot(&at.velocity) < 0.0,
            };
            if acts {
                let source = LoadSource::PointForce {
                    index,
                    point: p.point,
                };
                out.push(force(link_of(p.point), source, at, p.force));
            }
        }
        for (i, &(l, t)) in self.torques.iter().enumerate() {
            out.push(couple(l, LoadSource::Torque(i), t));
        }
        out
    }
}

/// A link's d'Alembert inertia load: the force −m a_G through its centroid and the
/// couple −I α.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InertiaTerm {
    /// The link.
    pub link: LinkId,
    /// Its centroid G, m.
    pub at: Vec2,
    /// −m a_G, N.
    pub force: Vec2,
    /// −I_G α, N·m.
    pub couple: f64,
}

impl ForceModel {
    /// The inertia load of every link with mass, at the motion `sol`.
    pub fn inertia_terms(&self, sol: &Solution) -> Vec<InertiaTerm> {
        self.bodies
            .iter()
            .map(|b| {
                let l = &sol.links[b.link];
                let g = l.point(&b.centroid);
                InertiaTerm {
                    link: b.link,
                    at: g.position,
                    force: -(g.acceleration * b.mass_kg),
                    couple: -b.inertia_kg_m2 * l.alpha_rad_s2,
                }
            })
            .collect()
    }
}
