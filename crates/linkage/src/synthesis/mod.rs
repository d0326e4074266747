//! Dimensional synthesis: function generation by Freudenstein's equation
//! ([`function`]), motion generation through three positions ([`motion`]), and here
//! a crank-rocker from rocker length, swing and time ratio K
//! (the construction of the die-cutter paper): with the rocker's two limit
//! positions C1, C2 about D, the crank pivot A lies on the circle through C1 and C2
//! on which the chord C1C2 subtends θ = π(K − 1)/(K + 1); at the limits A, B, C are
//! collinear, so AB = (AC_far − AC_near)/2 and BC = (AC_far + AC_near)/2. The place
//! of A on that circle is the free choice: by default the one with the best minimum
//! transmission angle.

pub mod burmester;
pub mod function;
pub mod motion;
pub mod path;
pub mod positions;
pub mod rows;

/// Why a synthesis gives no linkage (defined with the other leaf error types).
pub use crate::error::DesignRefusal;

use indexmap::IndexMap;
use serde::Serialize;

use crate::error::{LinkageError, Result};
use crate::motion::{Vec2, cross};
use crate::scene::{
    Branch, DriverSpec, ForceWhen, ForcesSpec, LengthUnit, LinkSpec, Models, PointForceSpec,
    SceneFile, SliderSpec, SolverSpec, Speed,
};

/// A synthesized crank-rocker, SI units, D at the origin.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CrankRocker {
    /// Crank AB, m.
    pub crank_m: f64,
    /// Coupler BC, m.
    pub coupler_m: f64,
    /// Rocker CD, m.
    pub rocker_m: f64,
    /// Ground AD, m.
    pub ground_m: f64,
    /// Crank pivot A, m.
    pub pivot_a: [f64; 2],
    /// Rocker pivot D, m (the origin).
    pub pivot_d: [f64; 2],
    /// Rocker limit position at the start angle, m.
    pub c1: [f64; 2],
    /// Rocker limit position at start + swing, m.
    pub c2: [f64; 2],
    /// Crank angle between the two limit positions, rad.
    pub theta_rad: f64,
    /// Minimum transmission angle of the design (crank collinear with ground), rad.
    pub min_transmission_rad: f64,
    /// The free choice: A's angle on the synthesis circle about its centre, rad.
    pub arc_rad: f64,
    /// Which of the two mirror circles A lies on (+1: centre left of C1→C2).
    pub side: i8,
    /// True when C is left of the line B→D on the assembly branch.
    pub c_left_of_bd: bool,
}

fn invalid(name: &str, value: f64, valid: &str) -> LinkageError {
    LinkageError::InvalidParameter {
        name: name.into(),
        value,
        valid: valid.into(),
    }
}

/// Design at A on the circle of `side` at angle `t`; `None` where no crank-rocker results.
fn design_at(c1: Vec2, c2: Vec2, rocker: f64, theta: f64, side: i8, t: f64) -> Option<CrankRocker> {
    let mid = (c1 + c2) * 0.5;
    let half = (c2 - c1).norm() * 0.5;
    let n = Vec2::new(-(c2 - c1).y, (c2 - c1).x) / (2.0 * half);
    let radius = half / theta.sin();
    let centre = mid + n * (f64::from(side) * half / theta.tan());
    let a = centre + Vec2::new(t.cos(), t.sin()) * radius;
    let (r1, r2) = (c1 - a, c2 - a);
    // Only the major arc sees the chord under θ (the minor arc under π − θ).
    let seen = cross(&r1, &r2).abs().atan2(r1.dot(&r2));
    if (seen - theta).abs() > 1e-6 {
        return None;
    }
    let (near, far) = if r1.norm() < r2.norm() {
        (c1, c2)
    } else {
        (c2, c1)
    };
    let (dn, df) = ((near - a).norm(), (far - a).norm());
    let crank = 0.5 * (df - dn);
    let coupler = 0.5 * (df + dn);
    let ground = a.norm();
    let lengths = [crank, coupler, rocker, ground];
    let longest = lengths.iter().cloned().fold(0.0, f64::max);
    if crank.is_nan()
        || crank <= 1e-9 * rocker
        || lengths[1..].iter().any(|&l| l <= crank)
        || crank + longest >= lengths.iter().sum::<f64>() - crank - longest
    {
        return None;
    }
    // Same assembly branch at both limits, or the rocker cannot reach both.
    let b_ext = a + (far - a) * (crank / df);
    let b_fold = a - (near - a) * (crank / dn);
    let side_ext = cross(&(-b_ext), &(far - b_ext));
    let side_fold = cross(&(-b_fold), &(near - b_fold));
    if side_ext * side_fold <= 0.0 {
        return None;
    }
    let mu = |bd: f64| {
        let c = ((coupler * coupler + rocker * rocker - bd * bd) / (2.0 * coupler * rocker))
            .clamp(-1.0, 1.0);
        let m = c.acos();
        m.min(std::f64::consts::PI - m)
    };
    Some(CrankRocker {
        crank_m: crank,
        coupler_m: coupler,
        rocker_m: rocker,
        ground_m: ground,
        pivot_a: [a.x, a.y],
        pivot_d: [0.0, 0.0],
        c1: [c1.x, c1.y],
        c2: [c2.x, c2.y],
        theta_rad: theta,
        min_transmission_rad: mu(ground - crank).min(mu(ground + crank)),
        arc_rad: t.rem_euclid(std::f64::consts::TAU),
        side,
        c_left_of_bd: side_ext > 0.0,
    })
}

