//! The validated mechanism: SI units, indices instead of names, joints made explicit.

use nalgebra::{UnitComplex, Vector2};

use crate::error::{LinkageError, Result};
use crate::motion::{LinkMotion, SlideMotion, Vec2, perp};
use crate::real::{Real, splat, splat_vec};
use crate::scene::{Branch, ForcesSpec, FreeLength, Models, SceneFile, SolverSpec, Speed};

/// A rigid link.
#[derive(Clone, Debug, PartialEq)]
pub struct Link {
    /// Name from the scene.
    pub name: String,
    /// True for the frame.
    pub is_ground: bool,
    /// The link's points: (index into `Mechanism::points`, link coordinates in m).
    pub points: Vec<(usize, Vec2)>,
    /// Mass, kg, when the scene gives it.
    pub mass_kg: Option<f64>,
    /// Centroid in link coordinates, m.
    pub centroid_m: Option<Vec2>,
    /// Moment of inertia about the centroid, kg·m².
    pub inertia_kg_m2: Option<f64>,
}

impl Link {
    /// Local coordinates of a point on this link, if the link carries it.
    pub fn local(&self, point: usize) -> Option<Vec2> {
        self.points
            .iter()
            .find(|(p, _)| *p == point)
            .map(|(_, v)| *v)
    }
}

/// A named point; it moves with `link` (the first link that lists it).
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// Name from the scene.
    pub name: String,
    /// Link it is computed from.
    pub link: usize,
    /// Coordinates on that link, m.
    pub local: Vec2,
}

/// A revolute joint between links `a` and `b` at a shared point.
#[derive(Clone, Debug, PartialEq)]
pub struct Revolute {
    /// The shared point.
    pub point: usize,
    /// First link.
    pub a: usize,
    /// Joint point in `a`'s coordinates, m.
    pub a_local: Vec2,
    /// Second link.
    pub b: usize,
    /// Joint point in `b`'s coordinates, m.
    pub b_local: Vec2,
}

/// A prismatic joint: `slider_local` on `slider` stays on the guide line of `guide`.
#[derive(Clone, Debug, PartialEq)]
pub struct Prismatic {
    /// Display name, `slider/guide`.
    pub name: String,
    /// Sliding link.
    pub slider: usize,
    /// The slider's point on the line.
    pub point: usize,
    /// That point in slider coordinates, m.
    pub slider_local: Vec2,
    /// Guide link.
    pub guide: usize,
    /// A point of the line in guide coordinates, m.
    pub through_local: Vec2,
    /// Unit direction of the line in guide coordinates.
    pub direction_local: Vec2,
    /// Slider angle minus guide angle, as a rotation.
    pub relative: UnitComplex<f64>,
}

impl Prismatic {
    /// World direction of the guide line.
    pub fn direction<T: Real>(&self, links: &[LinkMotion<T>]) -> Vector2<T> {
        links[self.guide].rotation * splat_vec(&self.direction_local)
    }

    /// Displacement of the slider point along the guide from `through`, with its
    /// first and second time derivatives (relative to the guide, Coriolis removed).
    pub fn motion<T: Real>(&self, links: &[LinkMotion<T>]) -> SlideMotion<T> {
        let guide = &links[self.guide];
        let u = self.direction(links);
        let p = links[self.slider].point(&self.slider_local);
        let on_guide = guide.material_point_at(&p.position);
        let v_rel = p.velocity - on_guide.velocity;
        let a_rel = p.acceleration
            - on_guide.acceleration
            - perp(&v_rel) * (splat::<T>(2.0) * guide.omega_rad_s);
        SlideMotion {
            displacement_m: (p.position - guide.world(&self.through_local)).dot(&u),
            velocity_m_s: v_rel.dot(&u),
            acceleration_m_s2: a_rel.dot(&u),
        }
    }
}

/// The input.
#[derive(Clone, Debug, PartialEq)]
pub struct Driver {
    /// Input link.
    pub link: usize,
    /// Index into `Mechanism::revolutes` of its joint with ground.
    pub pivot: usize,
    /// Input speed, rad/s.
    pub speed_rad_s: f64,
    /// Input angle at t = 0, rad.
    pub start_rad: f64,
}

