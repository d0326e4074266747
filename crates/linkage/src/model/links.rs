//! The links and their points, in SI, before the joints are made: one ground, names
//! unique and not empty, each link with a point, no two joints of a link at one place.

use super::units::{Units, invalid, positive_named};
use crate::error::Result;
use crate::error::SceneProblem;
use crate::model::{Link, LinkId, Point, PointId};
use crate::motion::Vec2;
use crate::scene::SceneFile;

/// The links and their points, in SI, before the joints are made.
pub(super) struct Bodies {
    pub(super) links: Vec<Link>,
    pub(super) points: Vec<Point>,
    /// For every point, the links that carry it and where on each.
    pub(super) on_links: Vec<Vec<(LinkId, Vec2)>>,
    /// The largest distance of a point from its link's origin, m.
    pub(super) size_m: f64,
    /// The link and point that set `size_m`.
    pub(super) farthest: (String, String),
}

/// The links with their points (one ground, names unique and not empty, each with a
/// point), masses and inertias.
pub(super) fn bodies(scene: &SceneFile, units: Units) -> Result<Bodies> {
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
            let local = units.point(|| format!("{}.{}", spec.name, pname), xy)?;
            // hypot: a coordinate of 1e300 squared would overflow to infinity.
            let reach = local.x.hypot(local.y);
            if reach > b.size_m {
                b.size_m = reach;
                b.farthest = (spec.name.clone(), pname.clone());
            }
            let li = LinkId(li);
            let pi = match b.points.iter().position(|p| &p.name == pname) {
                Some(pi) => PointId(pi),
                None => {
                    b.points.push(Point {
                        name: pname.clone(),
                        link: li,
                        local,
                    });
                    b.on_links.push(Vec::new());
                    PointId(b.points.len() - 1)
                }
            };
            b.on_links[pi].push((li, local));
            link_points.push((pi, local));
        }
        if let Some(m) = spec.mass {
            positive_named(m, || format!("{}.mass", spec.name))?;
        }
        if let Some(j) = spec.inertia {
            positive_named(j, || format!("{}.inertia", spec.name))?;
        }
        b.links.push(Link {
            name: spec.name.clone(),
            is_ground: spec.ground,
            points: link_points,
            mass_kg: spec.mass,
            centroid_m: spec
                .centroid
                .map(|c| units.point(|| format!("{}.centroid", spec.name), c))
                .transpose()?,
            inertia_kg_m2: spec.inertia,
        });
    }
    Ok(b)
}

/// Two joints of one link at the same place make that link a point: no length, no
/// angle (a zero-length crank, say).
pub(super) fn check_joint_gaps(b: &Bodies) -> Result<()> {
    for link in &b.links {
        let joints: Vec<&(PointId, Vec2)> = link
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
