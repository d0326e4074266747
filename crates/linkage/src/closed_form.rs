//! Closed-form kinematics by Assur dyads (the complex-vector method of the papers):
//! the chain is split into the driven crank and a sequence of two-link groups,
//! each solved exactly from links already known, with its assembly branch explicit.
//!
//! Every group ends in one 2×2 linear system `x1·c1 + x2·c2 = rhs` for velocities
//! and the same matrix for accelerations, so the Coriolis term of a slider riding a
//! moving guide appears as an explicit right-hand-side term.
//!
//! The group solvers are generic over the number type ([`Real`]): `f64` solves one
//! position, [`crate::lanes::Lanes`] several at once in SIMD lanes. Their tests are
//! lane masks: a group fails if it fails in any lane.

use std::f64::consts::TAU;

use nalgebra::{SimdBool, UnitComplex, Vector2};

use crate::assembly::{AssemblyRanges, GRID};
use crate::dyad::DyadKind;
use crate::error::{LinkageError, Result};
use crate::model::{Mechanism, Prismatic};
use crate::motion::{LinkMotion, PointMotion, SlideMotion, Vec2, cross, perp};
use crate::real::{Real, splat, splat_vec};
use crate::roots_util::{refine, sign_changes};
use crate::scene::Branch;
use crate::scene_problem::SceneProblem;

/// A pin: a point fixed on a link, given in that link's coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Pin {
    pub link: usize,
    pub local: Vec2,
    /// The link is ground: the pin stands still at `local` (no rotation to apply).
    pub on_ground: bool,
}

impl Pin {
    #[inline(always)]
    fn motion<T: Real>(&self, links: &[LinkMotion<T>]) -> PointMotion<T> {
        if self.on_ground {
            PointMotion {
                position: splat_vec(&self.local),
                ..Default::default()
            }
        } else {
            links[self.link].point(&self.local)
        }
    }
}

/// Two revolute links `i` (pinned at `a`) and `j` (pinned at `c`) joined at `mid`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Rrr {
    pub i: usize,
    pub j: usize,
    pub a: Pin,
    pub a_on_i: Vec2,
    pub mid_on_i: Vec2,
    pub mid_on_j: Vec2,
    pub c: Pin,
    pub c_on_j: Vec2,
    pub len_i: f64,
    pub len_j: f64,
    pub inv_len_i: f64,
    pub inv_len_j: f64,
    /// Inverse of the direction of `mid - a` in `i`'s coordinates.
    pub dir_i_inv: UnitComplex<f64>,
    /// Inverse of the direction of `mid - c` in `j`'s coordinates.
    pub dir_j_inv: UnitComplex<f64>,
    /// +1: `mid` left of a→c.
    pub sign: f64,
    /// The points of the end pins `a` and `c` (to name the branch).
    pub end_points: (usize, usize),
}

/// Link `i` pinned at `a`, joined at `mid` to slider `j` on a guide of a known link.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Rrp {
    pub i: usize,
    pub j: usize,
    pub a: Pin,
    pub a_on_i: Vec2,
    pub mid_on_j: Vec2,
    pub len_i: f64,
    pub inv_len_i: f64,
    /// Inverse of the direction of `mid - a` in `i`'s coordinates.
    pub dir_i_inv: UnitComplex<f64>,
    pub slide: Prismatic,
    /// +1: `mid` ahead along the guide of the foot of the perpendicular from `a`.
    pub sign: f64,
}

/// Two links pinned to known links, sliding on each other (inverted slider, quick return).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Rpr {
    /// The sliding link and its pin.
    pub slider: usize,
    pub s: Pin,
    pub s_on_slider: Vec2,
    /// The guide link and its pin.
    pub guide: usize,
    pub g: Pin,
    pub g_on_guide: Vec2,
    /// Signed distance of the guide pin from the line the slider pin runs on.
    pub offset: f64,
    pub dir_u: UnitComplex<f64>,
    pub relative: UnitComplex<f64>,
    /// +1: the slider pin lies ahead of the guide pin along the guide.
    pub sign: f64,
}