/// A validated 1-DOF planar mechanism in SI units.
#[derive(Clone, Debug, PartialEq)]
pub struct Mechanism {
    /// Title.
    pub name: String,
    /// Description.
    pub description: String,
    /// Notes for the student.
    pub notes: Vec<String>,
    /// What the scene computes.
    pub models: Models,
    /// Links (ground included).
    pub links: Vec<Link>,
    /// Index of the ground link.
    pub ground: usize,
    /// Named points, in order of first appearance.
    pub points: Vec<Point>,
    /// Revolute joints (from shared point names).
    pub revolutes: Vec<Revolute>,
    /// Prismatic joints.
    pub sliders: Vec<Prismatic>,
    /// The input.
    pub driver: Driver,
    /// Branch per dyad inner point: (point index, branch).
    pub branches: Vec<(usize, Branch)>,
    /// Main output link (time ratio).
    pub output: usize,
    /// Newton starting guesses per link: (origin m, angle rad).
    pub guess: Vec<Option<(Vec2, f64)>>,
    /// Force elements, lengths in m and angles in rad.
    pub forces: ForcesSpec,
    /// Solver settings.
    pub solver: SolverSpec,
    /// Largest point distance from the origin, m: the scale for tolerances.
    pub size_m: f64,
}

fn invalid(msg: impl Into<String>) -> LinkageError {
    LinkageError::SceneInvalid(msg.into())
}

fn finite(name: &str, v: f64) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(LinkageError::InvalidParameter {
            name: name.to_string(),
            value: v,
            valid: "must be a finite number".into(),
        })
    }
}

/// Largest angle a scene may give, rad (about 3200 turns). A double holds angles up to
/// here to 4e-12 rad; far beyond it the reduction to one turn, which every sine and
/// cosine does, loses the angle itself (at 1e16 deg one unit in the last place is
/// over a turn, and a sweep from there is no longer monotonic).
pub const MAX_ANGLE_RAD: f64 = 2.0e4;

/// A scene angle `v` in the scene's unit (`rad_per_unit` radians each), in radians.
fn scene_angle(name: &str, v: f64, rad_per_unit: f64) -> Result<f64> {
    let rad = finite(name, v)? * rad_per_unit;
    if rad.abs() <= MAX_ANGLE_RAD {
        Ok(rad)
    } else {
        let limit = MAX_ANGLE_RAD / rad_per_unit;
        Err(LinkageError::InvalidParameter {
            name: name.to_string(),
            value: v,
            valid: format!(
                "must lie within ±{limit:.6} (the scene's angle unit; about 3200 turns), beyond which a double cannot hold the angle to 1e-11 rad: give it within one turn"
            ),
        })
    }
}

fn positive(name: &str, v: f64) -> Result<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(LinkageError::InvalidParameter {
            name: name.to_string(),
            value: v,
            valid: "must be finite and > 0".into(),
        })
    }
}

impl Mechanism {
    /// Parses and validates scene text.
    pub fn from_ron(text: &str) -> Result<Self> {
        Self::from_scene(&SceneFile::parse(text)?)
    }

    /// Index of a link by name.
    pub fn link_index(&self, name: &str) -> Option<usize> {
        self.links.iter().position(|l| l.name == name)
    }

    /// Index of a point by name.
    pub fn point_index(&self, name: &str) -> Option<usize> {
        self.points.iter().position(|p| p.name == name)
    }

    /// The points that are joints (pins and slider points), each once, ascending.
    pub fn joint_points(&self) -> Vec<usize> {
        let mut joints: Vec<usize> = self
            .revolutes
            .iter()
            .map(|r| r.point)
            .chain(self.sliders.iter().map(|sl| sl.point))
            .collect();
        joints.sort_unstable();
        joints.dedup();
        joints
    }

