//! One stage of the graphical kinetostatics solved on its own: the equilibrium of its
//! links (force and moment about the stage's first joint) for the reactions of the
//! joints not yet solved, with the reactions of the stages solved before it as known
//! loads.

use nalgebra::{DMatrix, DVector};

use super::parts::{CoupleTerm, ForceVector, JointForce, JointId, Stage, StagePolygon};
use super::symbol::{CoupleSymbol, ForceSymbol};
use crate::dynamics::{Action, ForceModel, InertiaTerm, LoadTerm};
use crate::error::{LinkageError, Result};
use crate::ids::{LinkId, PointId};
use crate::model::Mechanism;
use crate::motion::{Solution, Vec2, cross, perp};

/// A joint's reaction: the force on its second link from its first, and the couple
/// (prismatic joints only).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Reaction {
    force: Vec2,
    couple: f64,
}

/// The stages' shared state: the loads, and the reactions solved so far.
pub(super) struct Stages<'a> {
    m: &'a Mechanism,
    sol: &'a Solution,
    loads: Vec<LoadTerm>,
    inertia: Vec<InertiaTerm>,
    joints: Vec<JointId>,
    solved: Vec<Option<Reaction>>,
    torque: f64,
}

impl<'a> Stages<'a> {
    pub(super) fn new(m: &'a Mechanism, sol: &'a Solution, forces: &ForceModel) -> Self {
        let mut joints: Vec<JointId> = (0..m.revolutes.len()).map(JointId::Revolute).collect();
        joints.extend((0..m.sliders.len()).map(JointId::Prismatic));
        joints.extend((0..m.cams.len()).map(JointId::Cam));
        Self {
            m,
            sol,
            loads: forces.load_terms(sol),
            inertia: forces.inertia_terms(sol),
            solved: vec![None; joints.len()],
            joints,
            torque: 0.0,
        }
    }

    /// The joint's (first, second) links: a revolute's (a, b), a prismatic joint's
    /// (guide, slider), a cam contact's (cam, follower).
    fn ends(&self, j: JointId) -> (LinkId, LinkId) {
        match j {
            JointId::Revolute(r) => (self.m.revolutes[r].a, self.m.revolutes[r].b),
            JointId::Prismatic(p) => (self.m.sliders[p].guide, self.m.sliders[p].slider),
            JointId::Cam(c) => (self.m.cams[c].cam, self.m.cams[c].follower),
        }
    }

    fn point(&self, j: JointId) -> PointId {
        match j {
            JointId::Revolute(r) => self.m.revolutes[r].point,
            JointId::Prismatic(p) => self.m.sliders[p].point,
            // The push acts along the common normal, which runs through the roller's
            // centre.
            JointId::Cam(c) => self.m.cams[c].roller,
        }
    }

    /// The unit loads of a joint's unknowns on its second link: (force, couple) per
    /// unknown: x and y of a revolute; the guide's normal force and its couple; a
    /// cam's push along the common normal.
    fn unit_loads(&self, j: JointId) -> Vec<(Vec2, f64)> {
        match j {
            JointId::Revolute(_) => vec![(Vec2::x(), 0.0), (Vec2::y(), 0.0)],
            JointId::Prismatic(p) => {
                let normal = perp(&self.m.sliders[p].direction(&self.sol.links));
                vec![(normal, 0.0), (Vec2::zeros(), 1.0)]
            }
            JointId::Cam(c) => {
                let cam = &self.m.cams[c];
                vec![(cam.contact(self.sol.links[cam.cam].angle_rad()).normal, 0.0)]
            }
        }
    }

    /// The first column of each unknown joint's unknowns, and the column count.
    fn columns(&self, unknown: &[usize]) -> (Vec<usize>, usize) {
        let mut first = Vec::with_capacity(unknown.len());
        let mut count = 0;
        for &n in unknown {
            first.push(count);
            count += self.unit_loads(self.joints[n]).len();
        }
        (first, count)
    }

    /// Solves the stage of `links`: the joints on them not yet solved, and on the
    /// crank the balancing torque.
    pub(super) fn solve(
        &mut self,
        stage: Stage,
        links: &[LinkId],
        input_rad: f64,
    ) -> Result<StagePolygon> {
        let crank = matches!(stage, Stage::Crank { .. });
        let unknown: Vec<usize> = (0..self.joints.len())
            .filter(|&n| self.solved[n].is_none())
            .filter(|&n| {
                let (a, b) = self.ends(self.joints[n]);
                links.contains(&a) || links.contains(&b)
            })
            .collect();
        let (first_column, joint_columns) = self.columns(&unknown);
        let columns = joint_columns + usize::from(crank);
        if columns != 3 * links.len() {
            return Err(LinkageError::NotDecomposable(
                crate::error::Undecomposable::ForceStage {
                    links: links.len(),
                    unknowns: columns,
                },
            ));
        }
        let origin = unknown.first().map_or_else(
            || self.sol.links[links[0]].origin.position,
            |&n| self.sol.points[self.point(self.joints[n])].position,
        );
        let (a, b) = self.system(links, &unknown, &first_column, crank, origin);
        let x = a.lu().solve(&b).ok_or_else(|| LinkageError::Singular {
            input_deg: input_rad.to_degrees(),
            reason: crate::error::Singularity::GroupReactions,
        })?;
        for (c, &n) in unknown.iter().enumerate() {
            let units = self.unit_loads(self.joints[n]);
            let mut r = Reaction::default();
            for (k, (f, m)) in units.iter().enumerate() {
                r.force += f * x[first_column[c] + k];
                r.couple += m * x[first_column[c] + k];
            }
            self.solved[n] = Some(r);
        }
        if crank {
            self.torque = x[columns - 1];
        }
        Ok(self.polygon(stage, links, &unknown))
    }

