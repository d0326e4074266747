//! A scene in one of its poses as a drawing: what "This scene as a drawing" opens,
//! to add and delete links and sliders in a mechanism one did not draw.

use super::{Sketch, SketchLink, SketchPoint, SketchSlider};
use crate::Solution;
use crate::model::Mechanism;
use crate::scene::{Models, SceneFile};

/// Why a scene cannot become a drawing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NotDrawable {
    /// Springs, dampers, point forces, torques or stops: a drawing carries masses and
    /// gravity only, so they would be lost.
    Forces,
    /// Forward dynamics (a drawing computes kinematics or kinetostatics).
    Dynamics,
    /// A slider block that carries more than its pin.
    BlockCarriesPoints(String),
}

impl std::fmt::Display for NotDrawable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Forces => f.write_str(
                "its springs, dampers or forces would be lost: a drawing carries masses and gravity only",
            ),
            Self::Dynamics => f.write_str("it runs forward dynamics: a drawing computes kinematics or kinetostatics"),
            Self::BlockCarriesPoints(block) => {
                write!(f, "its slider block {block} carries more than its pin")
            }
        }
    }
}

impl Sketch {
    /// The drawing of `scene` in `pose` (a solved pose of `m`, the scene's
    /// mechanism): every point where it is, links by their points, slider blocks as
    /// sliders on their guides, the driver, output, speed, masses and gravity. Masses
    /// become uniform bodies (see [`Sketch::to_scene`]); a guide's line keeps its
    /// direction, through the block's pin.
    pub fn from_pose(
        scene: &SceneFile,
        m: &Mechanism,
        pose: &Solution,
    ) -> Result<Self, NotDrawable> {
        check_drawable(scene, m)?;
        let mut sketch = Sketch::new(&scene.name);
        sketch.length_unit = scene.length_unit;
        sketch.speed = scene.driver.speed;
        sketch.models = scene.models;
        sketch.gravity = scene.forces.gravity.is_some();
        let blocks: Vec<usize> = m.sliders.iter().map(|s| s.slider).collect();
        let moving: Vec<usize> = m.moving_links().filter(|l| !blocks.contains(l)).collect();
        let index = add_points(&mut sketch, m, pose, &moving);
        let mut link_index = vec![None; m.links.len()];
        for &l in &moving {
            let name = &m.links[l].name;
            if l == m.driver.link {
                sketch.driver = Some(sketch.links.len());
            }
            if scene.output.as_deref() == Some(name.as_str()) {
                sketch.output = Some(sketch.links.len());
            }
            link_index[l] = Some(sketch.links.len());
            let points = m.links[l]
                .points
                .iter()
                .filter_map(|(p, _)| index[*p])
                .collect();
            sketch.links.push(SketchLink {
                name: name.clone(),
                points,
                mass_kg: m.links[l].mass_kg,
            });
        }
        for s in &m.sliders {
            let direction = pose.links[s.guide].rotation * s.direction_local;
            let Some(point) = index[s.point] else {
                continue;
            };
            sketch.sliders.push(SketchSlider {
                point,
                guide: link_index[s.guide],
                angle_rad: direction.y.atan2(direction.x),
                mass_kg: m.links[s.slider].mass_kg,
            });
        }
        Ok(sketch)
    }
}

/// What a drawing cannot carry: force elements, dynamics, blocks with more points.
fn check_drawable(scene: &SceneFile, m: &Mechanism) -> Result<(), NotDrawable> {
    let f = &scene.forces;
    let forces = [
        f.springs.is_empty(),
        f.dampers.is_empty(),
        f.point_forces.is_empty(),
        f.torques.is_empty(),
        f.stops.is_empty(),
    ];
    if forces.contains(&false) {
        return Err(NotDrawable::Forces);
    }
    if scene.models == Models::Dynamics {
        return Err(NotDrawable::Dynamics);
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
    sketch: &mut Sketch,
    m: &Mechanism,
    pose: &Solution,
    moving: &[usize],
) -> Vec<Option<usize>> {
    let ground_points = &m.links[m.ground].points;
    let through_only: Vec<usize> = m
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
    let on_moving = |p: usize| {
        moving
            .iter()
            .any(|&l| m.links[l].points.iter().any(|(q, _)| *q == p))
            || m.sliders.iter().any(|s| s.point == p)
    };
    let on_ground =
        |p: usize| ground_points.iter().any(|(q, _)| *q == p) && !through_only.contains(&p);
    let mut index = vec![None; m.points.len()];
    for p in (0..m.points.len()).filter(|&p| on_moving(p) || on_ground(p)) {
        index[p] = Some(sketch.points.len());
        sketch.points.push(SketchPoint {
            name: m.points[p].name.clone(),
            at: pose.points[p].position,
            ground: on_ground(p),
        });
    }
    index
}