/// Crank-rocker with rocker `rocker_m` swinging `swing_rad` from `rocker_start_rad`
/// (angle of C1 about D) and time ratio `k`. `arc_rad`/`side` fix A on the circle;
/// `None` picks the best minimum transmission angle.
pub fn crank_rocker(
    rocker_m: f64,
    swing_rad: f64,
    k: f64,
    rocker_start_rad: f64,
    choice: Option<(f64, i8)>,
) -> Result<CrankRocker> {
    check_crank_rocker(rocker_m, swing_rad, k, rocker_start_rad)?;
    let theta = std::f64::consts::PI * (k - 1.0) / (k + 1.0);
    let at = |phi: f64| Vec2::new(phi.cos(), phi.sin()) * rocker_m;
    let (c1, c2) = (at(rocker_start_rad), at(rocker_start_rad + swing_rad));
    if let Some((t, side)) = choice {
        return design_at(c1, c2, rocker_m, theta, side, t).ok_or_else(|| {
            invalid(
                "arc (deg)",
                t.to_degrees(),
                "gives no crank-rocker here; omit it to get the best design",
            )
        });
    }
    const SAMPLES: usize = 3600;
    let mut best: Option<CrankRocker> = None;
    for side in [1i8, -1] {
        for i in 0..SAMPLES {
            let t = std::f64::consts::TAU * i as f64 / SAMPLES as f64;
            if let Some(d) = design_at(c1, c2, rocker_m, theta, side, t)
                && best
                    .as_ref()
                    .is_none_or(|b| d.min_transmission_rad > b.min_transmission_rad)
            {
                best = Some(d);
            }
        }
    }
    let coarse = best.ok_or_else(|| {
        invalid(
            "swing (deg)",
            swing_rad.to_degrees(),
            "admits no crank-rocker with this K",
        )
    })?;
    // Golden-section refinement within one grid step either side.
    let step = std::f64::consts::TAU / SAMPLES as f64;
    let score = |t: f64| {
        design_at(c1, c2, rocker_m, theta, coarse.side, t).map_or(-1.0, |d| d.min_transmission_rad)
    };
    let (mut lo, mut hi) = (coarse.arc_rad - step, coarse.arc_rad + step);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..80 {
        let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if score(x1) < score(x2) {
            lo = x1
        } else {
            hi = x2
        }
    }
    Ok(design_at(c1, c2, rocker_m, theta, coarse.side, 0.5 * (lo + hi)).unwrap_or(coarse))
}

/// The crank-rocker's requirements, each within its valid range.
fn check_crank_rocker(rocker_m: f64, swing_rad: f64, k: f64, rocker_start_rad: f64) -> Result<()> {
    if !(rocker_m.is_finite() && rocker_m > 0.0) {
        return Err(invalid("rocker length", rocker_m, "must be > 0"));
    }
    if !(swing_rad > 0.0 && swing_rad < std::f64::consts::PI) {
        return Err(invalid(
            "swing (deg)",
            swing_rad.to_degrees(),
            "must be in (0, 180) deg",
        ));
    }
    if !(k.is_finite() && k > 1.0 && k < 1e3) {
        return Err(invalid(
            "time ratio K",
            k,
            "must be in (1, 1000): K = 1 puts A at infinity on this circle (use a centred design)",
        ));
    }
    if !rocker_start_rad.is_finite() {
        return Err(invalid(
            "rocker start angle",
            rocker_start_rad,
            "must be finite",
        ));
    }
    Ok(())
}

/// The die-cutter requirements of the second paper.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DieCutterSpec {
    /// Stroke H, m.
    pub stroke_m: f64,
    /// Time ratio K.
    pub k: f64,
    /// CD = CE = L, m.
    pub link_m: f64,
    /// Crank speed, rpm.
    pub crank_rpm: f64,
}

