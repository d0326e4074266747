//! A mechanism as drawn: points at their places in the world, links as sets of
//! points, sliders on guides, perhaps a driver; complete or not. An editor builds
//! one click by click; [`Drawing::to_scene`] turns a complete one into a scene whose
//! start pose is the drawing: every link's coordinates are the world's at input 0,
//! and each dyad's assembly branch is read off the drawing. [`Drawing::from_pose`]
//! (`from_scene.rs`) goes the other way.

mod from_scene;

use indexmap::IndexMap;

use crate::Kinematics;
use crate::error::LinkageError;
use crate::model::Mechanism;
use crate::model::SceneProblem;
use crate::motion::{LinkMotion, Vec2};
use crate::scene::{
    AngleUnit, DamperSpec, DriverSpec, ForceWhen, ForcesSpec, FreeLength, LengthUnit, LinkSpec,
    Models, PointForceSpec, SceneFile, SliderSpec, Speed, SpringSpec,
};
use crate::solve::ClosedForm;
pub use from_scene::NotDrawable;

/// A point of the drawing.
#[derive(Clone, Debug, PartialEq)]
pub struct DrawingPoint {
    /// Unique name (a joint where links share it).
    pub name: String,
    /// Place in the world, m.
    pub at: Vec2,
    /// Whether the point is fixed to the frame (a ground pivot).
    pub ground: bool,
}

/// A rigid link through two or more points (indices into [`Drawing::points`]).
#[derive(Clone, Debug, PartialEq)]
pub struct DrawingLink {
    /// Unique name.
    pub name: String,
    /// Its points; two make a binary link, three or more a plate.
    pub points: Vec<usize>,
    /// Mass, kg (`None`: massless), for kinetostatics and dynamics.
    pub mass_kg: Option<f64>,
    /// Centroid in the world as drawn, m; `None`: the mean of its points.
    pub centroid: Option<Vec2>,
    /// Moment of inertia about the centroid, kg·m²; `None`: a uniform body's (see
    /// [`Drawing::to_scene`]).
    pub inertia_kg_m2: Option<f64>,
}

impl DrawingLink {
    /// A massless link named `name` through `points` (a uniform body once it is
    /// given a mass).
    pub fn new(name: &str, points: Vec<usize>) -> Self {
        Self {
            name: name.to_owned(),
            points,
            mass_kg: None,
            centroid: None,
            inertia_kg_m2: None,
        }
    }
}

/// A slider block pinned at `point`, sliding on a guide line through the point's
/// drawn place.
#[derive(Clone, Debug, PartialEq)]
pub struct DrawingSlider {
    /// The block's pin (shared with the links that drive or follow it).
    pub point: usize,
    /// The link carrying the guide (an index into [`Drawing::links`]); `None`: ground.
    pub guide: Option<usize>,
    /// The guide's direction in the world as drawn, rad.
    pub angle_rad: f64,
    /// The block's mass, kg (`None`: massless), a point mass at its pin.
    pub mass_kg: Option<f64>,
}

/// A linear spring between two points (indices into [`Drawing::points`]).
#[derive(Clone, Debug, PartialEq)]
pub struct DrawingSpring {
    /// One end.
    pub a: usize,
    /// The other end.
    pub b: usize,
    /// Stiffness, N/m.
    pub k_n_per_m: f64,
    /// Free length, m; `None`: unstretched as drawn.
    pub free_length_m: Option<f64>,
}

/// A linear viscous damper between two points.
#[derive(Clone, Debug, PartialEq)]
pub struct DrawingDamper {
    /// One end.
    pub a: usize,
    /// The other end.
    pub b: usize,
    /// Coefficient, N·s/m.
    pub c_n_s_per_m: f64,
}

/// A constant force at a point.
#[derive(Clone, Debug, PartialEq)]
pub struct DrawingForce {
    /// Where it acts.
    pub point: usize,
    /// The force in the world, N.
    pub force_n: Vec2,
    /// Always, or only while the point moves against it (a working stroke).
    pub when: ForceWhen,
}

