//! A scene file validated and converted to a [`Mechanism`], section by section: the
//! links and their points, the joints they make, the sliders, the mobility, the
//! driver, the branches, the guesses, the forces and the solver's settings. Each
//! section names what it refuses and, where one exists, the valid range.

use nalgebra::UnitComplex;

use crate::error::{LinkageError, Result};
use crate::model::{Driver, Link, MAX_ANGLE_RAD, Mechanism, Point, Prismatic, Revolute};
use crate::motion::Vec2;
use crate::scene::{Branch, ForcesSpec, FreeLength, SceneFile, Speed};
use crate::scene_problem::{LonePoint, MadeJoint, SceneProblem};

/// The links and their points, in SI, before the joints are made.
struct Bodies {
    links: Vec<Link>,
    points: Vec<Point>,
    /// For every point, the links that carry it and where on each.
    on_links: Vec<Vec<(usize, Vec2)>>,
    /// The largest distance of a point from its link's origin, m.
    size_m: f64,
    /// The link and point that set `size_m`.
    farthest: (String, String),
}

/// The scene's lengths and angles in SI.
#[derive(Clone, Copy)]
struct Units {
    /// Metres per scene length unit.
    len: f64,
    /// Radians per scene angle unit.
    ang: f64,
}

impl Units {
    /// A scene point named `ctx`, in metres.
    fn point(self, ctx: &str, (x, y): (f64, f64)) -> Result<Vec2> {
        Ok(Vec2::new(
            finite(&format!("{ctx}.x"), x)? * self.len,
            finite(&format!("{ctx}.y"), y)? * self.len,
        ))
    }
}

impl Mechanism {
    /// Validates a parsed scene and converts it to SI.
    pub fn from_scene(scene: &SceneFile) -> Result<Self> {
        let units = Units {
            len: scene.length_unit.to_metres(),
            ang: scene.angle_unit.to_radians(),
        };
        let bodies = bodies(scene, units)?;
        let revolutes = revolutes(&bodies.on_links);
        check_joint_gaps(&bodies)?;
        let names = Names {
            links: &bodies.links,
            points: &bodies.points,
        };
        let sliders = sliders(scene, &names, units)?;
        check_mobility(&bodies, &revolutes, &sliders)?;
        let ground = bodies
            .links
            .iter()
            .position(|l| l.is_ground)
            .ok_or(invalid(SceneProblem::GroundCount { found: 0 }))?;
        let driver = driver(scene, &names, ground, &revolutes, units)?;
        let branches = branches(scene, &bodies.points)?;
        let output = match &scene.output {
            Some(name) => names.link("output", name)?,
            None => bodies.links.len() - 1,
        };
        let guess = guesses(scene, &names, units)?;
        let forces = convert_forces(
            &scene.forces,
            units.len,
            units.ang,
            &bodies.links,
            &bodies.points,
        )?;
        if !(scene.solver.tolerance > 0.0 && scene.solver.tolerance.is_finite()) {
            return Err(LinkageError::InvalidParameter {
                name: "solver.tolerance".into(),
                value: scene.solver.tolerance,
                valid: "must be finite and > 0 (typical 1e-13)".into(),
            });
        }
        if bodies.size_m <= 0.0 {
            return Err(invalid(SceneProblem::NoSize));
        }
        Ok(Self {
            name: scene.name.clone(),
            description: scene.description.clone(),
            notes: scene.notes.clone(),
            models: scene.models,
            links: bodies.links,
            ground,
            points: bodies.points,
            revolutes,
            sliders,
            driver,
            branches,
            output,
            guess,
            forces,
            solver: scene.solver,
            size_m: bodies.size_m,
        })
    }
}

