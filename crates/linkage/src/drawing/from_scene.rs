//! A scene in one of its poses as a drawing: what "This scene as a drawing" opens,
//! to add and delete links and sliders in a mechanism one did not draw.

use super::{
    Drawing, DrawingDamper, DrawingForce, DrawingLink, DrawingPoint, DrawingSlider, DrawingSpring,
};
use crate::Solution;
use crate::ids::{LinkId, PointId};
use crate::model::Mechanism;
use crate::motion::Vec2;
use crate::scene::{DamperSpec, FreeLength, SceneFile};

/// Why a scene cannot become a drawing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NotDrawable {
    /// Torques, end stops or rotational dampers: a drawing carries springs, linear
    /// dampers and point forces only, so they would be lost.
    Forces,
    /// A slider block that carries more than its pin.
    BlockCarriesPoints(String),
    /// A force element at a point the drawing does not have (a guide's own point).
    PointNotDrawn(String),
    /// A cam joint: a drawing has pins and sliders only, so it would be lost.
    CamJoint(String),
}

impl std::fmt::Display for NotDrawable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Forces => f.write_str(
                "its torques, end stops or rotational dampers would be lost: a drawing carries springs, linear dampers and point forces",
            ),
            Self::BlockCarriesPoints(block) => {
                write!(f, "its slider block {block} carries more than its pin")
            }
            Self::PointNotDrawn(point) => {
                write!(f, "a force element acts at {point}, which a drawing does not have")
            }
            Self::CamJoint(joint) => write!(
                f,
                "its cam joint {joint} would be lost: a drawing has pins and sliders"
            ),
        }
    }
}

impl Drawing {
    /// The drawing of `scene` in `pose` (a solved pose of `m`, the scene's
    /// mechanism): every point where it is, links by their points with their masses,
    /// centroids and inertias, slider blocks as sliders on their guides, the driver,
    /// output, speed, gravity, springs, linear dampers and point forces. A guide's
    /// line keeps its direction, through the block's pin.
    pub fn from_pose(
        scene: &SceneFile,
        m: &Mechanism,
        pose: &Solution,
    ) -> Result<Self, NotDrawable> {
        check_drawable(scene, m)?;
        let mut drawing = Drawing::new(&scene.name);
        drawing.length_unit = scene.length_unit;
        drawing.speed = scene.driver.speed;
        drawing.models = scene.models;
        drawing.gravity = scene.forces.gravity.is_some();
        drawing.drive = scene.drive.clone();
        let blocks: Vec<LinkId> = m.sliders.iter().map(|s| s.slider).collect();
        let moving: Vec<LinkId> = m.moving_links().filter(|l| !blocks.contains(l)).collect();
        let index = add_points(&mut drawing, m, pose, &moving);
        let mut link_index = vec![None; m.links.len()];
        for &l in &moving {
            let link = &m.links[l];
            if l == m.driver.link {
                drawing.driver = Some(drawing.links.len());
            }
            if scene.output.as_deref() == Some(link.name.as_str()) {
                drawing.output = Some(drawing.links.len());
            }
            link_index[l] = Some(drawing.links.len());
            let placed = &pose.links[l];
            drawing.links.push(DrawingLink {
                name: link.name.clone(),
                points: link.points.iter().filter_map(|(p, _)| index[*p]).collect(),
                mass_kg: link.mass_kg,
                centroid: link
                    .centroid_m
                    .map(|c| placed.origin.position + placed.rotation * c),
                inertia_kg_m2: link.inertia_kg_m2,
            });
        }
        for s in &m.sliders {
            let direction = pose.links[s.guide].rotation * s.direction_local;
            let Some(point) = index[s.point] else {
                continue;
            };
            drawing.sliders.push(DrawingSlider {
                point,
                guide: link_index[s.guide],
                angle_rad: direction.y.atan2(direction.x),
                mass_kg: m.links[s.slider].mass_kg,
            });
        }
        add_force_elements(&mut drawing, scene, m, pose)?;
        Ok(drawing)
    }
}