/// A drawing of a mechanism.
#[derive(Clone, Debug, PartialEq)]
pub struct Drawing {
    /// Title of the scene it becomes.
    pub name: String,
    /// The unit the scene writes lengths in.
    pub length_unit: LengthUnit,
    /// The points.
    pub points: Vec<DrawingPoint>,
    /// The moving links (the frame is every ground point together).
    pub links: Vec<DrawingLink>,
    /// The sliders.
    pub sliders: Vec<DrawingSlider>,
    /// The input link (an index into [`Drawing::links`]), once picked.
    pub driver: Option<usize>,
    /// The input speed.
    pub speed: Speed,
    /// The main output for the time ratio (an index into [`Drawing::links`]); `None`:
    /// the scene's default, its last link (slider blocks come after the links).
    pub output: Option<usize>,
    /// What the scene computes: kinematics, kinetostatics or dynamics, with the
    /// masses and force elements.
    pub models: Models,
    /// Gravity, 9.81 m/s² down the drawing's y-axis, on every mass.
    pub gravity: bool,
    /// Springs.
    pub springs: Vec<DrawingSpring>,
    /// Dampers.
    pub dampers: Vec<DrawingDamper>,
    /// Point forces.
    pub forces: Vec<DrawingForce>,
    /// The motor, gear and flywheel of the scene it came from, kept as they were
    /// (the drawing does not edit them, and an edit must not lose them).
    pub drive: Option<crate::scene::DriveSpec>,
}

/// The Grübler–Kutzbach count of a drawing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mobility {
    /// Moving bodies: links and slider blocks.
    pub moving: usize,
    /// Revolute joints: a point shared by k bodies (the frame counts for a ground
    /// point) is k - 1 of them.
    pub revolutes: usize,
    /// Prismatic joints: one per slider.
    pub prismatics: usize,
}

impl Mobility {
    /// Degrees of freedom: 3 per moving body, less 2 per joint.
    pub fn dof(&self) -> i64 {
        3 * self.moving as i64 - 2 * (self.revolutes + self.prismatics) as i64
    }
}

/// Why a drawing is not yet a mechanism.
#[derive(Clone, Debug, PartialEq)]
pub enum DrawingProblem {
    /// Nothing moves yet.
    NoLinks,
    /// The count says `dof` degrees of freedom, not 1.
    Mobility(Mobility),
    /// No input link picked.
    NoDriver,
    /// The input link has no ground pivot to turn about.
    DriverNotGrounded(String),
    /// The solver refuses the drawing (zero-length links, an over-constrained chain).
    Invalid(LinkageError),
}

impl std::fmt::Display for DrawingProblem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::NoLinks => {
                f.write_str("no links yet: place ground pivots, then links between points")
            }
            Self::Mobility(m) => {
                let dof = m.dof();
                let what = if dof > 1 {
                    "add a link or fix a point to ground"
                } else {
                    "the chain is locked: remove a link or free a point"
                };
                write!(
                    f,
                    "{dof} degrees of freedom (3 x {} moving - 2 x {} joints): {what}",
                    m.moving,
                    m.revolutes + m.prismatics
                )
            }
            Self::NoDriver => f.write_str("1 degree of freedom: pick the input link (Driver)"),
            Self::DriverNotGrounded(link) => {
                write!(
                    f,
                    "the input link {link} needs a ground pivot to turn about"
                )
            }
            Self::Invalid(e) => write!(f, "{e}"),
        }
    }
}

impl Drawing {
    /// An empty drawing in millimetres, at 60 rpm.
    pub fn new(name: &str) -> Self {
        Self {
            name: name.to_owned(),
            length_unit: LengthUnit::Millimetre,
            points: Vec::new(),
            links: Vec::new(),
            sliders: Vec::new(),
            driver: None,
            speed: Speed::Rpm(60.0),
            output: None,
            models: Models::Kinematics,
            gravity: false,
            drive: None,
            springs: Vec::new(),
            dampers: Vec::new(),
            forces: Vec::new(),
        }
    }

    /// The Grübler–Kutzbach count.
    pub fn mobility(&self) -> Mobility {
        let mut bodies_at = vec![0usize; self.points.len()];
        for p in self.links.iter().flat_map(|l| &l.points) {
            bodies_at[*p] += 1;
        }
        for s in &self.sliders {
            bodies_at[s.point] += 1;
        }
        for (p, point) in self.points.iter().enumerate() {
            bodies_at[p] += usize::from(point.ground);
        }
        Mobility {
            moving: self.links.len() + self.sliders.len(),
            revolutes: bodies_at.iter().map(|k| k.saturating_sub(1)).sum(),
            prismatics: self.sliders.len(),
        }
    }

