//! Force elements and the reduction to the input coordinate.

use crate::error::{LinkageError, Result};
use crate::ids::{LinkId, PointId};
use crate::model::SceneProblem;
use crate::model::{Drive, Mechanism};
use crate::motion::{Solution, Vec2, cross};
use crate::scene::{DamperSpec, ForceWhen, FreeLength, Models};
use crate::solve::Kinematics;

/// Mass data of one moving link, SI.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Body {
    pub(super) link: LinkId,
    pub(super) mass_kg: f64,
    pub(super) centroid: Vec2,
    pub(super) inertia_kg_m2: f64,
}

#[derive(Clone, Debug, PartialEq)]
pub(super) struct Spring {
    pub(super) a: PointId,
    pub(super) b: PointId,
    pub(super) k: f64,
    pub(super) free_length_m: f64,
}

#[derive(Clone, Debug, PartialEq)]
pub(super) enum Damper {
    Linear { a: PointId, b: PointId, c: f64 },
    Rotational { a: LinkId, b: LinkId, c: f64 },
}

#[derive(Clone, Debug, PartialEq)]
pub(super) struct PointForce {
    pub(super) point: PointId,
    pub(super) force: Vec2,
    pub(super) when: ForceWhen,
}

/// The reduced model at one position: J, dJ/dq and the generalized forces, split so
/// that the energy balance can be checked.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Reduced {
    /// Equivalent inertia J(q), kg·m² (per rad² of the input).
    pub j: f64,
    /// dJ/dq.
    pub dj_dq: f64,
    /// Generalized force from conservative elements (gravity, springs, constant
    /// always-on forces), N·m.
    pub m_conservative: f64,
    /// Generalized force from dampers (depends on q̇), N·m.
    pub m_damping: f64,
    /// Generalized force from torques and stroke-dependent forces, N·m.
    pub m_other: f64,
}

impl Reduced {
    /// Total equivalent moment M(q, q̇, t).
    pub fn moment(&self) -> f64 {
        self.m_conservative + self.m_damping + self.m_other
    }

    /// The non-conservative part of M (dampers, torques, stroke forces), N·m.
    pub fn m_nonconservative(&self) -> f64 {
        self.m_damping + self.m_other
    }

    /// q̈ from J q̈ + ½ J' q̇² = M.
    pub fn acceleration(&self, q_dot: f64) -> f64 {
        (self.moment() - 0.5 * self.dj_dq * q_dot * q_dot) / self.j
    }
}

/// Energy terms at one state, J.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct EnergyTerms {
    /// Kinetic energy ½ J q̇².
    pub kinetic: f64,
    /// Gravity potential.
    pub gravity: f64,
    /// Spring potential.
    pub spring: f64,
    /// Potential of constant always-on point forces (−F·r).
    pub forces: f64,
}

impl EnergyTerms {
    /// Kinetic plus potential.
    pub fn total(&self) -> f64 {
        self.kinetic + self.gravity + self.spring + self.forces
    }
}

/// A load on one link: resultant force, its moment about the world origin, its power.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Load {
    /// Resultant force, N.
    pub force: Vec2,
    /// Moment about the world origin (couples included), N·m.
    pub moment: f64,
    /// Power at the current motion, W.
    pub power: f64,
}

/// Adds a couple `t` to a link turning at `omega`.
pub(super) fn couple(load: &mut Load, t: f64, omega: f64) {
    load.moment += t;
    load.power += t * omega;
}

/// The force elements a scene declares, resolved to indices and SI units.
#[derive(Clone, Debug, PartialEq)]
pub struct ForceModel {
    pub(super) bodies: Vec<Body>,
    pub(super) gravity: Option<Vec2>,
    pub(super) springs: Vec<Spring>,
    pub(super) dampers: Vec<Damper>,
    pub(super) point_forces: Vec<PointForce>,
    pub(super) torques: Vec<(LinkId, f64)>,
    /// The link each point is fixed on.
    pub(super) point_links: Vec<LinkId>,
    /// The motor, gear and flywheel on the driver link, if any.
    drive: Option<(LinkId, Drive)>,
}

fn missing(link: &str, field: &'static str) -> LinkageError {
    LinkageError::from(SceneProblem::MissingInertia {
        link: link.to_string(),
        field,
    })
}