/// Rocker angle at the far limit: S = H = 2L(1 − sin φ30).
pub fn die_cutter_far_angle(spec: &DieCutterSpec) -> Result<f64> {
    let s = 1.0 - spec.stroke_m / (2.0 * spec.link_m);
    if !(spec.stroke_m > 0.0 && spec.link_m > 0.0 && s > 0.0) {
        return Err(invalid(
            "stroke H (m)",
            spec.stroke_m,
            &format!("must be in (0, 2L) = (0, {}) m", 2.0 * spec.link_m),
        ));
    }
    Ok(s.asin())
}

/// The written scene must load again: a crank speed that is not a finite number
/// would give a scene file that no reader accepts.
fn check_crank_speed(spec: &DieCutterSpec) -> Result<()> {
    if spec.crank_rpm.is_finite() {
        Ok(())
    } else {
        Err(LinkageError::InvalidParameter {
            name: "crank speed (rpm)".into(),
            value: spec.crank_rpm,
            valid: "must be a finite number".into(),
        })
    }
}

/// Synthesizes the toggle six-bar: rocker CD swings from φ30 to 90° (C on DE at the
/// top, the toggle), crank-rocker ABCD from the swing and K, CE = CD, slider E on a
/// vertical guide through D. Returns the scene (mm) and the four-bar design.
pub fn die_cutter(spec: &DieCutterSpec) -> Result<(SceneFile, CrankRocker)> {
    check_crank_speed(spec)?;
    let phi30 = die_cutter_far_angle(spec)?;
    let design = crank_rocker(
        spec.link_m,
        std::f64::consts::FRAC_PI_2 - phi30,
        spec.k,
        phi30,
        None,
    )?;
    let scene = die_cutter_scene(
        &design,
        spec,
        "Die cutter (synthesized from the paper's requirements)",
        format!(
            "Toggle six-bar force amplifier of the flat-press die cutter (paper 2), synthesized by `linkage synth die-cutter --stroke-mm {} --k {} --link-mm {}` from H, K and CD = CE = L; AB = {:.3} mm, BC = {:.3} mm, AD = {:.3} mm; rocker swings {:.3} deg to {:.0} deg where C lies on DE (toggle).",
            spec.stroke_m * 1e3,
            spec.k,
            spec.link_m * 1e3,
            design.crank_m * 1e3,
            design.coupler_m * 1e3,
            design.ground_m * 1e3,
            phi30.to_degrees(),
            90.0
        ),
        vec![
            format!("phi30 = asin(1 - H/(2L)) = {:.4} deg: the paper's bound 'L <= 600 gives phi30 <= 73.4 deg'.", phi30.to_degrees()),
            "The crank turns at 50 rpm = 5.236 rad/s; the paper's v_B = 44.93 m/s uses the motor's 151.8 rad/s.".into(),
            "Pressing force 2e6 N acts on the die only on the upward working stroke; die + slider 120 kg.".into(),
            format!("Crank pivot A chosen on the synthesis circle for the best minimum transmission angle ({:.2} deg).", design.min_transmission_rad.to_degrees()),
        ],
    );
    Ok((scene, design))
}

/// The die cutter with the printed AB, BC and CD = CE, keeping the printed K and the
/// toggle at the top: the rocker swing these force, and A where they put it.
pub fn die_cutter_as_printed(
    crank_m: f64,
    coupler_m: f64,
    spec: &DieCutterSpec,
) -> Result<(SceneFile, CrankRocker)> {
    check_crank_speed(spec)?;
    let theta = std::f64::consts::PI * (spec.k - 1.0) / (spec.k + 1.0);
    let (near, far) = (coupler_m - crank_m, coupler_m + crank_m);
    let chord = (near * near + far * far - 2.0 * near * far * theta.cos()).sqrt();
    let swing = 2.0 * (chord / (2.0 * spec.link_m)).min(1.0).asin();
    let start = std::f64::consts::FRAC_PI_2 - swing;
    // A on the circle where the crank is the printed length: a root of crank(t) - AB.
    let best = crank_rocker(spec.link_m, swing, spec.k, start, None)?;
    let f = |t: f64| {
        crate::synthesis::crank_rocker(spec.link_m, swing, spec.k, start, Some((t, best.side)))
            .map_or(f64::NAN, |d| d.crank_m - crank_m)
    };
    let mut found = None;
    let n = 3600;
    let mut prev = (best.arc_rad, f(best.arc_rad));
    for i in 1..=n {
        let t = best.arc_rad + std::f64::consts::PI * i as f64 / n as f64;
        let v = f(t);
        if prev.1.is_finite() && v.is_finite() && prev.1.signum() != v.signum() {
            found = crate::roots_util::refine(prev.0, t, f);
            break;
        }
        prev = (t, v);
    }
    let t = found
        .ok_or_else(|| invalid("AB (m)", crank_m, "cannot be placed with this BC, CD and K"))?;
    let design = crank_rocker(spec.link_m, swing, spec.k, start, Some((t, best.side)))?;
    let scene = die_cutter_scene(
        &design,
        spec,
        "Die cutter (as printed: AB = 296, BC = 892, CD = CE = 600)",
        format!(
            "The paper's printed dimensions AB = {:.0} mm, BC = {:.0} mm, CD = CE = {:.0} mm, keeping its K = {} and the toggle at the top (C on DE). These lengths force a rocker swing of {:.2} deg (not the 30 deg of phi30 = 60 deg), so the stroke is far from 50 mm: see `linkage report`.",
            crank_m * 1e3,
            coupler_m * 1e3,
            spec.link_m * 1e3,
            spec.k,
            swing.to_degrees()
        ),
        vec![
            "Contradiction shown, not hidden: AB = 295.42, BC = 891.96 with K = 1.3 need a rocker swing of about 69 deg, which no 50 mm stroke allows.".into(),
            "The paper's v_B = 44.93 m/s is omega x AB with omega = 151.8 rad/s, the MOTOR speed (1450 rpm); the crank turns at 50 rpm = 5.236 rad/s. Reproduce with `linkage at ... --speed-rad-s 151.8`.".into(),
            "Paper's graphical results for its position 1: v_C = 50.436 m/s, v_E = 49.772 m/s (from its inconsistent geometry).".into(),
            "Ground pivot A is not printed; it is placed where the printed AB, BC, CD and K are consistent.".into(),
        ],
    );
    Ok((scene, design))
}

