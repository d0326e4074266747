//! The designs the synthesis window makes, free of any GUI type: the inputs of each
//! kind, in the units a designer types (mm, deg), and the design as a table of words
//! and a scene. The solver does the synthesis (`linkage::synthesis`).

use linkage::SceneFile;
use linkage::synthesis::function::{PrecisionPoint, freudenstein, structural_error};
use linkage::synthesis::motion::{BodyPose, three_positions};
use linkage::synthesis::{CrankRocker, DieCutterSpec, crank_rocker, die_cutter, four_bar_scene};

/// Which design.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SynthKind {
    /// A crank-rocker from swing and K.
    CrankRocker,
    /// The die cutter's six-bar from H, K and L.
    DieCutter,
    /// A function generator through precision points.
    Function,
    /// A four-bar through three positions of a body.
    Motion,
    /// A four-bar whose coupler point passes through targets (a search).
    Path,
}

impl SynthKind {
    /// Every kind, in the window's order.
    pub const ALL: [SynthKind; 5] = [
        SynthKind::CrankRocker,
        SynthKind::DieCutter,
        SynthKind::Function,
        SynthKind::Motion,
        SynthKind::Path,
    ];

    /// Its tab's label.
    pub fn label(self) -> &'static str {
        match self {
            SynthKind::CrankRocker => "crank-rocker",
            SynthKind::DieCutter => "die cutter",
            SynthKind::Function => "function",
            SynthKind::Motion => "three positions",
            SynthKind::Path => "path",
        }
    }
}

/// The inputs of every kind (each kept while another is shown).
#[derive(Clone, Debug, PartialEq)]
pub struct SynthInputs {
    /// Which design.
    pub kind: SynthKind,
    /// Crank-rocker: rocker CD (mm), swing (deg), K.
    pub rocker: [f64; 3],
    /// Die cutter: stroke H (mm), K, L (mm), crank speed (rpm).
    pub die: [f64; 4],
    /// Function: precision points, `input_deg, output_deg` per line.
    pub function_points: String,
    /// Function: ground AD, mm.
    pub function_ground_mm: f64,
    /// Motion: the body's three positions, `x_mm, y_mm, angle_deg` per line.
    pub poses: String,
    /// Motion: the moving pivots in the body's frame, mm: x1, y1, x2, y2.
    pub moving_mm: [f64; 4],
    /// Path: the targets and constraints of the search.
    pub path: crate::path_inputs::PathInputs,
}

impl Default for SynthInputs {
    fn default() -> Self {
        Self {
            kind: SynthKind::CrankRocker,
            rocker: [600.0, 16.6, 1.3],
            die: [50.0, 1.3, 600.0, 50.0],
            // y = log10(x) on [1, 2] at its three Chebyshev points: θ over 60° from
            // 30°, φ over 90° from 240°.
            function_points: "34.0192, 248.4189\n60.0, 292.6466\n85.9808, 325.5766\n".into(),
            function_ground_mm: 100.0,
            poses: "0, 0, 0\n200, 100, 20\n350, 300, 45\n".into(),
            moving_mm: [-100.0, -150.0, 150.0, -100.0],
            path: crate::path_inputs::PathInputs::default(),
        }
    }
}

/// A design: its table (quantity, value in words) and its scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Design {
    /// What the design is, row by row.
    pub table: Vec<(String, String)>,
    /// The scene it opens as.
    pub scene: SceneFile,
}

/// The design of `inputs`, or why there is none (in words: it is shown at once).
///
/// # Errors
/// Inputs outside their valid range, rows that are not numbers, or requirements no
/// linkage of the kind meets; each names its cause.
pub fn design(inputs: &SynthInputs) -> Result<Design, String> {
    match inputs.kind {
        SynthKind::CrankRocker => rocker(inputs.rocker),
        SynthKind::DieCutter => die(inputs.die),
        SynthKind::Function => function(&inputs.function_points, inputs.function_ground_mm),
        SynthKind::Motion => motion(&inputs.poses, inputs.moving_mm),
        // Not closed form: the window runs its search (`crate::path_job`).
        SynthKind::Path => Err("a path design comes from its search: press Search".into()),
    }
}

fn mm(m: f64) -> String {
    format!("{:.3} mm", m * 1e3)
}

fn deg(rad: f64) -> String {
    format!("{:.3}°", rad.to_degrees())
}

fn row(what: &str, value: String) -> (String, String) {
    (what.to_owned(), value)
}

