//! The joints: a revolute for every point shared by two links, the prismatic joints,
//! and the mobility they give (one, or the joints that were and were not made, named).

use nalgebra::UnitComplex;

use super::links::Bodies;
use super::units::{Units, invalid, scene_angle};
use crate::error::Result;
use crate::error::{LonePoint, MadeJoint, SceneProblem};
use crate::model::{Link, LinkId, Point, PointId, Prismatic, Revolute};
use crate::motion::Vec2;
use crate::scene::SceneFile;

/// A revolute joint for every further link that carries a point.
pub(super) fn revolutes(on_links: &[Vec<(LinkId, Vec2)>]) -> Vec<Revolute> {
    let mut revolutes = Vec::new();
    for (pi, users) in on_links.iter().enumerate() {
        let (a, a_local) = users[0];
        for &(b, b_local) in &users[1..] {
            revolutes.push(Revolute {
                point: PointId(pi),
                a,
                a_local,
                b,
                b_local,
            });
        }
    }
    revolutes
}

/// The links and points by name, for the sections that name them.
pub(super) struct Names<'a> {
    pub(super) links: &'a [Link],
    pub(super) points: &'a [Point],
}

impl Names<'_> {
    /// The link named `name`, which `ctx` names.
    pub(super) fn link(&self, ctx: &str, name: &str) -> Result<LinkId> {
        self.links
            .iter()
            .position(|l| l.name == name)
            .map(LinkId)
            .ok_or_else(|| {
                invalid(SceneProblem::UnknownLink {
                    context: ctx.to_string(),
                    name: name.to_string(),
                    known: self.links.iter().map(|l| l.name.clone()).collect(),
                })
            })
    }

    /// The point named `name` on `link`, and where on it.
    pub(super) fn point_on(&self, ctx: &str, link: LinkId, name: &str) -> Result<(PointId, Vec2)> {
        let pi = self.points.iter().position(|p| p.name == name).map(PointId);
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
pub(super) fn sliders(
    scene: &SceneFile,
    names: &Names<'_>,
    units: Units,
) -> Result<Vec<Prismatic>> {
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
pub(super) fn check_mobility(
    b: &Bodies,
    revolutes: &[Revolute],
    sliders: &[Prismatic],
    cams: usize,
) -> Result<()> {
    let moving = b.links.len() - 1;
    let mobility = 3 * moving as i64 - 2 * (revolutes.len() + sliders.len()) as i64 - cams as i64;
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
        cams,
        lone,
        made,
    }))
}
