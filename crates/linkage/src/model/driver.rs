//! The driver (a link pinned to ground, its speed and start), the assembly branches
//! and the starting guesses of Newton.

use super::joints::Names;
use super::units::{Units, finite, invalid, scene_angle};
use crate::error::Result;
use crate::error::SceneProblem;
use crate::model::{Driver, LinkId, Point, PointId, Revolute};
use crate::motion::Vec2;
use crate::scene::{Branch, SceneFile, Speed};

/// The driver: a link other than ground, pinned to it, with its speed and start.
pub(super) fn driver(
    scene: &SceneFile,
    names: &Names<'_>,
    ground: LinkId,
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
pub(super) fn branches(scene: &SceneFile, points: &[Point]) -> Result<Vec<(PointId, Branch)>> {
    let mut branches = Vec::new();
    for (name, b) in &scene.branches {
        let pi = points
            .iter()
            .position(|p| &p.name == name)
            .map(PointId)
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
pub(super) fn guesses(
    scene: &SceneFile,
    names: &Names<'_>,
    units: Units,
) -> Result<Vec<Option<(Vec2, f64)>>> {
    let mut guess = vec![None; names.links.len()];
    for (name, &(x, y, a)) in &scene.guess {
        let li = names.link("guess", name)?;
        guess[li] = Some((
            units.point(|| format!("guess.{name}"), (x, y))?,
            scene_angle("guess angle", a, units.ang)?,
        ));
    }
    Ok(guess)
}