/// The scene's springs, linear dampers and point forces, on the drawing's points. A
/// spring unstretched at the scene's start stays so where `pose` is the start; from
/// any other pose its free length is the one at the start.
fn add_force_elements(
    drawing: &mut Drawing,
    scene: &SceneFile,
    m: &Mechanism,
    pose: &Solution,
) -> Result<(), NotDrawable> {
    let find = |name: &str| {
        drawing
            .points
            .iter()
            .position(|p| p.name == name)
            .ok_or_else(|| NotDrawable::PointNotDrawn(name.to_owned()))
    };
    let at_start = (pose.input_rad - m.driver.start_rad).abs() < 1e-12;
    let mut start = None;
    let mut springs = Vec::new();
    for s in &scene.forces.springs {
        let (a, b) = (find(&s.a)?, find(&s.b)?);
        let free_length_m = match s.free_length {
            FreeLength::Length(l) => Some(l * scene.length_unit.to_metres()),
            FreeLength::UnstretchedAtStart if at_start => None,
            FreeLength::UnstretchedAtStart => {
                let start: &Solution = start.get_or_insert_with(|| solve_at_start(m, pose));
                let at = |name: &str| m.point_index(name).map(|p| start.points[p].position);
                at(&s.a).zip(at(&s.b)).map(|(p, q)| (p - q).norm())
            }
        };
        springs.push(DrawingSpring {
            a,
            b,
            k_n_per_m: s.k_n_per_m,
            free_length_m,
        });
    }
    let mut dampers = Vec::new();
    for d in &scene.forces.dampers {
        if let DamperSpec::Linear { a, b, c_n_s_per_m } = d {
            dampers.push(DrawingDamper {
                a: find(a)?,
                b: find(b)?,
                c_n_s_per_m: *c_n_s_per_m,
            });
        }
    }
    let mut forces = Vec::new();
    for f in &scene.forces.point_forces {
        forces.push(DrawingForce {
            point: find(&f.point)?,
            force_n: Vec2::new(f.force_n.0, f.force_n.1),
            when: f.when,
        });
    }
    (drawing.springs, drawing.dampers, drawing.forces) = (springs, dampers, forces);
    Ok(())
}

/// The scene's start pose, or `pose` where the start does not solve (the chain was
/// opened elsewhere): the best free length there is.
fn solve_at_start(m: &Mechanism, pose: &Solution) -> Solution {
    crate::Kinematics::new(m.clone())
        .and_then(|mut k| k.solve(m.driver.start_rad))
        .unwrap_or_else(|_| pose.clone())
}

/// What a drawing cannot carry: torques, stops, rotational dampers, blocks with more
/// points.
fn check_drawable(scene: &SceneFile, m: &Mechanism) -> Result<(), NotDrawable> {
    let f = &scene.forces;
    let rotational = f
        .dampers
        .iter()
        .any(|d| matches!(d, DamperSpec::Rotational { .. }));
    if rotational || !f.torques.is_empty() || !f.stops.is_empty() {
        return Err(NotDrawable::Forces);
    }
    if let Some(cam) = m.cams.first() {
        return Err(NotDrawable::CamJoint(cam.name.clone()));
    }
    match m
        .sliders
        .iter()
        .find(|s| m.links[s.slider].points.len() > 1)
    {
        Some(s) => Err(NotDrawable::BlockCarriesPoints(
            m.links[s.slider].name.clone(),
        )),
        None => Ok(()),
    }
}

/// The drawing's points: those of the moving links, the sliders' pins and the ground
/// pivots, where `pose` has them; returns each mechanism point's index in the
/// drawing. A guide's point on ground that is no joint is left out: `to_scene` makes
/// it again, and it is no pivot to draw.
fn add_points(
    drawing: &mut Drawing,
    m: &Mechanism,
    pose: &Solution,
    moving: &[LinkId],
) -> Vec<Option<usize>> {
    let ground_points = &m.links[m.ground].points;
    let through_only: Vec<PointId> = m
        .sliders
        .iter()
        .filter(|s| s.guide == m.ground)
        .filter_map(|s| {
            ground_points
                .iter()
                .find(|(_, at)| *at == s.through_local)
                .map(|(p, _)| *p)
        })
        .filter(|&p| m.revolutes.iter().all(|r| r.point != p))
        .collect();
    let on_moving = |p: PointId| {
        moving
            .iter()
            .any(|&l| m.links[l].points.iter().any(|(q, _)| *q == p))
            || m.sliders.iter().any(|s| s.point == p)
    };
    let on_ground =
        |p: PointId| ground_points.iter().any(|(q, _)| *q == p) && !through_only.contains(&p);
    let mut index = vec![None; m.points.len()];
    for p in m.point_ids().filter(|&p| on_moving(p) || on_ground(p)) {
        index[p] = Some(drawing.points.len());
        drawing.points.push(DrawingPoint {
            name: m.points[p].name.clone(),
            at: pose.points[p].position,
            ground: on_ground(p),
        });
    }
    index
}