/// Two sliders on known guides, pinned together at `mid`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Prp {
    pub i: usize,
    pub j: usize,
    pub mid_on_i: Vec2,
    pub mid_on_j: Vec2,
    pub slide_i: Prismatic,
    pub slide_j: Prismatic,
}

/// One Assur group of the decomposition.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Group {
    Rrr(Rrr),
    Rrp(Rrp),
    Rpr(Rpr),
    Prp(Prp),
}

/// Why a group could not be solved (cheap to build; named by [`ClosedForm::describe`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Failure {
    /// Assembly margin < 0 (dimensionless; how far from assembling).
    CannotAssemble { group: usize, margin: f64 },
    /// The velocity system is singular (the group's two directions are parallel).
    Singular { group: usize },
}

/// Result of one group: the assembly margin (> 0 assembles) and the conditioning.
#[derive(Clone, Copy, Debug)]
struct GroupOk<T> {
    margin: T,
    conditioning: T,
}

/// The smallest lane of `x`, a NaN lane counting as -1 (it closes nothing).
#[inline(always)]
fn worst_lane<T: Real>(x: T) -> f64 {
    (0..T::LANES)
        .map(|k| x.extract(k))
        .fold(f64::INFINITY, |w, v| {
            if v.is_nan() {
                -1.0_f64.min(w)
            } else {
                w.min(v)
            }
        })
}

/// Fails with `CannotAssemble` unless every lane's margin is above the slack
/// (a NaN margin fails too).
#[inline(always)]
fn check_margin<T: Real>(margin: T, group: usize) -> std::result::Result<(), Failure> {
    if margin.simd_ge(splat(-TANGENT_SLACK)).all() {
        Ok(())
    } else {
        Err(Failure::CannotAssemble {
            group,
            margin: worst_lane(margin),
        })
    }
}

/// The 2×2 system `x1·c1 + x2·c2 = rhs` of one group, factored once and solved for
/// the velocity and the acceleration right-hand sides (one division in all).
struct Pair<T: Real> {
    c1: Vector2<T>,
    c2: Vector2<T>,
    inv_det: T,
}

impl<T: Real> Pair<T> {
    /// Fails with `Singular` when the columns are parallel (|sin| below 1e-14) in
    /// any lane.
    #[inline(always)]
    fn new(c1: Vector2<T>, c2: Vector2<T>, group: usize) -> std::result::Result<Self, Failure> {
        let det = cross(&c1, &c2);
        // Compared squared: no square roots on the hot path.
        let floor = splat::<T>(1e-28) * c1.norm_squared() * c2.norm_squared();
        if !(det * det).simd_gt(floor).all() {
            return Err(Failure::Singular { group });
        }
        Ok(Self {
            c1,
            c2,
            inv_det: T::one() / det,
        })
    }

    #[inline(always)]
    fn solve(&self, rhs: &Vector2<T>) -> (T, T) {
        (
            cross(rhs, &self.c2) * self.inv_det,
            cross(&self.c1, rhs) * self.inv_det,
        )
    }
}

/// The rotation whose x-axis is the unit vector `unit`.
#[inline(always)]
fn direction<T: Real>(unit: &Vector2<T>) -> UnitComplex<T> {
    UnitComplex::from_cos_sin_unchecked(unit.x, unit.y)
}

/// `r` in every lane.
#[inline(always)]
fn splat_rotation<T: Real>(r: &UnitComplex<f64>) -> UnitComplex<T> {
    UnitComplex::from_cos_sin_unchecked(splat(r.re), splat(r.im))
}

/// Margins between 0 and this are treated as exact tangency (rounding), not failure.
pub(crate) const TANGENT_SLACK: f64 = 1e-12;