    /// The stage's equations: per link Σ F = 0 and Σ M about `origin` = 0 with the
    /// d'Alembert forces, unknowns in the columns, known loads on the right.
    fn system(
        &self,
        links: &[LinkId],
        unknown: &[usize],
        first_column: &[usize],
        crank: bool,
        origin: Vec2,
    ) -> (DMatrix<f64>, DVector<f64>) {
        let n = 3 * links.len();
        let mut a = DMatrix::<f64>::zeros(n, n);
        let mut b = DVector::<f64>::zeros(n);
        let row = |l: LinkId| links.iter().position(|&x| x == l).map(|i| 3 * i);
        for (c, &j) in unknown.iter().enumerate() {
            let joint = self.joints[j];
            let (first, second) = self.ends(joint);
            let p = self.sol.points[self.point(joint)].position - origin;
            for (k, (f, m)) in self.unit_loads(joint).into_iter().enumerate() {
                let col = first_column[c] + k;
                for (link, sign) in [(second, 1.0), (first, -1.0)] {
                    if let Some(r) = row(link) {
                        a[(r, col)] += sign * f.x;
                        a[(r + 1, col)] += sign * f.y;
                        a[(r + 2, col)] += sign * (cross(&p, &f) + m);
                    }
                }
            }
        }
        if crank && let Some(r) = row(links[0]) {
            a[(r + 2, n - 1)] = 1.0;
        }
        for &link in links {
            let r = row(link).unwrap_or(0);
            for f in self.known_forces(link) {
                b[r] -= f.force.x;
                b[r + 1] -= f.force.y;
                b[r + 2] -= cross(&(f.at - origin), &f.force);
            }
            for c in self.known_couples(link) {
                b[r + 2] -= c.moment;
            }
        }
        (a, b)
    }

    /// The forces on `link` known before its stage: loads, its inertia force, and the
    /// reactions of the joints already solved.
    fn known_forces(&self, link: LinkId) -> Vec<ForceVector> {
        let known = |symbol, force, at| ForceVector {
            symbol,
            force,
            at,
            magnitude_known: true,
            direction_known: true,
        };
        let mut out = Vec::new();
        for t in self.loads.iter().filter(|t| t.link == link) {
            if let Action::Force { at, force, .. } = t.action {
                let symbol = ForceSymbol::Load {
                    link,
                    source: t.source,
                };
                out.push(known(symbol, force, at));
            }
        }
        for t in self.inertia.iter().filter(|t| t.link == link) {
            out.push(known(ForceSymbol::Inertia { link }, t.force, t.at));
        }
        for (n, r) in self.solved.iter().enumerate() {
            if let Some(r) = r
                && let Some(f) = self.reaction_on(self.joints[n], *r, link)
            {
                out.push(f);
            }
        }
        out.retain(|f| f.force != Vec2::zeros());
        out
    }

    /// The couples on `link` known before its stage.
    fn known_couples(&self, link: LinkId) -> Vec<CoupleTerm> {
        let mut out = Vec::new();
        for t in self.loads.iter().filter(|t| t.link == link) {
            if let Action::Couple { moment } = t.action {
                let symbol = CoupleSymbol::Load {
                    link,
                    source: t.source,
                };
                out.push(CoupleTerm {
                    symbol,
                    link,
                    moment,
                    known: true,
                });
            }
        }
        for t in self.inertia.iter().filter(|t| t.link == link) {
            let symbol = CoupleSymbol::Inertia { link };
            out.push(CoupleTerm {
                symbol,
                link,
                moment: t.couple,
                known: true,
            });
        }
        for (n, r) in self.solved.iter().enumerate() {
            if let Some(r) = r
                && let Some(c) = self.guide_couple_on(self.joints[n], *r, link)
            {
                out.push(c);
            }
        }
        out.retain(|c| c.moment != 0.0);
        out
    }

    /// A solved joint's force on `link`, if the joint is on it.
    fn reaction_on(&self, joint: JointId, r: Reaction, link: LinkId) -> Option<ForceVector> {
        let (first, second) = self.ends(joint);
        let (from, force) = if link == second {
            (first, r.force)
        } else if link == first {
            (second, -r.force)
        } else {
            return None;
        };
        let point = self.point(joint);
        Some(ForceVector {
            symbol: ForceSymbol::Reaction {
                from,
                on: link,
                point,
            },
            force,
            at: self.sol.points[point].position,
            magnitude_known: true,
            direction_known: true,
        })
    }