fn rocker([cd_mm, swing_deg, k]: [f64; 3]) -> Result<Design, String> {
    let d = crank_rocker(
        cd_mm * 1e-3,
        swing_deg.to_radians(),
        k,
        45f64.to_radians(),
        None,
    )
    .map_err(|e| e.to_string())?;
    Ok(Design {
        table: crank_rocker_rows(&d, "rocker CD", "least transmission angle"),
        scene: four_bar_scene(&d, k),
    })
}

/// The table of a crank-rocker design, its rocker and transmission rows named by
/// the caller (the die cutter's rocker is also CE, and its angle is ABCD's only).
fn crank_rocker_rows(d: &CrankRocker, rocker: &str, transmission: &str) -> Vec<(String, String)> {
    vec![
        row("crank AB", mm(d.crank_m)),
        row("coupler BC", mm(d.coupler_m)),
        row(rocker, mm(d.rocker_m)),
        row("ground AD", mm(d.ground_m)),
        row("crank angle between the limits", deg(d.theta_rad)),
        row(transmission, deg(d.min_transmission_rad)),
    ]
}

fn die([h_mm, k, l_mm, rpm]: [f64; 4]) -> Result<Design, String> {
    let spec = DieCutterSpec {
        stroke_m: h_mm * 1e-3,
        k,
        link_m: l_mm * 1e-3,
        crank_rpm: rpm,
    };
    let (scene, d) = die_cutter(&spec).map_err(|e| e.to_string())?;
    Ok(Design {
        table: crank_rocker_rows(&d, "rocker CD = CE", "least transmission angle (ABCD)"),
        scene,
    })
}

/// Rows of `width` numbers, one per line (blank lines skipped).
fn numbers(text: &str, width: usize) -> Result<Vec<Vec<f64>>, String> {
    text.lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(i, line)| {
            let v: Result<Vec<f64>, _> = line.split(',').map(|c| c.trim().parse()).collect();
            v.ok()
                .filter(|v| v.len() == width && v.iter().all(|x| x.is_finite()))
                .ok_or_else(|| format!("line {}: {:?} is not {width} numbers", i + 1, line.trim()))
        })
        .collect()
}

fn function(points: &str, ground_mm: f64) -> Result<Design, String> {
    let points: Vec<PrecisionPoint> = numbers(points, 2)?
        .into_iter()
        .map(|v| PrecisionPoint {
            input_rad: v[0].to_radians(),
            output_rad: v[1].to_radians(),
        })
        .collect();
    let d = freudenstein(&points, ground_mm * 1e-3).map_err(|e| e.to_string())?;
    let [k1, k2, k3] = d.k;
    let [a, b, c, g] = d.lengths;
    let error = structural_error(&d, &points)
        .map_or_else(|| "the chain does not close at a point".into(), deg);
    let method = if points.len() == 3 {
        "exact"
    } else {
        "least squares"
    };
    Ok(Design {
        table: vec![
            row("method", format!("{method}, {} points", points.len())),
            row("K1, K2, K3", format!("{k1:.6}, {k2:.6}, {k3:.6}")),
            row("crank AB", mm(a.abs())),
            row("coupler BC", mm(b)),
            row("rocker CD", mm(c.abs())),
            row("ground AD", mm(g)),
            row("largest error at the points", error),
        ],
        scene: d.scene(points[0]),
    })
}

fn motion(poses: &str, moving_mm: [f64; 4]) -> Result<Design, String> {
    let rows = numbers(poses, 3)?;
    let poses: [BodyPose; 3] = rows
        .iter()
        .map(|v| BodyPose {
            at: [v[0] * 1e-3, v[1] * 1e-3],
            angle_rad: v[2].to_radians(),
        })
        .collect::<Vec<_>>()
        .try_into()
        .map_err(|v: Vec<BodyPose>| format!("{} positions: three are needed", v.len()))?;
    let [x1, y1, x2, y2] = moving_mm.map(|v| v * 1e-3);
    let d = three_positions(poses, [[x1, y1], [x2, y2]]).map_err(|e| e.to_string())?;
    let checked = d.check().map_err(|e| e.to_string())?;
    let point = |p: [f64; 2]| format!("({:.3}, {:.3}) mm", p[0] * 1e3, p[1] * 1e3);
    let mut table = vec![
        row("fixed pivot A0", point(d.fixed[0])),
        row("fixed pivot B0", point(d.fixed[1])),
    ];
    for (name, p) in ["pole P12", "pole P13", "pole P23"].iter().zip(d.poles) {
        table.push(row(name, p.map_or_else(|| "at infinity".into(), point)));
    }
    table.push(row(
        "miss when moved there",
        format!(
            "{:.1e} mm, {:.1e}°",
            checked.miss_m * 1e3,
            checked.miss_rad.to_degrees()
        ),
    ));
    Ok(Design {
        table,
        scene: checked.scene,
    })
}