impl Group {
    /// Solves the group from the already-known links. With `motion == false` only
    /// positions are computed (used for the assembly margin, also at singular points).
    #[inline(always)]
    fn solve<T: Real>(
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
        }
    }

    /// The two unknown links.
    pub(crate) fn links(&self) -> (usize, usize) {
        match self {
            Group::Rrr(g) => (g.i, g.j),
            Group::Rrp(g) => (g.i, g.j),
            Group::Rpr(g) => (g.slider, g.guide),
            Group::Prp(g) => (g.i, g.j),
        }
    }

    /// Switches the group to its other assembly branch (a PRP group has only one).
    fn flip_branch(&mut self) {
        match self {
            Group::Rrr(g) => g.sign = -g.sign,
            Group::Rrp(g) => g.sign = -g.sign,
            Group::Rpr(g) => g.sign = -g.sign,
            Group::Prp(_) => {}
        }
    }

    /// The branch this group is on, as a scene writes it (a PRP group has none).
    fn branch(&self, m: &Mechanism) -> Option<Branch> {
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
            Group::Prp(_) => None,
        }
    }

    /// The group type in Assur notation.
    pub(crate) fn kind(&self) -> DyadKind {
        match self {
            Group::Rrr(_) => DyadKind::Rrr,
            Group::Rrp(_) => DyadKind::Rrp,
            Group::Rpr(_) => DyadKind::Rpr,
            Group::Prp(_) => DyadKind::Prp,
        }
    }
}

impl Rrr {
    #[inline(always)]
    fn solve<T: Real>(
        &self,
        links: &mut [LinkMotion<T>],
        motion: bool,
        group: usize,
    ) -> std::result::Result<GroupOk<T>, Failure> {
        let pa = self.a.motion(links);
        let pc = self.c.motion(links);
        let d = pc.position - pa.position;
        let dist2 = d.norm_squared();
        let (l1, l2) = (self.len_i, self.len_j);
        if !dist2.simd_gt(T::zero()).all() {
            // Coincident end pins: the dyad is free to turn about them (equal
            // lengths) or cannot close at all.
            let margin = -((l1 - l2) / l1).abs();
            if margin < 0.0 {
                return Err(Failure::CannotAssemble { group, margin });
            }
            return Err(Failure::Singular { group });
        }
        let inv_dist = T::one() / dist2.simd_sqrt();
        let along = (splat::<T>(l1 * l1 - l2 * l2) + dist2) * (splat::<T>(0.5) * inv_dist);
        let ratio = along * splat(self.inv_len_i);
        let margin = T::one() - ratio * ratio;
        check_margin(margin, group)?;
        let h = splat::<T>(l1) * margin.simd_max(T::zero()).simd_sqrt();
        let dhat = d * inv_dist;
        let b = pa.position + dhat * along + perp(&dhat) * (splat::<T>(self.sign) * h);
        let r1 = b - pa.position;
        let r2 = b - pc.position;
        let rot_i = direction(&(r1 * splat::<T>(self.inv_len_i))) * splat_rotation(&self.dir_i_inv);
        let rot_j = direction(&(r2 * splat::<T>(self.inv_len_j))) * splat_rotation(&self.dir_j_inv);
        let conditioning = (cross(&r1, &r2) * splat(self.inv_len_i * self.inv_len_j)).simd_abs();
        let (mut wi, mut wj, mut ai, mut aj) = (T::zero(), T::zero(), T::zero(), T::zero());
        if motion {
            let pair = Pair::new(perp(&r1), -perp(&r2), group)?;
            (wi, wj) = pair.solve(&(pc.velocity - pa.velocity));
            let rhs = pc.acceleration - pa.acceleration + r1 * (wi * wi) - r2 * (wj * wj);
            (ai, aj) = pair.solve(&rhs);
        }
        links[self.i] = LinkMotion::from_pin(rot_i, wi, ai, &self.a_on_i, &pa);
        links[self.j] = LinkMotion::from_pin(rot_j, wj, aj, &self.c_on_j, &pc);
        Ok(GroupOk {
            margin,
            conditioning,
        })
    }
}

