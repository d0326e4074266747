//! The positions tab's designs: a four-bar that carries a body through three,
//! four or five positions, with its construction for drawing: the positions, the
//! poles, the centre-point curve (four), the Burmester points (five), and the
//! pivots.

use linkage::synthesis::burmester::centre_curve;
use linkage::synthesis::motion::{BodyPose, MotionFourBar};
use linkage::synthesis::positions::{PositionsChoice, PositionsDesign, through_positions};
use linkage::synthesis::rows::read_rows;

pub use crate::synthesis::design::Construction;
use crate::synthesis::design::{Design, Figure, SynthError, row};

/// What fixes the four-bar, per number of positions.
#[derive(Clone, Debug, PartialEq)]
pub struct MotionChoice {
    /// Three: the moving pivots in the body's frame, mm: x1, y1, x2, y2.
    pub moving_mm: [f64; 4],
    /// Four: points near the fixed pivots, mm: x1, y1, x2, y2.
    pub fixed_near_mm: [f64; 4],
    /// Five: which two Burmester points, from 1.
    pub pair: [usize; 2],
}

impl Default for MotionChoice {
    fn default() -> Self {
        Self {
            moving_mm: [-100.0, -150.0, 150.0, -100.0],
            fixed_near_mm: [-300.0, -300.0, 400.0, -300.0],
            pair: [1, 2],
        }
    }
}

/// The four-bar through the positions in `text` (`x mm, y mm, angle deg` rows).
pub fn motion(text: &str, choice: &MotionChoice) -> Result<Design, SynthError> {
    let poses: Vec<BodyPose> = read_rows(text, 3)?
        .iter()
        .map(|v| BodyPose {
            at: [v[0] * 1e-3, v[1] * 1e-3],
            angle_rad: v[2].to_radians(),
        })
        .collect();
    let metres =
        |[x1, y1, x2, y2]: [f64; 4]| Some([[x1, y1], [x2, y2]].map(|p| p.map(|v| v * 1e-3)));
    let positions = PositionsChoice {
        moving: metres(choice.moving_mm),
        fixed_near: metres(choice.fixed_near_mm),
        burmester_pair: choice.pair,
    };
    let PositionsDesign {
        four_bar: d,
        burmester,
    } = through_positions(&poses, &positions)?;
    let burmester = burmester.unwrap_or_default();
    let checked = d.check()?;
    let points: Vec<[f64; 2]> = burmester.iter().map(|c| c.centre).collect();
    Ok(Design {
        table: table(&d, &points, checked.miss_m, checked.miss_rad),
        scene: checked.scene,
        figure: Figure::Construction(construction(&d, &points)),
    })
}

fn point(p: [f64; 2]) -> String {
    format!("({:.3}, {:.3}) mm", p[0] * 1e3, p[1] * 1e3)
}

fn table(
    d: &MotionFourBar,
    burmester: &[[f64; 2]],
    miss_m: f64,
    miss_rad: f64,
) -> Vec<(String, String)> {
    let mut table = vec![
        row("fixed pivot A0", point(d.fixed[0])),
        row("fixed pivot B0", point(d.fixed[1])),
    ];
    let n = d.poses.len();
    let pairs = (1..=n).flat_map(|a| (a + 1..=n).map(move |b| (a, b)));
    for ((a, b), p) in pairs.zip(&d.poles) {
        table.push(row(
            &format!("pole P{a}{b}"),
            p.map_or_else(|| "at infinity".into(), point),
        ));
    }
    for (i, b) in burmester.iter().enumerate() {
        table.push(row(&format!("Burmester point {}", i + 1), point(*b)));
    }
    table.push(row(
        "miss when moved there",
        format!("{:.1e} mm, {:.1e}°", miss_m * 1e3, miss_rad.to_degrees()),
    ));
    table
}

fn construction(d: &MotionFourBar, burmester: &[[f64; 2]]) -> Construction {
    let mm = |p: [f64; 2]| p.map(|v| v * 1e3);
    let first = d.poses[0];
    let size = d
        .poses
        .iter()
        .map(|p| (p.at[0] - first.at[0]).hypot(p.at[1] - first.at[1]))
        .fold(1e-3, f64::max);
    let mut curve = vec![];
    if d.poses.len() >= 4 {
        curve.extend(centre_curve(&d.poses[..4], 3.0 * size, 120));
    }
    if d.poses.len() == 5 {
        let other = [d.poses[0], d.poses[1], d.poses[2], d.poses[4]];
        curve.extend(centre_curve(&other, 3.0 * size, 120));
    }
    let place = |m: [f64; 2]| first.place(linkage::Vec2::new(m[0], m[1])).into();
    Construction {
        positions: d.poses.iter().map(|p| (mm(p.at), p.angle_rad)).collect(),
        poles: d.poles.iter().flatten().map(|p| mm(*p)).collect(),
        curve: curve.into_iter().map(|s| s.map(mm)).collect(),
        burmester: burmester.iter().map(|b| mm(*b)).collect(),
        fixed: d.fixed.map(mm),
        moving: d.moving.map(|m| mm(place(m))),
    }
}