/// Every moving link's body. A `Dynamics` scene must give each its mass, centroid
/// and inertia; other scenes use what they give (absent = massless).
fn bodies(m: &Mechanism) -> Result<Vec<Body>> {
    let strict = m.models == Models::Dynamics;
    let mut bodies = Vec::new();
    for l in m.moving_links() {
        let link = &m.links[l];
        match (link.mass_kg, link.centroid_m, link.inertia_kg_m2) {
            (Some(mass_kg), Some(centroid), Some(inertia_kg_m2)) => bodies.push(Body {
                link: l,
                mass_kg,
                centroid,
                inertia_kg_m2,
            }),
            (None, _, _) if strict => return Err(missing(&link.name, "mass")),
            (_, None, _) if strict => return Err(missing(&link.name, "centroid")),
            (_, _, None) if strict => return Err(missing(&link.name, "inertia")),
            (Some(mass_kg), centroid, inertia) => bodies.push(Body {
                link: l,
                mass_kg,
                centroid: centroid.unwrap_or_default(),
                inertia_kg_m2: inertia.unwrap_or(0.0),
            }),
            (None, _, _) => {}
        }
    }
    Ok(bodies)
}

/// The point a force element names.
fn point_named(m: &Mechanism, name: &str) -> Result<PointId> {
    m.point_index(name).ok_or_else(|| {
        LinkageError::from(SceneProblem::ForceNamesUnknownPoint {
            element: "a force element".into(),
            name: name.to_string(),
        })
    })
}

/// The link a force element names.
fn link_named(m: &Mechanism, name: &str) -> Result<LinkId> {
    m.link_index(name).ok_or_else(|| {
        LinkageError::from(SceneProblem::ForceNamesUnknownLink {
            element: "a force element".into(),
            name: name.to_string(),
        })
    })
}

/// The springs, a free length "unstretched at start" measured in `start`.
fn springs(m: &Mechanism, start: &Solution) -> Result<Vec<Spring>> {
    let mut springs = Vec::new();
    for s in &m.forces.springs {
        let (a, b) = (point_named(m, &s.a)?, point_named(m, &s.b)?);
        let free_length_m = match s.free_length {
            FreeLength::Length(l) => l,
            FreeLength::UnstretchedAtStart => {
                (start.points[a].position - start.points[b].position).norm()
            }
        };
        springs.push(Spring {
            a,
            b,
            k: s.k_n_per_m,
            free_length_m,
        });
    }
    Ok(springs)
}

/// The dampers, between two points or two links.
fn dampers(m: &Mechanism) -> Result<Vec<Damper>> {
    let mut dampers = Vec::new();
    for d in &m.forces.dampers {
        dampers.push(match d {
            DamperSpec::Linear { a, b, c_n_s_per_m } => Damper::Linear {
                a: point_named(m, a)?,
                b: point_named(m, b)?,
                c: *c_n_s_per_m,
            },
            DamperSpec::Rotational {
                link_a,
                link_b,
                c_n_m_s,
            } => Damper::Rotational {
                a: link_named(m, link_a)?,
                b: link_named(m, link_b)?,
                c: *c_n_m_s,
            },
        });
    }
    Ok(dampers)
}

impl ForceModel {
    /// Builds the model; `start` is the solution at the start position (for springs
    /// unstretched there). A `Dynamics` scene must give every moving link its mass,
    /// centroid and inertia; other scenes use what they give (absent = massless).
    pub fn new(m: &Mechanism, start: &Solution) -> Result<Self> {
        let bodies = bodies(m)?;
        let springs = springs(m, start)?;
        let dampers = dampers(m)?;
        let f = &m.forces;
        let mut point_forces = Vec::new();
        for p in &f.point_forces {
            point_forces.push(PointForce {
                point: point_named(m, &p.point)?,
                force: Vec2::new(p.force_n.0, p.force_n.1),
                when: p.when,
            });
        }
        let mut torques = Vec::new();
        for t in &f.torques {
            torques.push((link_named(m, &t.link)?, t.torque_n_m));
        }
        Ok(Self {
            bodies,
            gravity: f.gravity.map(|(x, y)| Vec2::new(x, y)),
            springs,
            dampers,
            point_forces,
            torques,
            point_links: m.points.iter().map(|p| p.link).collect(),
            drive: m.drive.clone().map(|d| (m.driver.link, d)),
        })
    }