/// World data of a guide line: direction, the point of the line, the slider's rotation.
struct GuideLine<T: Real> {
    u: Vector2<T>,
    through: Vector2<T>,
    slider_rotation: UnitComplex<T>,
}

#[inline(always)]
fn guide_line<T: Real>(slide: &Prismatic, links: &[LinkMotion<T>]) -> GuideLine<T> {
    let g = &links[slide.guide];
    GuideLine {
        u: g.rotation * splat_vec(&slide.direction_local),
        through: g.world(&slide.through_local),
        slider_rotation: g.rotation * splat_rotation(&slide.relative),
    }
}

/// Motion of a point riding a guide: the guide's coincident material point plus the
/// sliding velocity, plus the Coriolis term `2 ω_guide × v_rel`.
#[inline(always)]
fn riding_point<T: Real>(
    on_guide: &PointMotion<T>,
    u: &Vector2<T>,
    omega_guide: T,
    s_dot: T,
    s_ddot: T,
) -> PointMotion<T> {
    PointMotion {
        position: on_guide.position,
        velocity: on_guide.velocity + u * s_dot,
        acceleration: on_guide.acceleration
            + perp(u) * (splat::<T>(2.0) * omega_guide * s_dot)
            + u * s_ddot,
    }
}

impl Rrp {
    #[inline(always)]
    fn solve<T: Real>(
        &self,
        links: &mut [LinkMotion<T>],
        motion: bool,
        group: usize,
    ) -> std::result::Result<GroupOk<T>, Failure> {
        let pa = self.a.motion(links);
        let line = guide_line(&self.slide, links);
        let u = line.u;
        let b0 = line.through
            + line.slider_rotation * splat_vec(&(self.mid_on_j - self.slide.slider_local));
        let w = b0 - pa.position;
        let l1 = self.len_i;
        let off = cross(&w, &u) * splat(self.inv_len_i);
        let margin = T::one() - off * off;
        check_margin(margin, group)?;
        let s = -w.dot(&u) + splat::<T>(self.sign * l1) * margin.simd_max(T::zero()).simd_sqrt();
        let b = b0 + u * s;
        let r1 = b - pa.position;
        let rot_i = direction(&(r1 * splat::<T>(self.inv_len_i))) * splat_rotation(&self.dir_i_inv);
        let conditioning = (r1.dot(&u) * splat(self.inv_len_i)).simd_abs();
        let guide = links[self.slide.guide];
        let on_guide = guide.material_point_at(&b);
        let (mut wi, mut ai, mut sd, mut sdd) = (T::zero(), T::zero(), T::zero(), T::zero());
        if motion {
            let pair = Pair::new(perp(&r1), -u, group)?;
            (wi, sd) = pair.solve(&(on_guide.velocity - pa.velocity));
            let rhs = on_guide.acceleration + perp(&u) * (splat::<T>(2.0) * guide.omega_rad_s * sd)
                - pa.acceleration
                + r1 * (wi * wi);
            (ai, sdd) = pair.solve(&rhs);
        }
        let pb = riding_point(&on_guide, &u, guide.omega_rad_s, sd, sdd);
        links[self.i] = LinkMotion::from_pin(rot_i, wi, ai, &self.a_on_i, &pa);
        links[self.j] = LinkMotion::from_pin(
            line.slider_rotation,
            guide.omega_rad_s,
            guide.alpha_rad_s2,
            &self.mid_on_j,
            &pb,
        );
        Ok(GroupOk {
            margin,
            conditioning,
        })
    }
}