    /// The scene of a complete drawing (one degree of freedom, a grounded driver),
    /// starting in the drawn pose; else what is missing. A link with a mass and no
    /// centroid or inertia of its own has its centroid at the mean of its points and
    /// the inertia of a uniform body there: a bar between its two points (m L²/12),
    /// or the triangle of its first three points (m (a² + b² + c²)/36); a slider
    /// block's mass sits at its pin.
    pub fn to_scene(&self) -> Result<SceneFile, DrawingProblem> {
        if self.links.is_empty() {
            return Err(DrawingProblem::NoLinks);
        }
        let mobility = self.mobility();
        if mobility.dof() != 1 {
            return Err(DrawingProblem::Mobility(mobility));
        }
        let driver = self.driver.ok_or(DrawingProblem::NoDriver)?;
        let driver_link = &self.links[driver];
        if !driver_link.points.iter().any(|&p| self.points[p].ground) {
            return Err(DrawingProblem::DriverNotGrounded(driver_link.name.clone()));
        }
        let mut scene = self.scene_without_branches(driver);
        let m = Mechanism::from_scene(&scene).map_err(DrawingProblem::Invalid)?;
        // Every link sits at the world's own coordinates in the drawing.
        let drawn = vec![LinkMotion::default(); m.links.len()];
        match ClosedForm::new_without_branches(&m) {
            Ok(mut closed) => {
                closed.match_pose(0.0, &drawn);
                scene.branches = closed.branches(&m).into_iter().collect();
            }
            Err(LinkageError::NotDecomposable(_)) => {
                // Newton starts from the drawing itself.
                scene.guess = scene.links[1..]
                    .iter()
                    .map(|l| (l.name.clone(), (0.0, 0.0, 0.0)))
                    .collect();
            }
            Err(e) => return Err(DrawingProblem::Invalid(e)),
        }
        self.check_assembles_as_drawn(&scene)?;
        Ok(scene)
    }

    /// The scene with every link in world coordinates, its guides' points added.
    fn scene_without_branches(&self, driver: usize) -> SceneFile {
        let unit = self.length_unit.to_metres();
        let xy = |p: Vec2| (p.x / unit, p.y / unit);
        let mut ground: IndexMap<String, (f64, f64)> = self
            .points
            .iter()
            .filter(|p| p.ground)
            .map(|p| (p.name.clone(), xy(p.at)))
            .collect();
        let mut links: Vec<LinkSpec> = self
            .links
            .iter()
            .enumerate()
            .map(|(index, l)| {
                let points = l
                    .points
                    .iter()
                    .map(|&p| (self.points[p].name.clone(), xy(self.points[p].at)));
                let mut spec = link_spec(&l.name, points);
                if let Some((centroid, inertia)) = self.body(index) {
                    spec.mass = l.mass_kg;
                    spec.centroid = Some(xy(centroid));
                    spec.inertia = Some(inertia);
                }
                spec
            })
            .collect();
        let sliders = self.slider_specs(&mut ground, &mut links);
        links.insert(
            0,
            LinkSpec {
                ground: true,
                ..link_spec("ground", ground)
            },
        );
        SceneFile {
            name: self.name.clone(),
            description: String::new(),
            notes: Vec::new(),
            models: self.models,
            length_unit: self.length_unit,
            angle_unit: AngleUnit::Degree,
            links,
            sliders,
            driver: DriverSpec {
                link: self.links[driver].name.clone(),
                speed: self.speed,
                start: 0.0,
            },
            branches: IndexMap::new(),
            output: self.output.map(|l| self.links[l].name.clone()),
            guess: IndexMap::new(),
            forces: self.forces_spec(),
            solver: Default::default(),
            drive: self.drive.clone(),
            cams: Vec::new(),
        }
    }