/// The links with their points (one ground, names unique and not empty, each with a
/// point), masses and inertias.
fn bodies(scene: &SceneFile, units: Units) -> Result<Bodies> {
    let grounds = scene.links.iter().filter(|l| l.ground).count();
    if grounds != 1 {
        return Err(invalid(SceneProblem::GroundCount { found: grounds }));
    }
    let mut b = Bodies {
        links: Vec::with_capacity(scene.links.len()),
        points: Vec::new(),
        on_links: Vec::new(),
        size_m: 0.0,
        farthest: (String::new(), String::new()),
    };
    for (li, spec) in scene.links.iter().enumerate() {
        if spec.name.is_empty() {
            return Err(invalid(SceneProblem::UnnamedLink { number: li + 1 }));
        }
        if scene.links[..li].iter().any(|l| l.name == spec.name) {
            return Err(invalid(SceneProblem::DuplicateLink {
                link: spec.name.clone(),
            }));
        }
        if spec.points.is_empty() {
            return Err(invalid(SceneProblem::LinkWithoutPoints {
                link: spec.name.clone(),
            }));
        }
        let mut link_points = Vec::with_capacity(spec.points.len());
        for (pname, &xy) in &spec.points {
            let local = units.point(&format!("{}.{}", spec.name, pname), xy)?;
            // hypot: a coordinate of 1e300 squared would overflow to infinity.
            let reach = local.x.hypot(local.y);
            if reach > b.size_m {
                b.size_m = reach;
                b.farthest = (spec.name.clone(), pname.clone());
            }
            let pi = match b.points.iter().position(|p| &p.name == pname) {
                Some(pi) => pi,
                None => {
                    b.points.push(Point {
                        name: pname.clone(),
                        link: li,
                        local,
                    });
                    b.on_links.push(Vec::new());
                    b.points.len() - 1
                }
            };
            b.on_links[pi].push((li, local));
            link_points.push((pi, local));
        }
        if let Some(m) = spec.mass {
            positive(&format!("{}.mass", spec.name), m)?;
        }
        if let Some(j) = spec.inertia {
            positive(&format!("{}.inertia", spec.name), j)?;
        }
        b.links.push(Link {
            name: spec.name.clone(),
            is_ground: spec.ground,
            points: link_points,
            mass_kg: spec.mass,
            centroid_m: spec
                .centroid
                .map(|c| units.point(&format!("{}.centroid", spec.name), c))
                .transpose()?,
            inertia_kg_m2: spec.inertia,
        });
    }
    Ok(b)
}

/// A revolute joint for every further link that carries a point.
fn revolutes(on_links: &[Vec<(usize, Vec2)>]) -> Vec<Revolute> {
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
    revolutes
}

/// Two joints of one link at the same place make that link a point: no length, no
/// angle (a zero-length crank, say).
fn check_joint_gaps(b: &Bodies) -> Result<()> {
    for link in &b.links {
        let joints: Vec<&(usize, Vec2)> = link
            .points
            .iter()
            .filter(|(p, _)| b.on_links[*p].len() > 1)
            .collect();
        for (n, (pa, pos_a)) in joints.iter().enumerate() {
            for (pb, pos_b) in &joints[n + 1..] {
                let gap = (pos_a - pos_b).norm();
                let (name_a, name_b) = (&b.points[*pa].name, &b.points[*pb].name);
                if gap == 0.0 {
                    return Err(invalid(SceneProblem::ZeroLength {
                        link: link.name.clone(),
                        a: name_a.to_string(),
                        b: name_b.to_string(),
                    }));
                }
                if gap <= 1e-12 * b.size_m {
                    // Not zero, but lost beside the largest coordinate: name that.
                    return Err(invalid(SceneProblem::LengthLost {
                        link: link.name.clone(),
                        a: name_a.to_string(),
                        b: name_b.to_string(),
                        gap_m: gap,
                        size_m: b.size_m,
                        farthest_point: b.farthest.1.clone(),
                        farthest_link: b.farthest.0.clone(),
                    }));
                }
            }
        }
    }
    Ok(())
}

/// The links and points by name, for the sections that name them.
struct Names<'a> {
    links: &'a [Link],
    points: &'a [Point],
}

impl Names<'_> {
    /// The link named `name`, which `ctx` names.
    fn link(&self, ctx: &str, name: &str) -> Result<usize> {
        self.links
            .iter()
            .position(|l| l.name == name)
            .ok_or_else(|| {
                invalid(SceneProblem::UnknownLink {
                    context: ctx.to_string(),
                    name: name.to_string(),
                    known: self.links.iter().map(|l| l.name.clone()).collect(),
                })
            })
    }

    /// The point named `name` on `link`, and where on it.
    fn point_on(&self, ctx: &str, link: usize, name: &str) -> Result<(usize, Vec2)> {
        let pi = self.points.iter().position(|p| p.name == name);
        pi.and_then(|pi| self.links[link].local(pi).map(|v| (pi, v)))
            .ok_or_else(|| {
                invalid(SceneProblem::PointNotOnLink {
                    context: ctx.to_string(),
                    point: name.to_string(),
                    link: self.links[link].name.clone(),
                })
            })
    }
}