impl Rpr {
    #[inline(always)]
    fn solve<T: Real>(
        &self,
        links: &mut [LinkMotion<T>],
        motion: bool,
        group: usize,
    ) -> std::result::Result<GroupOk<T>, Failure> {
        let ps = self.s.motion(links);
        let pg = self.g.motion(links);
        let d = pg.position - ps.position;
        let dist = d.norm();
        if !dist.simd_gt(T::zero()).all() {
            // The pins coincide: no line through both, the guide's direction is free.
            return Err(Failure::CannotAssemble {
                group,
                margin: -1.0,
            });
        }
        let ratio = splat::<T>(self.offset) / dist;
        let margin = T::one() - ratio * ratio;
        check_margin(margin, group)?;
        let dhat = d / dist;
        // Along (+1) puts the slider pin ahead of the guide pin: (S - G)·U > 0.
        let cos_phi = splat::<T>(-self.sign) * margin.simd_max(T::zero()).simd_sqrt();
        let u = dhat * cos_phi + perp(&dhat) * (-ratio);
        let rot_guide =
            UnitComplex::from_cos_sin_unchecked(u.x, u.y) * splat_rotation(&self.dir_u.inverse());
        let rot_slider = rot_guide * splat_rotation(&self.relative);
        let r = ps.position - pg.position;
        let conditioning = (r.dot(&u) / dist).simd_abs();
        let (w, al) = if motion {
            let c1 = perp(&r);
            let pair = Pair::new(c1, u, group)?;
            let (w, sd) = pair.solve(&(ps.velocity - pg.velocity));
            let rhs = ps.acceleration - pg.acceleration + r * (w * w)
                - perp(&u) * (splat::<T>(2.0) * w * sd);
            (w, pair.solve(&rhs).0)
        } else {
            (T::zero(), T::zero())
        };
        links[self.guide] = LinkMotion::from_pin(rot_guide, w, al, &self.g_on_guide, &pg);
        links[self.slider] = LinkMotion::from_pin(rot_slider, w, al, &self.s_on_slider, &ps);
        Ok(GroupOk {
            margin,
            conditioning,
        })
    }
}

impl Prp {
    #[inline(always)]
    fn solve<T: Real>(
        &self,
        links: &mut [LinkMotion<T>],
        motion: bool,
        group: usize,
    ) -> std::result::Result<GroupOk<T>, Failure> {
        let li = guide_line(&self.slide_i, links);
        let lj = guide_line(&self.slide_j, links);
        let b_i0 = li.through
            + li.slider_rotation * splat_vec(&(self.mid_on_i - self.slide_i.slider_local));
        let b_j0 = lj.through
            + lj.slider_rotation * splat_vec(&(self.mid_on_j - self.slide_j.slider_local));
        let conditioning = cross(&li.u, &lj.u).simd_abs();
        let pair = Pair::new(li.u, -lj.u, group)?;
        let (s_i, _) = pair.solve(&(b_j0 - b_i0));
        let b = b_i0 + li.u * s_i;
        let gi = links[self.slide_i.guide];
        let gj = links[self.slide_j.guide];
        let on_i = gi.material_point_at(&b);
        let on_j = gj.material_point_at(&b);
        let (mut sd_i, mut sd_j, mut sdd_i, mut sdd_j) =
            (T::zero(), T::zero(), T::zero(), T::zero());
        if motion {
            (sd_i, sd_j) = pair.solve(&(on_j.velocity - on_i.velocity));
            let two = splat::<T>(2.0);
            let rhs = on_j.acceleration + perp(&lj.u) * (two * gj.omega_rad_s * sd_j)
                - on_i.acceleration
                - perp(&li.u) * (two * gi.omega_rad_s * sd_i);
            (sdd_i, sdd_j) = pair.solve(&rhs);
        }
        let pb_i = riding_point(&on_i, &li.u, gi.omega_rad_s, sd_i, sdd_i);
        let pb_j = riding_point(&on_j, &lj.u, gj.omega_rad_s, sd_j, sdd_j);
        links[self.i] = LinkMotion::from_pin(
            li.slider_rotation,
            gi.omega_rad_s,
            gi.alpha_rad_s2,
            &self.mid_on_i,
            &pb_i,
        );
        links[self.j] = LinkMotion::from_pin(
            lj.slider_rotation,
            gj.omega_rad_s,
            gj.alpha_rad_s2,
            &self.mid_on_j,
            &pb_j,
        );
        Ok(GroupOk {
            margin: T::one(),
            conditioning,
        })
    }
}