    /// The sliders' blocks (added to `links`) and joints: each block a link of its own
    /// at its pin, its guide through the pin on ground or on its link.
    fn slider_specs(
        &self,
        ground: &mut IndexMap<String, (f64, f64)>,
        links: &mut Vec<LinkSpec>,
    ) -> Vec<SliderSpec> {
        let unit = self.length_unit.to_metres();
        let xy = |p: Vec2| (p.x / unit, p.y / unit);
        let mut sliders = Vec::new();
        for s in &self.sliders {
            let pin = &self.points[s.point];
            let through = format!("{} guide", pin.name);
            let guide = match s.guide {
                None => {
                    ground.insert(through.clone(), xy(pin.at));
                    "ground".to_owned()
                }
                Some(l) => {
                    links[l].points.insert(through.clone(), xy(pin.at));
                    links[l].name.clone()
                }
            };
            let block = format!("slider {}", pin.name);
            let mut spec = link_spec(&block, [(pin.name.clone(), xy(pin.at))]);
            if let Some(kg) = s.mass_kg {
                spec.mass = Some(kg);
                spec.centroid = Some(xy(pin.at));
            }
            links.push(spec);
            sliders.push(SliderSpec {
                slider: block,
                point: pin.name.clone(),
                guide,
                through,
                angle: s.angle_rad.to_degrees(),
                relative_angle: 0.0,
            });
        }
        sliders
    }

    /// The centroid (in the world as drawn, m) and the moment of inertia about it
    /// (kg·m²) the scene gives link `link`: its own where set, else a uniform body's
    /// (see [`Drawing::to_scene`]); `None` for a massless link.
    pub fn body(&self, link: usize) -> Option<(Vec2, f64)> {
        let l = self.links.get(link)?;
        let kg = l.mass_kg?;
        let at: Vec<Vec2> = l.points.iter().map(|&p| self.points[p].at).collect();
        let mean = at.iter().sum::<Vec2>() / at.len().max(1) as f64;
        Some((
            l.centroid.unwrap_or(mean),
            l.inertia_kg_m2.unwrap_or_else(|| uniform_inertia(kg, &at)),
        ))
    }

    /// Gravity and the force elements, by point name, lengths in the scene's unit.
    fn forces_spec(&self) -> ForcesSpec {
        let unit = self.length_unit.to_metres();
        let name = |p: usize| self.points[p].name.clone();
        ForcesSpec {
            gravity: self.gravity.then_some((0.0, -9.81)),
            springs: self
                .springs
                .iter()
                .map(|s| SpringSpec {
                    a: name(s.a),
                    b: name(s.b),
                    k_n_per_m: s.k_n_per_m,
                    free_length: s.free_length_m.map_or(FreeLength::UnstretchedAtStart, |m| {
                        FreeLength::Length(m / unit)
                    }),
                })
                .collect(),
            dampers: self
                .dampers
                .iter()
                .map(|d| DamperSpec::Linear {
                    a: name(d.a),
                    b: name(d.b),
                    c_n_s_per_m: d.c_n_s_per_m,
                })
                .collect(),
            point_forces: self
                .forces
                .iter()
                .map(|f| PointForceSpec {
                    point: name(f.point),
                    force_n: (f.force_n.x, f.force_n.y),
                    when: f.when,
                })
                .collect(),
            ..Default::default()
        }
    }

    /// Solves the scene at its start: every point must land where it was drawn.
    fn check_assembles_as_drawn(&self, scene: &SceneFile) -> Result<(), DrawingProblem> {
        let m = Mechanism::from_scene(scene).map_err(DrawingProblem::Invalid)?;
        let size = m.size_m.max(1e-9);
        let mut k = Kinematics::new(m).map_err(DrawingProblem::Invalid)?;
        let pose = k.solve(0.0).map_err(DrawingProblem::Invalid)?;
        let m = k.mechanism();
        for p in &self.points {
            let Some(i) = m.points.iter().position(|q| q.name == p.name) else {
                continue;
            };
            if (pose.points[i].position - p.at).norm() > 1e-9 * size {
                return Err(DrawingProblem::Invalid(LinkageError::from(
                    SceneProblem::NotAsDrawn {
                        point: p.name.clone(),
                    },
                )));
            }
        }
        Ok(())
    }
}

/// The moment of inertia about the centroid of a uniform bar through two points, or
/// of a uniform triangle through the first three, kg·m².
fn uniform_inertia(kg: f64, at: &[Vec2]) -> f64 {
    match at {
        [a, b] => kg * (b - a).norm_squared() / 12.0,
        [a, b, c, ..] => {
            let sides = (b - a).norm_squared() + (c - b).norm_squared() + (a - c).norm_squared();
            kg * sides / 36.0
        }
        _ => 0.0,
    }
}

fn link_spec(name: &str, points: impl IntoIterator<Item = (String, (f64, f64))>) -> LinkSpec {
    LinkSpec {
        name: name.to_owned(),
        ground: false,
        points: points.into_iter().collect(),
        mass: None,
        centroid: None,
        inertia: None,
    }
}