    /// Moving links (all but ground), in scene order.
    pub fn moving_links(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.links.len()).filter(move |&i| i != self.ground)
    }

    /// The revolute joint (its index in `revolutes`) that pins moving link `link` to
    /// ground, if one does.
    pub fn ground_pivot_of(&self, link: usize) -> Option<usize> {
        let g = self.ground;
        (link != g)
            .then(|| {
                self.revolutes
                    .iter()
                    .position(|r| (r.a == link && r.b == g) || (r.b == link && r.a == g))
            })
            .flatten()
    }

    /// Validates a parsed scene and converts it to SI.
    pub fn from_scene(scene: &SceneFile) -> Result<Self> {
        let len = scene.length_unit.to_metres();
        let ang = scene.angle_unit.to_radians();
        let v2 = |ctx: &str, (x, y): (f64, f64)| -> Result<Vec2> {
            Ok(Vec2::new(
                finite(&format!("{ctx}.x"), x)? * len,
                finite(&format!("{ctx}.y"), y)? * len,
            ))
        };

        let grounds: Vec<_> = scene.links.iter().filter(|l| l.ground).collect();
        if grounds.len() != 1 {
            return Err(invalid(format!(
                "exactly one link must have `ground: true`, found {}",
                grounds.len()
            )));
        }
        let mut links = Vec::with_capacity(scene.links.len());
        let mut points: Vec<Point> = Vec::new();
        let mut on_links: Vec<Vec<(usize, Vec2)>> = Vec::new();
        let mut size_m: f64 = 0.0;
        // The point farthest from its link's origin, which sets `size_m`.
        let mut farthest = (String::new(), String::new());
        for (li, spec) in scene.links.iter().enumerate() {
            if spec.name.is_empty() {
                return Err(invalid(format!("link #{} has an empty name", li + 1)));
            }
            if scene.links[..li].iter().any(|l| l.name == spec.name) {
                return Err(invalid(format!("two links are named `{}`", spec.name)));
            }
            if spec.points.is_empty() {
                return Err(invalid(format!("link `{}` has no points", spec.name)));
            }
            let mut link_points = Vec::with_capacity(spec.points.len());
            for (pname, &xy) in &spec.points {
                let local = v2(&format!("{}.{}", spec.name, pname), xy)?;
                // hypot: a coordinate of 1e300 squared would overflow to infinity.
                let reach = local.x.hypot(local.y);
                if reach > size_m {
                    size_m = reach;
                    farthest = (spec.name.clone(), pname.clone());
                }
                let pi = match points.iter().position(|p| &p.name == pname) {
                    Some(pi) => pi,
                    None => {
                        points.push(Point {
                            name: pname.clone(),
                            link: li,
                            local,
                        });
                        on_links.push(Vec::new());
                        points.len() - 1
                    }
                };
                on_links[pi].push((li, local));
                link_points.push((pi, local));
            }
            if let Some(m) = spec.mass {
                positive(&format!("{}.mass", spec.name), m)?;
            }
            if let Some(j) = spec.inertia {
                positive(&format!("{}.inertia", spec.name), j)?;
            }
            links.push(Link {
                name: spec.name.clone(),
                is_ground: spec.ground,
                points: link_points,
                mass_kg: spec.mass,
                centroid_m: spec
                    .centroid
                    .map(|c| v2(&format!("{}.centroid", spec.name), c))
                    .transpose()?,
                inertia_kg_m2: spec.inertia,
            });
        }
        let ground = links
            .iter()
            .position(|l| l.is_ground)
            .ok_or_else(|| invalid("no ground link"))?;

        let mut revolutes = Vec::new();
        for (pi, users) in on_links.iter().enumerate() {
            let (a, a_local) = users[0];
            for &(b, b_local) in &users[1..] {
                revolutes.push(Revolute {
                    point: pi,
                    a,
                    a_local,
                    b,
                    b_local,
                });
            }
        }

        // Two joints of one link at the same place make that link a point: no length,
        // no angle (a zero-length crank, say).
        for link in &links {
            let joints: Vec<&(usize, Vec2)> = link
                .points
                .iter()
                .filter(|(p, _)| on_links[*p].len() > 1)
                .collect();
            for (n, (pa, a)) in joints.iter().enumerate() {
                for (pb, b) in &joints[n + 1..] {
                    let gap = (a - b).norm();
                    if gap == 0.0 {
                        return Err(invalid(format!(
                            "link `{}` has zero length between its joints `{}` and `{}`",
                            link.name, points[*pa].name, points[*pb].name
                        )));
                    }
                    if gap <= 1e-12 * size_m {
                        // Not zero, but lost beside the largest coordinate: name that.
                        return Err(invalid(format!(
                            "link `{}`: joints `{}` and `{}` are {gap:.3e} m apart, below 1e-12 \
                             of the mechanism's size {size_m:.3e} m, set by point `{}` of link \
                             `{}`; lengths so far apart cannot be solved together (is that point \
                             a typo?)",
                            link.name, points[*pa].name, points[*pb].name, farthest.1, farthest.0
                        )));
                    }
                }
            }
        }

        let link_of = |name: &str, ctx: &str| -> Result<usize> {
            links.iter().position(|l| l.name == name).ok_or_else(|| {
                invalid(format!(
                    "{ctx} names link `{name}`, which does not exist (links: {})",
                    links
                        .iter()
                        .map(|l| l.name.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                ))
            })
        };
        let point_on = |link: usize, name: &str, ctx: &str| -> Result<(usize, Vec2)> {
            let pi = points.iter().position(|p| p.name == name);
            pi.and_then(|pi| links[link].local(pi).map(|v| (pi, v)))
                .ok_or_else(|| {
                    invalid(format!(
                        "{ctx}: point `{name}` is not on link `{}`",
                        links[link].name
                    ))
                })
        };

        let mut sliders = Vec::new();
        for s in &scene.sliders {
            let ctx = format!("slider `{}` on `{}`", s.slider, s.guide);
            let slider = link_of(&s.slider, &ctx)?;
            let guide = link_of(&s.guide, &ctx)?;
            if slider == guide {
                return Err(invalid(format!(
                    "{ctx}: slider and guide are the same link"
                )));
            }
            let (point, slider_local) = point_on(slider, &s.point, &ctx)?;
            let (_, through_local) = point_on(guide, &s.through, &ctx)?;
            let angle = scene_angle(&format!("{ctx}.angle"), s.angle, ang)?;
            let rel = scene_angle(&format!("{ctx}.relative_angle"), s.relative_angle, ang)?;
            sliders.push(Prismatic {
                name: format!("{}/{}", s.slider, s.guide),
                slider,
                point,
                slider_local,
                guide,
                through_local,
                direction_local: Vec2::new(angle.cos(), angle.sin()),
                relative: UnitComplex::new(rel),
            });
        }

        let moving = links.len() - 1;
        let mobility = 3 * moving as i64 - 2 * (revolutes.len() + sliders.len()) as i64;
        if mobility != 1 {
            // A misspelt point name is the usual cause: it leaves a joint unmade, its
            // point alone on one link. Name those, so the typo can be found.
            let lone: Vec<String> = on_links
                .iter()
                .enumerate()
                .filter(|(_, users)| users.len() == 1)
                .map(|(p, users)| format!("`{}` (on `{}`)", points[p].name, links[users[0].0].name))
                .collect();
            // With none alone, list the joints that were made, to compare with the drawing.
            let made: Vec<String> = revolutes
                .iter()
                .map(|r| {
                    let (a, b) = (&links[r.a].name, &links[r.b].name);
                    format!("`{}` ({a}-{b})", points[r.point].name)
                })
                .chain(
                    sliders
                        .iter()
                        .map(|s| format!("slider `{}`", links[s.slider].name)),
                )
                .collect();
            let hint = if lone.is_empty() {
                format!("none; the joints made are {}", made.join(", "))
            } else {
                lone.join(", ")
            };
            return Err(invalid(format!(
                "the chain has mobility {mobility} (3 x {moving} moving links - 2 x {} joints); \
                 a single-input mechanism needs exactly 1. Joints are made by a point name \
                 shared between links; these points are on one link only: {hint}",
                revolutes.len() + sliders.len(),
            )));
        }

        let d = &scene.driver;
        let driver_link = link_of(&d.link, "driver")?;
        if driver_link == ground {
            return Err(invalid("the driver cannot be the ground link"));
        }
        let pivot = revolutes
            .iter()
            .position(|r| {
                (r.a == ground && r.b == driver_link) || (r.b == ground && r.a == driver_link)
            })
            .ok_or_else(|| {
                invalid(format!(
                    "driver link `{}` shares no point with ground, so it cannot be a crank",
                    d.link
                ))
            })?;
        let speed_rad_s = match d.speed {
            Speed::Rpm(n) => finite("driver.speed", n)? * std::f64::consts::TAU / 60.0,
            Speed::RadPerSecond(w) => finite("driver.speed", w)?,
        };
        let driver = Driver {
            link: driver_link,
            pivot,
            speed_rad_s,
            start_rad: scene_angle("driver.start", d.start, ang)?,
        };

        let mut branches = Vec::new();
        for (name, b) in &scene.branches {
            let pi = points
                .iter()
                .position(|p| &p.name == name)
                .ok_or_else(|| invalid(format!("branch key `{name}` is not a point name")))?;
            if let Branch::Left(f, t) | Branch::Right(f, t) = b {
                for n in [f, t] {
                    if !points.iter().any(|p| &p.name == n) {
                        return Err(invalid(format!(
                            "branch of `{name}` names unknown point `{n}`"
                        )));
                    }
                }
            }
            branches.push((pi, b.clone()));
        }

        let output = match &scene.output {
            Some(name) => link_of(name, "output")?,
            None => links.len() - 1,
        };

        let mut guess = vec![None; links.len()];
        for (name, &(x, y, a)) in &scene.guess {
            let li = link_of(name, "guess")?;
            guess[li] = Some((
                v2(&format!("guess.{name}"), (x, y))?,
                scene_angle("guess angle", a, ang)?,
            ));
        }

        let forces = convert_forces(&scene.forces, len, ang, &links, &points)?;
        if !(scene.solver.tolerance > 0.0 && scene.solver.tolerance.is_finite()) {
            return Err(LinkageError::InvalidParameter {
                name: "solver.tolerance".into(),
                value: scene.solver.tolerance,
                valid: "must be finite and > 0 (typical 1e-13)".into(),
            });
        }
        if size_m <= 0.0 {
            return Err(invalid(
                "all points are at the origin: the mechanism has no size",
            ));
        }

        Ok(Self {
            name: scene.name.clone(),
            description: scene.description.clone(),
            notes: scene.notes.clone(),
            models: scene.models,
            links,
            ground,
            points,
            revolutes,
            sliders,
            driver,
            branches,
            output,
            guess,
            forces,
            solver: scene.solver,
            size_m,
        })
    }

    /// The scene's branch for the dyad whose inner joint is `point`.
    pub fn branch_for(&self, point: usize) -> Option<&Branch> {
        self.branches
            .iter()
            .find(|(p, _)| *p == point)
            .map(|(_, b)| b)
    }

    /// Replaces (or adds) the branch of the dyad whose inner joint is named `point`.
    pub fn set_branch(&mut self, point: &str, branch: Branch) -> Result<()> {
        let pi = self
            .point_index(point)
            .ok_or_else(|| invalid(format!("no point named `{point}` to set a branch on")))?;
        match self.branches.iter_mut().find(|(p, _)| *p == pi) {
            Some(entry) => entry.1 = branch,
            None => self.branches.push((pi, branch)),
        }
        Ok(())
    }
}