/// The closed-form solver: a crank and a sequence of dyads.
#[derive(Clone, Debug, PartialEq)]
pub struct ClosedForm {
    pub(crate) groups: Vec<Group>,
    /// Inner joint point of each group (for names and branches).
    pub(crate) group_points: Vec<usize>,
    driver_link: usize,
    driver_on_link: Vec2,
    driver_pivot_world: Vec2,
    link_count: usize,
    ground: usize,
}

/// A joint seen from the decomposition.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum JointRef {
    Rev(usize),
    Pri(usize),
}

fn joint_links(m: &Mechanism, j: JointRef) -> (usize, usize) {
    match j {
        JointRef::Rev(r) => (m.revolutes[r].a, m.revolutes[r].b),
        JointRef::Pri(p) => (m.sliders[p].slider, m.sliders[p].guide),
    }
}

/// Local coordinates of a revolute's point on `link`.
fn rev_local(m: &Mechanism, r: usize, link: usize) -> Vec2 {
    let rv = &m.revolutes[r];
    if rv.a == link { rv.a_local } else { rv.b_local }
}

fn rev_pin(m: &Mechanism, r: usize, known: usize, unknown: usize) -> (Pin, Vec2) {
    (
        Pin {
            link: known,
            local: rev_local(m, r, known),
            on_ground: known == m.ground,
        },
        rev_local(m, r, unknown),
    )
}

fn link_len(
    m: &Mechanism,
    from: Vec2,
    to: Vec2,
    link: usize,
    what: &str,
) -> Result<(f64, UnitComplex<f64>)> {
    let v = to - from;
    let len = v.norm();
    if len <= 1e-12 * m.size_m {
        return Err(LinkageError::from(SceneProblem::DyadZeroLength {
            link: m.links[link].name.clone(),
            which: what.to_string(),
        }));
    }
    Ok((len, direction(&(v / len))))
}

