//! Scenes written from synthesized dimensions: a four-bar A-B-C-D (the crank-rocker's,
//! function generation's) and the links and points the die cutter's scene is made of.

use indexmap::IndexMap;

use super::crank_rocker::CrankRocker;
use crate::scene::{
    Branch, DriverSpec, ForcesSpec, LengthUnit, LinkSpec, Models, SceneFile, SolverSpec, Speed,
};

/// A link's points from (name, x, y), in order.
pub(crate) fn points(list: &[(&str, f64, f64)]) -> IndexMap<String, (f64, f64)> {
    list.iter()
        .map(|(n, x, y)| (n.to_string(), (*x, *y)))
        .collect()
}

/// A link with its points and no mass.
pub(crate) fn plain_link(
    name: &str,
    ground: bool,
    points: IndexMap<String, (f64, f64)>,
) -> LinkSpec {
    LinkSpec {
        name: name.into(),
        ground,
        points,
        mass: None,
        centroid: None,
        inertia: None,
    }
}

/// The synthesized crank-rocker as a four-bar scene (metres, crank at 60 rpm).
pub fn four_bar_scene(d: &CrankRocker, k: f64) -> SceneFile {
    let mut scene = four_bar(&FourBar {
        pivot_a: d.pivot_a,
        pivot_d: [0.0, 0.0],
        lengths_m: [d.crank_m, d.coupler_m, d.rocker_m],
        start_deg: 0.0,
        c_left_of_bd: d.c_left_of_bd,
        coupler_point: None,
    });
    scene.name = "Synthesized crank-rocker".into();
    scene.description = format!(
        "Crank-rocker synthesized for K = {k}: AB = {:.6} m, BC = {:.6} m, CD = {:.6} m, AD = {:.6} m.",
        d.crank_m, d.coupler_m, d.rocker_m, d.ground_m
    );
    scene
}

/// A four-bar A-B-C-D to write as a scene: the ground pivots, the lengths, where the
/// crank starts and on which branch C is.
pub(crate) struct FourBar {
    /// The crank's pivot A, m.
    pub pivot_a: [f64; 2],
    /// The rocker's pivot D, m.
    pub pivot_d: [f64; 2],
    /// Crank AB, coupler BC, rocker DC, m.
    pub lengths_m: [f64; 3],
    /// The crank's start angle, deg.
    pub start_deg: f64,
    /// Whether C is left of the line B→D (the assembly branch).
    pub c_left_of_bd: bool,
    /// A coupler point P in the coupler's frame (origin B, x-axis along B→C), m.
    pub coupler_point: Option<[f64; 2]>,
}

/// The scene of `f` (metres, each moving link along its own x-axis, the crank AB
/// driving at 60 rpm, the rocker the output), unnamed: callers name and describe it.
pub(crate) fn four_bar(f: &FourBar) -> SceneFile {
    let branch = if f.c_left_of_bd {
        Branch::Left("B".into(), "D".into())
    } else {
        Branch::Right("B".into(), "D".into())
    };
    let ([ax, ay], [dx, dy]) = (f.pivot_a, f.pivot_d);
    let [crank, coupler, rocker] = f.lengths_m;
    SceneFile {
        name: String::new(),
        description: String::new(),
        notes: vec![],
        models: Models::Kinematics,
        length_unit: LengthUnit::Metre,
        angle_unit: crate::scene::AngleUnit::Degree,
        links: vec![
            plain_link("ground", true, points(&[("A", ax, ay), ("D", dx, dy)])),
            plain_link(
                "crank",
                false,
                points(&[("A", 0.0, 0.0), ("B", crank, 0.0)]),
            ),
            plain_link("coupler", false, {
                let mut points = points(&[("B", 0.0, 0.0), ("C", coupler, 0.0)]);
                if let Some([px, py]) = f.coupler_point {
                    points.insert("P".into(), (px, py));
                }
                points
            }),
            plain_link(
                "rocker",
                false,
                points(&[("D", 0.0, 0.0), ("C", rocker, 0.0)]),
            ),
        ],
        sliders: vec![],
        driver: DriverSpec {
            link: "crank".into(),
            speed: Speed::Rpm(60.0),
            start: f.start_deg,
        },
        branches: [("C".to_string(), branch)].into_iter().collect(),
        output: Some("rocker".into()),
        guess: IndexMap::new(),
        forces: ForcesSpec::default(),
        solver: SolverSpec::default(),
        drive: None,
        cams: Vec::new(),
    }
}
