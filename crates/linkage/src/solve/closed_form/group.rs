//! One Assur group of the decomposition: a dyad of one of the four kinds, solved
//! and measured through one interface.

use super::cam::CamFollow;
use super::parts::{Failure, GroupOk};
use super::prp::Prp;
use super::rpr::Rpr;
use super::rrp::Rrp;
use super::rrr::Rrr;
use crate::dyad::{DyadKind, Shortfall};
use crate::ids::{LinkId, PointId};
use crate::model::Mechanism;
use crate::motion::LinkMotion;
use crate::real::Real;
use crate::scene::Branch;

/// One Assur group of the decomposition.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Group {
    Rrr(Rrr),
    Rrp(Rrp),
    Rpr(Rpr),
    Prp(Prp),
    /// A cam joint's follower (one link).
    Cam(CamFollow),
}

impl Group {
    /// Solves the group from the already-known links. With `motion == false` only
    /// positions are computed (used for the assembly margin, also at singular points).
    // Each kind's `solve` (rrr.rs, rrp.rs, rpr.rs, prp.rs, the cam follower) has this
    // same signature, and the repeated lines are only that: a trait would add a
    // dynamic or generic layer to the solver's innermost call for no shared body
    // (the shared part of their endings is `Pair::rates`).
    #[inline(always)]
    pub(super) fn solve<T: Real>(
        &self,
        links: &mut [LinkMotion<T>],
        motion: bool,
        group: usize,
    ) -> std::result::Result<GroupOk<T>, Failure> {
        match self {
            Group::Rrr(g) => g.solve(links, motion, group),
            Group::Rrp(g) => g.solve(links, motion, group),
            Group::Rpr(g) => g.solve(links, motion, group),
            Group::Prp(g) => g.solve(links, motion, group),
            Group::Cam(g) => g.solve(links),
        }
    }

    /// How the group falls short of closing with the known links where `links`
    /// put them, its points named from `m` (`inner` the point the group solves
    /// for); `None` for the groups whose failure is no distance (PRP, a cam).
    pub(super) fn shortfall(
        &self,
        links: &[LinkMotion],
        m: &Mechanism,
        inner: PointId,
    ) -> Option<Shortfall> {
        let name = |p: PointId| m.points[p].name.clone();
        match self {
            Group::Rrr(g) => {
                let (a, c) = g.end_points;
                Some(g.shortfall(links, [name(a), name(c), name(inner)]))
            }
            Group::Rrp(g) => Some(g.shortfall(links, [name(g.points.0), name(g.points.1)])),
            Group::Rpr(g) => Some(g.shortfall(links, [name(g.points.0), name(g.points.1)])),
            Group::Prp(_) | Group::Cam(_) => None,
        }
    }

    /// The two unknown links (a cam's follower twice: it is one).
    pub(crate) fn links(&self) -> (LinkId, LinkId) {
        match self {
            Group::Cam(g) => (g.follower(), g.follower()),
            Group::Rrr(g) => (g.i, g.j),
            Group::Rrp(g) => (g.i, g.j),
            Group::Rpr(g) => (g.slider, g.guide),
            Group::Prp(g) => (g.i, g.j),
        }
    }

    /// Switches the group to its other assembly branch (a PRP group has only one).
    pub(super) fn flip_branch(&mut self) {
        match self {
            Group::Rrr(g) => g.sign = -g.sign,
            Group::Rrp(g) => g.sign = -g.sign,
            Group::Rpr(g) => g.sign = -g.sign,
            Group::Prp(_) | Group::Cam(_) => {}
        }
    }

    /// The branch this group is on, as a scene writes it (a PRP group has none).
    pub(super) fn branch(&self, m: &Mechanism) -> Option<Branch> {
        let along = |sign: f64| {
            if sign > 0.0 {
                Branch::Along
            } else {
                Branch::Against
            }
        };
        match self {
            Group::Rrr(g) => {
                let (a, c) = (
                    &m.points[g.end_points.0].name,
                    &m.points[g.end_points.1].name,
                );
                Some(if g.sign > 0.0 {
                    Branch::Left(a.clone(), c.clone())
                } else {
                    Branch::Right(a.clone(), c.clone())
                })
            }
            Group::Rrp(g) => Some(along(g.sign)),
            Group::Rpr(g) => Some(along(g.sign)),
            Group::Prp(_) | Group::Cam(_) => None,
        }
    }

    /// The group type in Assur notation.
    pub(crate) fn kind(&self) -> DyadKind {
        match self {
            Group::Rrr(_) => DyadKind::Rrr,
            Group::Rrp(_) => DyadKind::Rrp,
            Group::Rpr(_) => DyadKind::Rpr,
            Group::Prp(_) => DyadKind::Prp,
            Group::Cam(_) => DyadKind::CamFollower,
        }
    }
}