    /// J, dJ/dq and the equivalent moments at the position of `unit`, a solution at
    /// unit input speed (its velocities are velocity ratios), for input rate `q_dot`.
    pub fn reduce(&self, unit: &Solution, q_dot: f64) -> Reduced {
        let mut r = Reduced::default();
        for b in &self.bodies {
            let l = &unit.links[b.link];
            let s = l.point(&b.centroid);
            r.j += b.mass_kg * s.velocity.norm_squared()
                + b.inertia_kg_m2 * l.omega_rad_s * l.omega_rad_s;
            r.dj_dq += 2.0
                * (b.mass_kg * s.velocity.dot(&s.acceleration)
                    + b.inertia_kg_m2 * l.omega_rad_s * l.alpha_rad_s2);
            if let Some(g) = self.gravity {
                r.m_conservative += b.mass_kg * g.dot(&s.velocity);
            }
        }
        for s in &self.springs {
            let (pa, pb) = (&unit.points[s.a], &unit.points[s.b]);
            let d = pa.position - pb.position;
            let len = d.norm();
            if len > 0.0 {
                // Tension k(L − L0) pulls the ends together: power −T·dL/dt.
                r.m_conservative -=
                    s.k * (len - s.free_length_m) * d.dot(&(pa.velocity - pb.velocity)) / len;
            }
        }
        for d in &self.dampers {
            let rate = match *d {
                Damper::Linear { a, b, .. } => {
                    let (pa, pb) = (&unit.points[a], &unit.points[b]);
                    let dd = pa.position - pb.position;
                    let len = dd.norm();
                    if len > 0.0 {
                        dd.dot(&(pa.velocity - pb.velocity)) / len
                    } else {
                        0.0
                    }
                }
                Damper::Rotational { a, b, .. } => {
                    unit.links[a].omega_rad_s - unit.links[b].omega_rad_s
                }
            };
            let c = match *d {
                Damper::Linear { c, .. } | Damper::Rotational { c, .. } => c,
            };
            r.m_damping -= c * rate * rate * q_dot;
        }
        for p in &self.point_forces {
            let ratio = p.force.dot(&unit.points[p.point].velocity);
            match p.when {
                ForceWhen::Always => r.m_conservative += ratio,
                // Acts while the point moves against the force (the force does negative work).
                ForceWhen::WorkingStroke => {
                    if ratio * q_dot < 0.0 {
                        r.m_other += ratio;
                    }
                }
            }
        }
        for &(l, t) in &self.torques {
            r.m_other += t * unit.links[l].omega_rad_s;
        }
        if let Some((crank, drive)) = &self.drive {
            // The rotor and flywheel turn with the crank: J grows by their inertia at
            // the crank times the crank's rate squared; the motor's torque there
            // depends on the crank's real speed.
            let c = &unit.links[*crank];
            let j = drive.inertia_at_crank_kg_m2;
            r.j += j * c.omega_rad_s * c.omega_rad_s;
            r.dj_dq += 2.0 * j * c.omega_rad_s * c.alpha_rad_s2;
            r.m_other += drive.torque_at_crank(c.omega_rad_s * q_dot) * c.omega_rad_s;
        }
        r
    }

    /// Potential energies and kinetic energy at the position of `unit` for rate `q_dot`.
    pub fn energy(&self, unit: &Solution, j: f64, q_dot: f64) -> EnergyTerms {
        let mut e = EnergyTerms {
            kinetic: 0.5 * j * q_dot * q_dot,
            ..Default::default()
        };
        if let Some(g) = self.gravity {
            for b in &self.bodies {
                e.gravity -= b.mass_kg * g.dot(&unit.links[b.link].world(&b.centroid));
            }
        }
        for s in &self.springs {
            let len = (unit.points[s.a].position - unit.points[s.b].position).norm();
            e.spring += 0.5 * s.k * (len - s.free_length_m).powi(2);
        }
        for p in &self.point_forces {
            if p.when == ForceWhen::Always {
                e.forces -= p.force.dot(&unit.points[p.point].position);
            }
        }
        e
    }

    /// Inertia loads m·a_G and the rate of angular momentum about the world origin
    /// (I α + r_G × m a_G) per link, and the rate of kinetic energy of each link.
    pub fn inertia_loads(&self, sol: &Solution) -> Vec<Load> {
        let mut loads = vec![Load::default(); sol.links.len()];
        for b in &self.bodies {
            let l = &sol.links[b.link];
            let g = l.point(&b.centroid);
            let ma = g.acceleration * b.mass_kg;
            loads[b.link] = Load {
                force: ma,
                moment: b.inertia_kg_m2 * l.alpha_rad_s2 + cross(&g.position, &ma),
                power: ma.dot(&g.velocity) + b.inertia_kg_m2 * l.alpha_rad_s2 * l.omega_rad_s,
            };
        }
        loads
    }

    /// True when the scene has no mass and no drive inertia (nothing to integrate).
    pub fn is_massless(&self) -> bool {
        self.bodies.is_empty()
            && self
                .drive
                .as_ref()
                .is_none_or(|(_, d)| d.inertia_at_crank_kg_m2 == 0.0)
    }

    /// The power ratios (F·v per unit input rate, N·m) of the forces that act on the
    /// working stroke only: where one changes sign such a force switches on or off,
    /// and the load moment has a kink or a step there.
    pub fn switching_ratios(&self, unit: &Solution) -> Vec<f64> {
        self.point_forces
            .iter()
            .filter(|p| p.when == ForceWhen::WorkingStroke)
            .map(|p| p.force.dot(&unit.points[p.point].velocity))
            .collect()
    }
}

/// Solves the kinematics at `q` with unit input speed (velocity ratios).
pub(crate) fn unit_solution(k: &mut Kinematics, q: f64, out: &mut Solution) -> Result<()> {
    k.solve_into(q, 1.0, out)
}
