//! Closed-form kinematics by Assur dyads (the complex-vector method of the papers):
//! the chain is split into the driven crank and a sequence of two-link groups,
//! each solved exactly from links already known, with its assembly branch explicit.
//!
//! Every group ends in one 2×2 linear system `x1·c1 + x2·c2 = rhs` for velocities
//! and the same matrix for accelerations, so the Coriolis term of a slider riding a
//! moving guide appears as an explicit right-hand-side term.
//!
//! The group solvers are generic over the number type ([`Real`]): `f64` solves one
//! position, [`crate::real::Lanes`] several at once in SIMD lanes. Their tests are
//! lane masks: a group fails if it fails in any lane.
mod branches;
mod cam;
mod group;
mod guide;
mod joints;
mod parts;
mod prp;
mod rpr;
mod rrp;
mod rrr;

use std::f64::consts::TAU;

use nalgebra::UnitComplex;

use crate::assembly::{AssemblyRanges, GRID};
use crate::error::{LinkageError, Result};
use crate::ids::{LinkId, PointId};
use crate::model::Mechanism;
use crate::motion::{LinkMotion, PointMotion, SlideMotion, Vec2};
use crate::real::{Real, splat, splat_vec};
use crate::roots_util::{refine, sign_changes};
use crate::scene::Branch;

use branches::Branches;
use cam::CamFollow;
pub(crate) use group::Group;
use joints::{JointRef, joint_links};
pub(crate) use parts::{Failure, TANGENT_SLACK};
// The dyads' own types, for the polygons that read their parts.
use prp::prp_group;
use rpr::rpr_group;
use rrp::rrp_group;
use rrr::rrr_group;
pub(crate) use {prp::Prp, rpr::Rpr, rrp::Rrp, rrr::Rrr};

/// The closed-form solver: a crank and a sequence of dyads.
#[derive(Clone, Debug, PartialEq)]
pub struct ClosedForm {
    pub(crate) groups: Vec<Group>,
    /// Inner joint point of each group (for names and branches).
    pub(crate) group_points: Vec<PointId>,
    driver_link: LinkId,
    driver_on_link: Vec2,
    driver_pivot_world: Vec2,
    link_count: usize,
    ground: LinkId,
}

impl ClosedForm {
    /// Decomposes the chain into dyads. Fails with [`LinkageError::NotDecomposable`]
    /// when it has none (then use [`crate::solve::Newton`]), or with
    /// [`LinkageError::SceneInvalid`] when a dyad's branch is missing or malformed.
    pub fn new(m: &Mechanism) -> Result<Self> {
        Self::decompose(m, false)
    }

    /// As [`Self::new`], but a dyad without a branch in the scene gets a provisional
    /// one (for [`Self::match_pose`], which then reads every branch off a pose).
    pub(crate) fn new_without_branches(m: &Mechanism) -> Result<Self> {
        Self::decompose(m, true)
    }