fn die_cutter_scene(
    d: &CrankRocker,
    spec: &DieCutterSpec,
    name: &str,
    description: String,
    notes: Vec<String>,
) -> SceneFile {
    let branch = if d.c_left_of_bd {
        Branch::Left("B".into(), "D".into())
    } else {
        Branch::Right("B".into(), "D".into())
    };
    SceneFile {
        name: name.into(),
        description,
        notes,
        models: Models::Kinetostatics,
        length_unit: LengthUnit::Millimetre,
        angle_unit: crate::scene::AngleUnit::Degree,
        links: die_cutter_links(d, spec.link_m),
        sliders: vec![SliderSpec {
            slider: "die".into(),
            point: "E".into(),
            guide: "ground".into(),
            through: "D".into(),
            angle: 90.0,
            relative_angle: 0.0,
        }],
        driver: DriverSpec {
            link: "crank".into(),
            speed: Speed::Rpm(spec.crank_rpm),
            start: 0.0,
        },
        branches: [("C".to_string(), branch), ("E".to_string(), Branch::Along)]
            .into_iter()
            .collect(),
        output: Some("die".into()),
        guess: IndexMap::new(),
        forces: ForcesSpec {
            gravity: Some((0.0, -9.81)),
            point_forces: vec![PointForceSpec {
                point: "E".into(),
                force_n: (0.0, -2.0e6),
                when: ForceWhen::WorkingStroke,
            }],
            ..Default::default()
        },
        solver: SolverSpec::default(),
        drive: None,
        cams: Vec::new(),
    }
}

/// The die cutter's links in millimetres, at full precision (rounding would move the
/// rocker's limit off the toggle): ground AD, crank AB, coupler BC, rocker DC and
/// CE of length `link_m`, and the die at E (the paper's 120 kg).
fn die_cutter_links(d: &CrankRocker, link_m: f64) -> Vec<LinkSpec> {
    let mm = |v: f64| v * 1e3;
    let l = mm(link_m);
    let mut die = plain_link("die", false, points(&[("E", 0.0, 0.0)]));
    die.mass = Some(120.0);
    die.centroid = Some((0.0, 0.0));
    let [ax, ay] = d.pivot_a.map(mm);
    vec![
        plain_link("ground", true, points(&[("A", ax, ay), ("D", 0.0, 0.0)])),
        plain_link(
            "crank",
            false,
            points(&[("A", 0.0, 0.0), ("B", mm(d.crank_m), 0.0)]),
        ),
        plain_link(
            "coupler",
            false,
            points(&[("B", 0.0, 0.0), ("C", mm(d.coupler_m), 0.0)]),
        ),
        plain_link("rocker", false, points(&[("D", 0.0, 0.0), ("C", l, 0.0)])),
        plain_link("link_ce", false, points(&[("C", 0.0, 0.0), ("E", l, 0.0)])),
        die,
    ]
}

/// A link's points from (name, x, y), in order.
fn points(list: &[(&str, f64, f64)]) -> IndexMap<String, (f64, f64)> {
    list.iter()
        .map(|(n, x, y)| (n.to_string(), (*x, *y)))
        .collect()
}

/// A link with its points and no mass.
fn plain_link(name: &str, ground: bool, points: IndexMap<String, (f64, f64)>) -> LinkSpec {
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