fn convert_forces(
    f: &ForcesSpec,
    len: f64,
    ang: f64,
    links: &[Link],
    points: &[Point],
) -> Result<ForcesSpec> {
    let has_point = |n: &str, ctx: &str| -> Result<()> {
        if points.iter().any(|p| p.name == n) {
            Ok(())
        } else {
            Err(invalid(format!("{ctx} names unknown point `{n}`")))
        }
    };
    let has_link = |n: &str, ctx: &str| -> Result<()> {
        if links.iter().any(|l| l.name == n) {
            Ok(())
        } else {
            Err(invalid(format!("{ctx} names unknown link `{n}`")))
        }
    };
    let mut out = f.clone();
    for s in &mut out.springs {
        has_point(&s.a, "spring")?;
        has_point(&s.b, "spring")?;
        positive(&format!("spring {}-{} k_n_per_m", s.a, s.b), s.k_n_per_m)?;
        if let FreeLength::Length(l) = &mut s.free_length {
            *l = finite("spring free_length", *l)? * len;
            if *l < 0.0 {
                return Err(LinkageError::InvalidParameter {
                    name: format!("spring {}-{} free_length", s.a, s.b),
                    value: *l,
                    valid: "must be >= 0".into(),
                });
            }
        }
    }
    for d in &out.dampers {
        match d {
            crate::scene::DamperSpec::Linear { a, b, c_n_s_per_m } => {
                has_point(a, "damper")?;
                has_point(b, "damper")?;
                positive("damper c_n_s_per_m", *c_n_s_per_m)?;
            }
            crate::scene::DamperSpec::Rotational {
                link_a,
                link_b,
                c_n_m_s,
            } => {
                has_link(link_a, "damper")?;
                has_link(link_b, "damper")?;
                positive("damper c_n_m_s", *c_n_m_s)?;
            }
        }
    }
    for pf in &out.point_forces {
        has_point(&pf.point, "point force")?;
        finite("point force x", pf.force_n.0)?;
        finite("point force y", pf.force_n.1)?;
    }
    for t in &out.torques {
        has_link(&t.link, "torque")?;
        finite("torque", t.torque_n_m)?;
    }
    for s in &mut out.stops {
        has_link(&s.link, "stop")?;
        s.angle = scene_angle("stop angle", s.angle, ang)?;
    }
    if let Some((gx, gy)) = out.gravity {
        finite("gravity x", gx)?;
        finite("gravity y", gy)?;
    }
    Ok(out)
}