    fn decompose(m: &Mechanism, provisional_branches: bool) -> Result<Self> {
        let mut joints: Vec<JointRef> = (0..m.revolutes.len()).map(JointRef::Rev).collect();
        joints.extend((0..m.sliders.len()).map(JointRef::Pri));
        let mut used = vec![false; joints.len()];
        let mut known = vec![false; m.links.len()];
        known[m.ground] = true;
        known[m.driver.link] = true;
        used[m.driver.pivot] = true;

        let mut groups = Vec::new();
        let mut group_points = Vec::new();
        // A cam's follower is placed by its cam, never by a dyad.
        let followers: Vec<LinkId> = m.cams.iter().map(|c| c.follower).collect();
        while known.iter().any(|k| !k) {
            if let Some(group) = Self::next_cam(m, &known) {
                known[group.follower()] = true;
                used[follower_joint(m, &group.cam)] = true;
                group_points.push(group.cam.roller);
                groups.push(Group::Cam(group));
                continue;
            }
            let mut found = None;
            'search: for (ji, &jij) in joints.iter().enumerate() {
                if used[ji] {
                    continue;
                }
                let (i, j) = joint_links(m, jij);
                if known[i] || known[j] || followers.contains(&i) || followers.contains(&j) {
                    continue;
                }
                let to_known = |l: LinkId| -> Vec<(usize, JointRef, LinkId)> {
                    joints
                        .iter()
                        .enumerate()
                        .filter(|(k, _)| !used[*k] && *k != ji)
                        .filter_map(|(k, &jr)| {
                            let (a, b) = joint_links(m, jr);
                            if a == l && known[b] {
                                Some((k, jr, b))
                            } else if b == l && known[a] {
                                Some((k, jr, a))
                            } else {
                                None
                            }
                        })
                        .collect()
                };
                let (ji_list, jj_list) = (to_known(i), to_known(j));
                if ji_list.len() == 1
                    && jj_list.len() == 1
                    && let Some(g) = Self::make_group(
                        m,
                        i,
                        j,
                        jij,
                        ji_list[0],
                        jj_list[0],
                        provisional_branches,
                    )?
                {
                    found = Some((g, [ji, ji_list[0].0, jj_list[0].0], i, j));
                    break 'search;
                }
            }
            let Some(((group, point), used_now, i, j)) = found else {
                let unknown: Vec<_> = m
                    .link_ids()
                    .filter(|&l| !known[l])
                    .map(|l| m.links[l].name.as_str())
                    .collect();
                return Err(LinkageError::NotDecomposable(
                    crate::error::Undecomposable::NoDyad {
                        links: unknown.into_iter().map(str::to_owned).collect(),
                    },
                ));
            };
            for k in used_now {
                used[k] = true;
            }
            known[i] = true;
            known[j] = true;
            groups.push(group);
            group_points.push(point);
        }
        if let Some(k) = used.iter().position(|u| !u) {
            let (a, b) = joint_links(m, joints[k]);
            return Err(LinkageError::NotDecomposable(
                crate::error::Undecomposable::RedundantJoint {
                    links: [m.links[a].name.clone(), m.links[b].name.clone()],
                },
            ));
        }
        let pivot = &m.revolutes[m.driver.pivot];
        let (ground_local, driver_on_link) = if pivot.a == m.ground {
            (pivot.a_local, pivot.b_local)
        } else {
            (pivot.b_local, pivot.a_local)
        };
        Ok(Self {
            groups,
            group_points,
            driver_link: m.driver.link,
            driver_on_link,
            driver_pivot_world: ground_local,
            link_count: m.links.len(),
            ground: m.ground,
        })
    }

    /// The first cam joint whose cam is placed and whose follower is not.
    fn next_cam(m: &Mechanism, known: &[bool]) -> Option<CamFollow> {
        let (joint, cam) = m
            .cams
            .iter()
            .enumerate()
            .find(|(_, c)| known[c.cam] && !known[c.follower])?;
        Some(CamFollow {
            joint,
            cam: cam.clone(),
        })
    }

    /// Builds the group for unknown links `i`, `j` joined by `jij`, with one joint each
    /// to a known link; `None` when the combination has no closed form here.
    fn make_group(
        m: &Mechanism,
        i: LinkId,
        j: LinkId,
        jij: JointRef,
        ji: (usize, JointRef, LinkId),
        jj: (usize, JointRef, LinkId),
        provisional_branches: bool,
    ) -> Result<Option<(Group, PointId)>> {
        use JointRef::{Pri, Rev};
        let branches = Branches {
            m,
            provisional: provisional_branches,
        };
        match (ji.1, jij, jj.1) {
            (Rev(ra), Rev(rm), Rev(rc)) => {
                rrr_group(m, &branches, (i, ra, ji.2), rm, (j, rc, jj.2))
                    .map(|(g, mid)| Some((Group::Rrr(g), mid)))
            }
            (Rev(_), Rev(_), Pri(_)) | (Pri(_), Rev(_), Rev(_)) => {
                // Normalise: i is pinned, j slides on a known guide.
                let (i, j, ji, jj) = if matches!(ji.1, Rev(_)) {
                    (i, j, ji, jj)
                } else {
                    (j, i, jj, ji)
                };
                let (Rev(ra), Rev(rm), Pri(p)) = (ji.1, jij, jj.1) else {
                    return Ok(None);
                };
                rrp_group(m, &branches, (i, ra, ji.2), rm, (j, p))
                    .map(|g| g.map(|(g, mid)| (Group::Rrp(g), mid)))
            }
            (Rev(ra), Pri(p), Rev(rc)) => rpr_group(m, &branches, i, (ra, ji.2), p, (rc, jj.2))
                .map(|(g, mid)| Some((Group::Rpr(g), mid))),
            (Pri(pi), Rev(rm), Pri(pj)) => {
                Ok(prp_group(m, (i, pi), rm, (j, pj)).map(|(g, mid)| (Group::Prp(g), mid)))
            }
            _ => Ok(None),
        }
    }

    /// Number of links (ground included) this solver writes.
    pub fn link_count(&self) -> usize {
        self.link_count
    }

    /// Sets every group's branch to the one that reproduces `pose` (all links
    /// assembled) at `input_rad`, group by group in solving order: a group's branch
    /// decides its own links, given the groups before it.
    pub(crate) fn match_pose(&mut self, input_rad: f64, pose: &[LinkMotion]) {
        let mut links = vec![LinkMotion::default(); self.link_count];
        for g in 0..self.groups.len() {
            let (i, j) = self.groups[g].links();
            let mut mismatch = |cf: &Self| -> f64 {
                // A failure can only come from a later group (this one's links are
                // placed all the same), so the result is not needed.
                let _ = cf.solve_links(input_rad, 0.0, &mut links);
                [i, j]
                    .iter()
                    .map(|&l| {
                        (links[l].origin.position - pose[l].origin.position).norm()
                            + (links[l].rotation.inverse() * pose[l].rotation)
                                .angle()
                                .abs()
                    })
                    .sum::<f64>()
            };
            let kept = mismatch(self);
            self.groups[g].flip_branch();
            if mismatch(self) >= kept {
                self.groups[g].flip_branch();
            }
        }
    }

    /// Every group's branch as a scene writes it, keyed by the group's inner joint
    /// point (after [`Self::match_pose`]: the branches of that pose).
    pub(crate) fn branches(&self, m: &Mechanism) -> Vec<(String, Branch)> {
        self.groups
            .iter()
            .zip(&self.group_points)
            .filter_map(|(g, &p)| Some((m.points[p].name.clone(), g.branch(m)?)))
            .collect()
    }

    /// Places the crank for input angle `input_rad` turning at `speed_rad_s`.
    #[inline(always)]
    fn place_driver<T: Real>(&self, links: &mut [LinkMotion<T>], input_rad: T, speed_rad_s: f64) {
        let pivot = PointMotion {
            position: splat_vec(&self.driver_pivot_world),
            ..Default::default()
        };
        let (sin, cos) = input_rad.sin_cos_of();
        links[self.driver_link] = LinkMotion::from_pin(
            UnitComplex::from_cos_sin_unchecked(cos, sin),
            splat(speed_rad_s),
            T::zero(),
            &self.driver_on_link,
            &pivot,
        );
    }

    /// Solves all links at one input (`T = f64`) or at one input per lane;
    /// `links` must have `link_count` entries with the ground's at rest (its
    /// default), as in every buffer this crate makes: the ground is never written
    /// here (for lanes that store was 6 % of a four-bar's time). Returns the
    /// conditioning (per lane). Points and slides are not filled here (see
    /// [`finish_solution`]).
    #[inline(always)]
    pub(crate) fn solve_links<T: Real>(
        &self,
        input_rad: T,
        speed_rad_s: f64,
        links: &mut [LinkMotion<T>],
    ) -> std::result::Result<T, Failure> {
        self.place_driver(links, input_rad, speed_rad_s);
        let mut conditioning = T::one();
        for (k, g) in self.groups.iter().enumerate() {
            conditioning = conditioning.simd_min(g.solve(links, true, k)?.conditioning);
        }
        Ok(conditioning)
    }

    /// Smallest assembly margin over the groups at this input (> 0: assembles,
    /// < 0: the first group that fails and by how much), with the group index.
    pub(crate) fn margin(&self, input_rad: f64, links: &mut [LinkMotion]) -> (f64, usize) {
        links[self.ground] = LinkMotion::default();
        self.place_driver(links, input_rad, 0.0);
        let mut worst = (f64::INFINITY, 0);
        for (k, g) in self.groups.iter().enumerate() {
            match g.solve(links, false, k) {
                Ok(ok) if ok.margin < worst.0 => worst = (ok.margin, k),
                Ok(_) => {}
                Err(Failure::CannotAssemble { margin, .. }) => return (margin, k),
                Err(Failure::Singular { .. }) => return (0.0, k),
            }
        }
        worst
    }

    /// How group `group` falls short of closing at `input_rad`, the groups before it
    /// placed (they close there: `group` is the first that does not).
    pub(crate) fn shortfall(
        &self,
        m: &Mechanism,
        input_rad: f64,
        group: usize,
    ) -> Option<crate::dyad::Shortfall> {
        let mut links = vec![LinkMotion::default(); m.links.len()];
        self.place_driver(&mut links, input_rad, 0.0);
        for (k, g) in self.groups.iter().take(group).enumerate() {
            g.solve(&mut links, false, k).ok()?;
        }
        self.groups
            .get(group)?
            .shortfall(&links, m, *self.group_points.get(group)?)
    }

    /// Velocity-system conditioning of each group at the current positions
    /// (|sin| of the angle between its two unknown directions).
    pub(crate) fn group_conditioning(&self, input_rad: f64, links: &mut [LinkMotion]) -> Vec<f64> {
        links[self.ground] = LinkMotion::default();
        self.place_driver(links, input_rad, 0.0);
        self.groups
            .iter()
            .enumerate()
            .map(|(k, g)| {
                g.solve(links, false, k)
                    .map(|ok| ok.conditioning)
                    .unwrap_or(0.0)
            })
            .collect()
    }
}