/// The prismatic joints.
fn sliders(scene: &SceneFile, names: &Names<'_>, units: Units) -> Result<Vec<Prismatic>> {
    let mut sliders = Vec::new();
    for s in &scene.sliders {
        let ctx = format!("slider `{}` on `{}`", s.slider, s.guide);
        let slider = names.link(&ctx, &s.slider)?;
        let guide = names.link(&ctx, &s.guide)?;
        if slider == guide {
            return Err(invalid(SceneProblem::SliderOnItsGuide { context: ctx }));
        }
        let (point, slider_local) = names.point_on(&ctx, slider, &s.point)?;
        let (_, through_local) = names.point_on(&ctx, guide, &s.through)?;
        let angle = scene_angle(&format!("{ctx}.angle"), s.angle, units.ang)?;
        let rel = scene_angle(
            &format!("{ctx}.relative_angle"),
            s.relative_angle,
            units.ang,
        )?;
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
    Ok(sliders)
}

/// One degree of freedom, or the joints that were (not) made, named.
fn check_mobility(b: &Bodies, revolutes: &[Revolute], sliders: &[Prismatic]) -> Result<()> {
    let moving = b.links.len() - 1;
    let mobility = 3 * moving as i64 - 2 * (revolutes.len() + sliders.len()) as i64;
    if mobility == 1 {
        return Ok(());
    }
    // A misspelt point name is the usual cause: it leaves a joint unmade, its point
    // alone on one link. Name those, so the typo can be found.
    let lone = b
        .on_links
        .iter()
        .enumerate()
        .filter(|(_, users)| users.len() == 1)
        .map(|(p, users)| LonePoint {
            point: b.points[p].name.clone(),
            link: b.links[users[0].0].name.clone(),
        })
        .collect();
    // With none alone, list the joints that were made, to compare with the drawing.
    let made = revolutes
        .iter()
        .map(|r| MadeJoint::Pin {
            point: b.points[r.point].name.clone(),
            a: b.links[r.a].name.clone(),
            b: b.links[r.b].name.clone(),
        })
        .chain(sliders.iter().map(|s| MadeJoint::Slider {
            link: b.links[s.slider].name.clone(),
        }))
        .collect();
    Err(invalid(SceneProblem::Mobility {
        mobility,
        moving,
        joints: revolutes.len() + sliders.len(),
        lone,
        made,
    }))
}

/// The driver: a link other than ground, pinned to it, with its speed and start.
fn driver(
    scene: &SceneFile,
    names: &Names<'_>,
    ground: usize,
    revolutes: &[Revolute],
    units: Units,
) -> Result<Driver> {
    let d = &scene.driver;
    let driver_link = names.link("driver", &d.link)?;
    if driver_link == ground {
        return Err(invalid(SceneProblem::DriverIsGround));
    }
    let pivot = revolutes
        .iter()
        .position(|r| {
            (r.a == ground && r.b == driver_link) || (r.b == ground && r.a == driver_link)
        })
        .ok_or_else(|| {
            invalid(SceneProblem::DriverNotOnGround {
                link: d.link.clone(),
            })
        })?;
    let speed_rad_s = match d.speed {
        Speed::Rpm(n) => finite("driver.speed", n)? * std::f64::consts::TAU / 60.0,
        Speed::RadPerSecond(w) => finite("driver.speed", w)?,
    };
    Ok(Driver {
        link: driver_link,
        pivot,
        speed_rad_s,
        start_rad: scene_angle("driver.start", d.start, units.ang)?,
    })
}

/// The assembly branches, each on a point the scene has and naming points it has.
fn branches(scene: &SceneFile, points: &[Point]) -> Result<Vec<(usize, Branch)>> {
    let mut branches = Vec::new();
    for (name, b) in &scene.branches {
        let pi = points
            .iter()
            .position(|p| &p.name == name)
            .ok_or_else(|| invalid(SceneProblem::UnknownBranchKey { name: name.clone() }))?;
        if let Branch::Left(f, t) | Branch::Right(f, t) = b {
            for n in [f, t] {
                if !points.iter().any(|p| &p.name == n) {
                    return Err(invalid(SceneProblem::BranchNamesUnknownPoint {
                        of: name.clone(),
                        name: n.clone(),
                    }));
                }
            }
        }
        branches.push((pi, b.clone()));
    }
    Ok(branches)
}

/// The starting guesses of Newton, per link: its origin and angle.
fn guesses(scene: &SceneFile, names: &Names<'_>, units: Units) -> Result<Vec<Option<(Vec2, f64)>>> {
    let mut guess = vec![None; names.links.len()];
    for (name, &(x, y, a)) in &scene.guess {
        let li = names.link("guess", name)?;
        guess[li] = Some((
            units.point(&format!("guess.{name}"), (x, y))?,
            scene_angle("guess angle", a, units.ang)?,
        ));
    }
    Ok(guess)
}

fn invalid(problem: SceneProblem) -> LinkageError {
    LinkageError::from(problem)
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
            Err(invalid(SceneProblem::ForceNamesUnknownPoint {
                element: ctx.to_string(),
                name: n.to_string(),
            }))
        }
    };
    let has_link = |n: &str, ctx: &str| -> Result<()> {
        if links.iter().any(|l| l.name == n) {
            Ok(())
        } else {
            Err(invalid(SceneProblem::ForceNamesUnknownLink {
                element: ctx.to_string(),
                name: n.to_string(),
            }))
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