impl ClosedForm {
    /// Decomposes the chain into dyads. Fails with [`LinkageError::NotDecomposable`]
    /// when it has none (then use [`crate::newton::Newton`]), or with
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
        while known.iter().any(|k| !k) {
            let mut found = None;
            'search: for (ji, &jij) in joints.iter().enumerate() {
                if used[ji] {
                    continue;
                }
                let (i, j) = joint_links(m, jij);
                if known[i] || known[j] {
                    continue;
                }
                let to_known = |l: usize| -> Vec<(usize, JointRef, usize)> {
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
                let unknown: Vec<_> = (0..m.links.len())
                    .filter(|&l| !known[l])
                    .map(|l| m.links[l].name.as_str())
                    .collect();
                return Err(LinkageError::NotDecomposable(format!(
                    "links {} form no RRR, RRP, RPR or PRP dyad on known links",
                    unknown.join(", ")
                )));
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
            return Err(LinkageError::NotDecomposable(format!(
                "the joint between `{}` and `{}` is redundant for a dyad chain",
                m.links[a].name, m.links[b].name
            )));
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

    /// Builds the group for unknown links `i`, `j` joined by `jij`, with one joint each
    /// to a known link; `None` when the combination has no closed form here.
    fn make_group(
        m: &Mechanism,
        i: usize,
        j: usize,
        jij: JointRef,
        ji: (usize, JointRef, usize),
        jj: (usize, JointRef, usize),
        provisional_branches: bool,
    ) -> Result<Option<(Group, usize)>> {
        use JointRef::{Pri, Rev};
        let branches = Branches {
            m,
            provisional: provisional_branches,
        };
        match (ji.1, jij, jj.1) {
            (Rev(ra), Rev(rm), Rev(rc)) => {
                rrr_group(m, &branches, (i, ra, ji.2), rm, (j, rc, jj.2)).map(Some)
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
            }
            (Rev(ra), Pri(p), Rev(rc)) => {
                rpr_group(m, &branches, i, (ra, ji.2), p, (rc, jj.2)).map(Some)
            }
            (Pri(pi), Rev(rm), Pri(pj)) => Ok(prp_group(m, (i, pi), rm, (j, pj))),
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

/// The scene's assembly branches, or while a pose is matched (`provisional`) any
/// valid branch of the right kind (`ClosedForm::match_pose` fixes it).
struct Branches<'a> {
    m: &'a Mechanism,
    provisional: bool,
}

impl Branches<'_> {
    /// The branch of the `kind` dyad whose inner joint is `point`.
    fn of(&self, point: usize, kind: DyadKind) -> Result<Branch> {
        match self.m.branch_for(point) {
            Some(b) => Ok(b.clone()),
            None if self.provisional && kind == DyadKind::Rrr => {
                Ok(Branch::Left(String::new(), String::new()))
            }
            None if self.provisional => Ok(Branch::Along),
            None => Err(LinkageError::from(SceneProblem::MissingBranch {
                kind,
                joint: self.m.points[point].name.clone(),
            })),
        }
    }

    /// An RRR dyad's sign: +1 on the left of its ends `pa` to `pc` as the branch
    /// names them.
    fn rrr_sign(&self, mid: usize, pa: usize, pc: usize) -> Result<f64> {
        let m = self.m;
        let names = |p: usize| m.points[p].name.clone();
        match self.of(mid, DyadKind::Rrr)? {
            Branch::Left(f, t) if f.is_empty() && t.is_empty() => Ok(1.0),
            Branch::Left(f, t) | Branch::Right(f, t) => {
                let left = if (&f, &t) == (&names(pa), &names(pc)) {
                    1.0
                } else if (&f, &t) == (&names(pc), &names(pa)) {
                    -1.0
                } else {
                    return Err(LinkageError::from(SceneProblem::BranchEnds {
                        joint: names(mid),
                        a: names(pa),
                        c: names(pc),
                    }));
                };
                Ok(if matches!(m.branch_for(mid), Some(Branch::Left(..))) {
                    left
                } else {
                    -left
                })
            }
            _ => Err(LinkageError::from(SceneProblem::BranchNotASide {
                joint: names(mid),
                a: names(pa),
                c: names(pc),
            })),
        }
    }

    /// A sliding dyad's sign: +1 Along, -1 Against; else a refusal that names the
    /// joint as `joint_kind` (how the user knows it).
    fn slide_sign(&self, point: usize, kind: DyadKind, joint_kind: &str) -> Result<f64> {
        match self.of(point, kind)? {
            Branch::Along => Ok(1.0),
            Branch::Against => Ok(-1.0),
            _ => Err(LinkageError::from(SceneProblem::BranchNotAlong {
                kind,
                joint_kind: joint_kind.to_string(),
                joint: self.m.points[point].name.clone(),
            })),
        }
    }
}

/// Three pins: link `i` pinned at `ra` to known link `ki`, link `j` at `rc` to `kj`,
/// and the two at `rm`.
fn rrr_group(
    m: &Mechanism,
    branches: &Branches<'_>,
    (i, ra, ki): (usize, usize, usize),
    rm: usize,
    (j, rc, kj): (usize, usize, usize),
) -> Result<(Group, usize)> {
    let (a, a_on_i) = rev_pin(m, ra, ki, i);
    let (c, c_on_j) = rev_pin(m, rc, kj, j);
    let (mid_on_i, mid_on_j) = (rev_local(m, rm, i), rev_local(m, rm, j));
    let (len_i, dir_i) = link_len(m, a_on_i, mid_on_i, i, "two")?;
    let (len_j, dir_j) = link_len(m, c_on_j, mid_on_j, j, "two")?;
    let mid = m.revolutes[rm].point;
    let (pa, pc) = (m.revolutes[ra].point, m.revolutes[rc].point);
    let sign = branches.rrr_sign(mid, pa, pc)?;
    let group = Group::Rrr(Rrr {
        i,
        j,
        a,
        a_on_i,
        mid_on_i,
        mid_on_j,
        c,
        c_on_j,
        len_i,
        len_j,
        inv_len_i: 1.0 / len_i,
        inv_len_j: 1.0 / len_j,
        dir_i_inv: dir_i.inverse(),
        dir_j_inv: dir_j.inverse(),
        sign,
        end_points: (pa, pc),
    });
    Ok((group, mid))
}

/// Pin, pin, slider: link `i` pinned at `ra` to known link `ki` and at `rm` to link
/// `j`, which slides in prismatic joint `p` on a known guide.
fn rrp_group(
    m: &Mechanism,
    branches: &Branches<'_>,
    (i, ra, ki): (usize, usize, usize),
    rm: usize,
    (j, p): (usize, usize),
) -> Result<Option<(Group, usize)>> {
    let slide = m.sliders[p].clone();
    if slide.slider != j {
        return Ok(None);
    }
    let (a, a_on_i) = rev_pin(m, ra, ki, i);
    let (mid_on_i, mid_on_j) = (rev_local(m, rm, i), rev_local(m, rm, j));
    let (len_i, dir_i) = link_len(m, a_on_i, mid_on_i, i, "two")?;
    let mid = m.revolutes[rm].point;
    let sign = branches.slide_sign(mid, DyadKind::Rrp, "slider joint")?;
    let group = Group::Rrp(Rrp {
        i,
        j,
        a,
        a_on_i,
        mid_on_j,
        len_i,
        inv_len_i: 1.0 / len_i,
        dir_i_inv: dir_i.inverse(),
        slide,
        sign,
    });
    Ok(Some((group, mid)))
}

/// A slider between two pins: prismatic joint `p` between its slider and guide, each
/// pinned to a known link (`i` pinned at `ra` to `ki`, the other at `rc` to `kc`).
fn rpr_group(
    m: &Mechanism,
    branches: &Branches<'_>,
    i: usize,
    (ra, ki): (usize, usize),
    p: usize,
    (rc, kc): (usize, usize),
) -> Result<(Group, usize)> {
    let slide = m.sliders[p].clone();
    let (s_rev, s_known, g_rev, g_known) = if slide.slider == i {
        (ra, ki, rc, kc)
    } else {
        (rc, kc, ra, ki)
    };
    let (s, s_on_slider) = rev_pin(m, s_rev, s_known, slide.slider);
    let (g, g_on_guide) = rev_pin(m, g_rev, g_known, slide.guide);
    let q_line = slide.through_local + slide.relative * (s_on_slider - slide.slider_local);
    let offset = cross(&slide.direction_local, &(g_on_guide - q_line));
    let sign = branches.slide_sign(slide.point, DyadKind::Rpr, "sliding joint")?;
    let group = Group::Rpr(Rpr {
        slider: slide.slider,
        s,
        s_on_slider,
        guide: slide.guide,
        g,
        g_on_guide,
        offset,
        dir_u: direction(&slide.direction_local),
        relative: slide.relative,
        sign,
    });
    Ok((group, slide.point))
}

/// A pin between two sliders: link `i` sliding in `pi`, link `j` in `pj`, pinned
/// together at `rm`; `None` unless each slides on a known guide.
fn prp_group(
    m: &Mechanism,
    (i, pi): (usize, usize),
    rm: usize,
    (j, pj): (usize, usize),
) -> Option<(Group, usize)> {
    let (si, sj) = (m.sliders[pi].clone(), m.sliders[pj].clone());
    let (si, sj) = if si.slider == i { (si, sj) } else { (sj, si) };
    if si.slider != i || sj.slider != j {
        return None;
    }
    let group = Group::Prp(Prp {
        i,
        j,
        mid_on_i: rev_local(m, rm, i),
        mid_on_j: rev_local(m, rm, j),
        slide_i: si,
        slide_j: sj,
    });
    Some((group, m.revolutes[rm].point))
}