/// The follower's joint with ground, as an index into the decomposition's joints
/// (revolutes, then prismatic joints).
fn follower_joint(m: &Mechanism, cam: &crate::model::CamJoint) -> usize {
    match cam.guide {
        crate::model::FollowerGuide::Arm { pivot, .. } => pivot,
        crate::model::FollowerGuide::Slide { slider, .. } => m.revolutes.len() + slider,
    }
}

/// Fills the motion of every named point and every prismatic joint from the links'.
#[inline(always)]
pub(crate) fn finish_solution<T: Real>(
    m: &Mechanism,
    links: &[LinkMotion<T>],
    points: &mut [PointMotion<T>],
    slides: &mut [SlideMotion<T>],
) {
    for (out, p) in points.iter_mut().zip(&m.points) {
        *out = if p.link == m.ground {
            // Ground is the world frame: no rotation, no motion.
            PointMotion {
                position: splat_vec(&p.local),
                ..Default::default()
            }
        } else {
            links[p.link].point(&p.local)
        };
    }
    for (out, s) in slides.iter_mut().zip(&m.sliders) {
        *out = s.motion(links);
    }
}

impl ClosedForm {
    /// The input intervals over which every group closes, by root-finding on the
    /// groups' margins over a 0.5 deg grid (`link_count` links in the mechanism).
    pub(crate) fn assembly_ranges(&self, link_count: usize) -> AssemblyRanges {
        let mut links = vec![Default::default(); link_count];
        // A margin that only touches zero (a dyad stretched straight, or its end pins
        // coinciding: the branch points of a change-point chain) assembles: counted as
        // positive, it is no root and no interval ends there.
        let mut margin = |x: f64| {
            let m = self.margin(x, &mut links).0;
            if m >= -TANGENT_SLACK {
                m.max(f64::MIN_POSITIVE)
            } else {
                m
            }
        };
        let xs: Vec<f64> = (0..=GRID).map(|i| TAU * i as f64 / GRID as f64).collect();
        let ms: Vec<f64> = xs.iter().map(|&x| margin(x)).collect();
        let roots: Vec<f64> = sign_changes(&ms)
            .into_iter()
            .filter_map(|i| refine(xs[i], xs[i + 1], &mut margin))
            .collect();
        if roots.is_empty() {
            let full = ms[0] >= 0.0;
            return AssemblyRanges {
                full_rotation: full,
                intervals: if full { vec![[0.0, TAU]] } else { vec![] },
            };
        }
        // Walk the circle from the first root; an interval starts where the margin rises.
        let mut intervals = Vec::new();
        for (n, &r) in roots.iter().enumerate() {
            let next = if n + 1 < roots.len() {
                roots[n + 1]
            } else {
                roots[0] + TAU
            };
            let mid = 0.5 * (r + next);
            if margin(mid.rem_euclid(TAU)) > 0.0 {
                intervals.push([r, next]);
            }
        }
        AssemblyRanges {
            full_rotation: false,
            intervals,
        }
    }
}