    /// A solved prismatic joint's couple on `link`, if the joint is on it.
    fn guide_couple_on(&self, joint: JointId, r: Reaction, link: LinkId) -> Option<CoupleTerm> {
        let JointId::Prismatic(_) = joint else {
            return None;
        };
        let (first, second) = self.ends(joint);
        let (from, moment) = if link == second {
            (first, r.couple)
        } else if link == first {
            (second, -r.couple)
        } else {
            return None;
        };
        Some(CoupleTerm {
            symbol: CoupleSymbol::Guide { from, on: link },
            link,
            moment,
            known: true,
        })
    }

    /// The stage's polygon once its reactions are solved.
    fn polygon(&self, stage: Stage, links: &[LinkId], unknown: &[usize]) -> StagePolygon {
        let is_inner = |n: usize| {
            let (a, b) = self.ends(self.joints[n]);
            links.contains(&a) && links.contains(&b)
        };
        let solved_here = |link: LinkId| -> Vec<ForceVector> {
            unknown
                .iter()
                .filter(|&&n| !is_inner(n))
                .filter_map(|&n| {
                    let joint = self.joints[n];
                    let r = self.solved[n]?;
                    let mut f = self.reaction_on(joint, r, link)?;
                    f.magnitude_known = false;
                    f.direction_known = matches!(joint, JointId::Prismatic(_) | JointId::Cam(_));
                    Some(f)
                })
                .collect()
        };
        // Known forces exclude this stage's own joints, solved a moment ago.
        let known = |link: LinkId| -> Vec<ForceVector> {
            self.known_forces(link)
                .into_iter()
                .filter(|f| !self.is_stage_reaction(f, unknown))
                .collect()
        };
        let first = links[0];
        let mut polygon = Vec::new();
        let mut inner = None;
        if let Some(&second) = links.get(1) {
            polygon.extend(solved_here(first));
            polygon.extend(known(first));
            let first_sum = polygon.iter().fold(Vec2::zeros(), |s, f| s + f.force);
            polygon.extend(known(second));
            polygon.extend(solved_here(second));
            inner = unknown.iter().find(|&&n| is_inner(n)).map(|&n| {
                let point = self.point(self.joints[n]);
                ForceVector {
                    symbol: ForceSymbol::Reaction {
                        from: first,
                        on: second,
                        point,
                    },
                    force: first_sum,
                    at: self.sol.points[point].position,
                    magnitude_known: false,
                    direction_known: false,
                }
            });
        } else {
            // The crank: its known forces, then the frame's reaction closing them.
            polygon.extend(known(first));
            polygon.extend(solved_here(first));
        }
        StagePolygon {
            stage,
            links: links.to_vec(),
            polygon,
            inner,
            couples: self.stage_couples(links, unknown),
        }
    }

    /// Whether `f` is the reaction of one of this stage's joints.
    fn is_stage_reaction(&self, f: &ForceVector, unknown: &[usize]) -> bool {
        let ForceSymbol::Reaction { point, from, on } = f.symbol else {
            return false;
        };
        unknown
            .iter()
            .any(|&n| self.point(self.joints[n]) == point && self.between(n, from, on))
    }

    /// Whether joint `n` joins links `x` and `y` (either way round).
    fn between(&self, n: usize, x: LinkId, y: LinkId) -> bool {
        let (a, b) = self.ends(self.joints[n]);
        (a, b) == (x, y) || (b, a) == (x, y)
    }

    /// The couples on the stage's links: loads and inertia, the guides' couples
    /// (this stage's are solved by now), and on the crank the balancing torque.
    fn stage_couples(&self, links: &[LinkId], unknown: &[usize]) -> Vec<CoupleTerm> {
        let mut out: Vec<CoupleTerm> = links.iter().flat_map(|&l| self.known_couples(l)).collect();
        for c in &mut out {
            if let CoupleSymbol::Guide { from, on } = c.symbol {
                c.known = !unknown.iter().any(|&n| self.between(n, from, on));
            }
        }
        if links == [self.m.driver.link] {
            out.push(CoupleTerm {
                symbol: CoupleSymbol::Balancing,
                link: links[0],
                moment: self.torque,
                known: false,
            });
        }
        out
    }

    /// The balancing torque, once the crank's stage is solved.
    pub(super) fn balancing_torque(&self) -> f64 {
        self.torque
    }

    /// Every joint's reaction (zero where a stage left one unsolved).
    pub(super) fn joint_forces(&self) -> Vec<JointForce> {
        self.joints
            .iter()
            .zip(&self.solved)
            .map(|(&joint, r)| {
                let r = r.unwrap_or_default();
                JointForce {
                    joint,
                    point: self.point(joint),
                    force: r.force,
                    couple: r.couple,
                }
            })
            .collect()
    }
}
