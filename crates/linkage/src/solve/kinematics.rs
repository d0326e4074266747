//! The kinematics facade: one mechanism, one chosen solver path, solutions with
//! named errors (the reachable input range included when a chain cannot assemble).

use crate::assembly::AssemblyRanges;
use crate::dyad::{DyadLabel, GroupLabel, Shortfall};
use crate::error::{AssemblyFailure, LinkageError, Result};
use crate::ids::LinkId;
use crate::model::Mechanism;
use crate::model::SceneProblem;
use crate::motion::{LinkMotion, Solution};
use crate::real::{LANES, Lanes};
use crate::scene::SolverPath;
use crate::solve::LaneSolution;
use crate::solve::Newton;
use crate::solve::{ClosedForm, Failure, finish_solution};

/// The solver path in use; serialized as its label.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum PathKind {
    /// Closed-form Assur dyads.
    #[serde(rename = "closed form")]
    ClosedForm,
    /// Newton–Raphson on the loop-closure constraints.
    Newton,
}

impl PathKind {
    /// Human-readable name.
    pub fn label(self) -> &'static str {
        match self {
            Self::ClosedForm => "closed form",
            Self::Newton => "Newton",
        }
    }
}

/// A mechanism ready to be solved at any input.
#[derive(Clone, Debug)]
pub struct Kinematics {
    mech: Mechanism,
    closed: Option<ClosedForm>,
    newton: Option<Newton>,
    path: PathKind,
    scratch: Vec<LinkMotion>,
}

impl Kinematics {
    /// Uses the path the scene asks for (`Auto`: closed form when the chain decomposes).
    pub fn new(mech: Mechanism) -> Result<Self> {
        let path = mech.solver.path;
        Self::with_path(mech, path)
    }

    /// Uses the given path.
    pub fn with_path(mech: Mechanism, path: SolverPath) -> Result<Self> {
        let closed = match ClosedForm::new(&mech) {
            Ok(c) => Some(c),
            Err(LinkageError::NotDecomposable(why)) => {
                if path == SolverPath::ClosedForm {
                    return Err(LinkageError::NotDecomposable(why));
                }
                None
            }
            Err(e) => return Err(e),
        };
        let scratch = vec![LinkMotion::default(); mech.links.len()];
        let mut k = Self {
            mech,
            closed,
            newton: None,
            path: PathKind::ClosedForm,
            scratch,
        };
        if path == SolverPath::Newton || k.closed.is_none() {
            let mut newton = k.build_newton()?;
            if k.closed.is_none() {
                let start = k.mech.driver.start_rad;
                let dof = newton.mobility(start, &mut k.scratch);
                if dof != 1 {
                    return Err(LinkageError::from(SceneProblem::RedundantJoints { dof }));
                }
                // No margins to find the assembly range on: trace the branch to its
                // folds instead, and keep every later solve inside what was found.
                newton.trace_range(&mut k.scratch)?;
            }
            k.newton = Some(newton);
            k.path = PathKind::Newton;
        }
        Ok(k)
    }

    fn build_newton(&mut self) -> Result<Newton> {
        let start = self.mech.driver.start_rad;
        let mut pose = vec![LinkMotion::default(); self.mech.links.len()];
        if let Some(cf) = &self.closed {
            cf.solve_links(start, 0.0, &mut pose)
                .map_err(|f| self.describe(f, start))?;
        } else {
            for l in self.mech.moving_links() {
                let (origin, angle) = self.mech.guess[l].ok_or_else(|| {
                    LinkageError::NotDecomposable(crate::error::Undecomposable::NeedsGuess {
                        link: self.mech.links[l].name.clone(),
                    })
                })?;
                pose[l].origin.position = origin;
                pose[l].rotation = nalgebra::UnitComplex::new(angle);
            }
            let d = self.mech.driver.link;
            pose[d].rotation = nalgebra::UnitComplex::new(start);
        }
        Newton::new(
            &self.mech,
            &pose,
            self.mech.solver.tolerance,
            self.mech.solver.max_iterations,
        )
    }

    /// The same chain driven by `link` instead, a link with a revolute joint to
    /// ground, in the assembly of `pose` (a solved pose of this chain): every branch is
    /// read off the pose. The new input is `link`'s angle. Used to integrate dynamics
    /// through a dead point of the scene's input, where another link's angle is
    /// regular.
    ///
    /// # Errors
    /// [`LinkageError::NotACoordinate`] when `link` has no revolute joint to ground.
    pub fn redriven(&self, link: LinkId, pose: &Solution) -> Result<Self> {
        let m = &self.mech;
        let pivot = m
            .ground_pivot_of(link)
            .ok_or_else(|| LinkageError::NotACoordinate {
                link: m
                    .links
                    .get(link.index())
                    .map_or_else(|| format!("#{}", link.index()), |l| l.name.clone()),
                candidates: m
                    .moving_links()
                    .filter(|&l| m.ground_pivot_of(l).is_some())
                    .map(|l| m.links[l].name.clone())
                    .collect(),
            })?;
        let mut mech = m.clone();
        let input = pose.links[link].angle_rad();
        mech.driver.link = link;
        mech.driver.pivot = pivot;
        mech.driver.start_rad = input;
        mech.driver.speed_rad_s = 1.0;
        // The scene's branches belong to the old decomposition; the new one reads its
        // own off the pose.
        mech.branches.clear();
        let closed = match ClosedForm::new_without_branches(&mech) {
            Ok(mut cf) => {
                cf.match_pose(input, &pose.links);
                Some(cf)
            }
            Err(LinkageError::NotDecomposable(_)) => None,
            Err(e) => return Err(e),
        };
        let newton = match (&closed, self.path) {
            (Some(_), PathKind::ClosedForm) => None,
            _ => Some(Newton::new(
                &mech,
                &pose.links,
                mech.solver.tolerance,
                mech.solver.max_iterations,
            )?),
        };
        Ok(Self {
            scratch: vec![LinkMotion::default(); mech.links.len()],
            path: if newton.is_some() {
                PathKind::Newton
            } else {
                PathKind::ClosedForm
            },
            mech,
            closed,
            newton,
        })
    }

    /// The mechanism.
    pub fn mechanism(&self) -> &Mechanism {
        &self.mech
    }

    /// The path in use.
    pub fn path(&self) -> PathKind {
        self.path
    }

    /// Whether a closed-form decomposition exists (needed for assembly ranges).
    pub fn has_closed_form(&self) -> bool {
        self.closed.is_some()
    }

    /// A solution buffer of the right sizes.
    pub fn empty_solution(&self) -> Solution {
        Solution {
            links: vec![LinkMotion::default(); self.mech.links.len()],
            points: vec![Default::default(); self.mech.points.len()],
            slides: vec![Default::default(); self.mech.sliders.len()],
            ..Default::default()
        }
    }

    /// Solves at `input_rad` with the scene's crank speed.
    pub fn solve(&mut self, input_rad: f64) -> Result<Solution> {
        let mut s = self.empty_solution();
        self.solve_into(input_rad, self.mech.driver.speed_rad_s, &mut s)?;
        Ok(s)
    }

    /// Solves at `input_rad` turning at `speed_rad_s` into `out` (no allocation when
    /// `out` came from [`Self::empty_solution`]).
    pub fn solve_into(
        &mut self,
        input_rad: f64,
        speed_rad_s: f64,
        out: &mut Solution,
    ) -> Result<()> {
        if !input_rad.is_finite() || !speed_rad_s.is_finite() {
            let (param, value) = if input_rad.is_finite() {
                (crate::error::Param::InputSpeed, speed_rad_s)
            } else {
                (crate::error::Param::InputAngle, input_rad)
            };
            return Err(LinkageError::invalid(
                param,
                value,
                crate::error::Valid::Finite,
            ));
        }
        if out.links.len() != self.mech.links.len() {
            *out = self.empty_solution();
        }
        // `out` is the caller's: make sure its ground is at rest, as the solvers expect.
        out.links[self.mech.ground] = LinkMotion::default();
        let conditioning = match (self.path, &self.closed, &mut self.newton) {
            (PathKind::ClosedForm, Some(cf), _) => cf
                .solve_links(input_rad, speed_rad_s, &mut out.links)
                .map_err(|f| self.describe(f, input_rad))?,
            (_, _, Some(nw)) => nw
                .solve_links(input_rad, speed_rad_s, &mut out.links)
                .map_err(|e| {
                    if let (
                        LinkageError::Singular { .. } | LinkageError::NewtonDiverged { .. },
                        Some(cf),
                    ) = (&e, &self.closed)
                    {
                        let mut links = vec![LinkMotion::default(); self.mech.links.len()];
                        if let Err(f) = cf.solve_links(input_rad, 0.0, &mut links) {
                            return self.describe(f, input_rad);
                        }
                    }
                    e
                })?,
            // Not reachable through `new`/`with_path`, which always build the solver of
            // the path they pick; an error rather than a panic all the same.
            _ => {
                return Err(LinkageError::NotDecomposable(
                    crate::error::Undecomposable::NoSolver {
                        newton: self.path == PathKind::Newton,
                    },
                ));
            }
        };
        out.input_rad = input_rad;
        out.input_speed_rad_s = speed_rad_s;
        out.conditioning = conditioning;
        finish_solution(&self.mech, &out.links, &mut out.points, &mut out.slides);
        Ok(())
    }

    /// A lane solution buffer of the right sizes.
    pub fn empty_lane_solution(&self) -> LaneSolution {
        LaneSolution {
            links: vec![Default::default(); self.mech.links.len()],
            points: vec![Default::default(); self.mech.points.len()],
            slides: vec![Default::default(); self.mech.sliders.len()],
            ground: self.mech.ground,
            ..Default::default()
        }
    }

    /// Solves [`LANES`] inputs at once, turning at `speed_rad_s`, into `out`: lane `k`
    /// holds input `inputs[k]`. On the closed-form path all lanes go through the
    /// dyads together in SIMD lanes, which is how a cycle is solved fastest; the
    /// Newton path follows its branch by continuation, so it solves lane by lane.
    ///
    /// # Errors
    /// The error of the first input (in lane order) that [`Self::solve_into`] would
    /// refuse, with the same message.
    pub fn solve_lanes(
        &mut self,
        inputs: [f64; LANES],
        speed_rad_s: f64,
        out: &mut LaneSolution,
    ) -> Result<()> {
        if out.links.len() != self.mech.links.len() || out.ground != self.mech.ground {
            *out = self.empty_lane_solution();
        }
        let finite = speed_rad_s.is_finite() && inputs.iter().all(|x| x.is_finite());
        if let (PathKind::ClosedForm, Some(cf), true) = (self.path, &self.closed, finite)
            && let Ok(conditioning) =
                cf.solve_links(Lanes::from(inputs), speed_rad_s, &mut out.links)
        {
            out.inputs = inputs;
            out.input_speed_rad_s = speed_rad_s;
            out.conditioning = conditioning.0.to_array();
            finish_solution(&self.mech, &out.links, &mut out.points, &mut out.slides);
            return Ok(());
        }
        // Newton, or a lane that fails: one at a time, so that the error names the
        // input and its cause exactly as a single solve does.
        let mut one = self.empty_solution();
        for (k, x) in inputs.into_iter().enumerate() {
            self.solve_into(x, speed_rad_s, &mut one)?;
            out.set_lane(k, &one);
        }
        Ok(())
    }

    /// Assembly margin at `input_rad` (> 0 assembles), closed form only.
    pub fn assembly_margin(&mut self, input_rad: f64) -> Option<f64> {
        let cf = self.closed.as_ref()?;
        Some(cf.margin(input_rad, &mut self.scratch).0)
    }

    /// The group that closes worst at `input_rad`, closed form only: what a length
    /// edit needs to know whether the chain still assembles, without solving it or
    /// wording an error.
    pub fn closure(&mut self, input_rad: f64) -> Option<Closure> {
        let cf = self.closed.as_ref()?;
        let (margin, group) = cf.margin(input_rad, &mut self.scratch);
        Some(Closure {
            margin,
            group,
            // Within the tangency slack a group closes, collinear (a solve there is
            // refused as singular, but the chain is not coming apart).
            assembles: margin >= -crate::solve::TANGENT_SLACK,
        })
    }

    /// Per-group velocity conditioning at `input_rad`, with the groups' names.
    pub fn group_conditioning(&mut self, input_rad: f64) -> Vec<(String, f64)> {
        let values = self.group_conditioning_values(input_rad);
        (0..values.len())
            .map(|g| (self.group_name(g).to_string(), values[g]))
            .collect()
    }

    /// [`Self::group_conditioning`] without the names, for scans that evaluate it
    /// many times (the names are formatted strings).
    pub(crate) fn group_conditioning_values(&mut self, input_rad: f64) -> Vec<f64> {
        match &self.closed {
            Some(cf) => cf.group_conditioning(input_rad, &mut self.scratch),
            None => Vec::new(),
        }
    }

    /// Number of closed-form groups (0 on the Newton-only path).
    pub fn group_count(&self) -> usize {
        self.closed.as_ref().map_or(0, |c| c.groups.len())
    }

    /// The traced assembly range of a chain without a closed form, unwrapped and
    /// holding the start input; `None` when it turns fully or has a closed form.
    pub fn traced_range(&self) -> Option<[f64; 2]> {
        self.newton
            .as_ref()
            .filter(|_| self.closed.is_none())?
            .range()
    }

    pub(crate) fn closed_form(&self) -> Option<&ClosedForm> {
        self.closed.as_ref()
    }

    /// Group `g` as a report names it: its dyad, or its number in a chain without a
    /// closed form.
    pub fn group_name(&self, g: usize) -> GroupLabel {
        self.dyad(g)
            .map_or(GroupLabel::Numbered(g), GroupLabel::Dyad)
    }

    /// Group `g` of the closed-form decomposition as its user knows it; `None` in a
    /// chain solved by Newton alone.
    pub fn dyad(&self, g: usize) -> Option<DyadLabel> {
        let cf = self.closed.as_ref()?;
        let group = &cf.groups[g];
        let (i, j) = group.links();
        Some(DyadLabel {
            kind: group.kind(),
            links: [
                self.mech.links[i].name.clone(),
                self.mech.links[j].name.clone(),
            ],
            inner_point: self.mech.points[cf.group_points[g]].name.clone(),
        })
    }

    /// The input intervals over which the chain assembles on its branch: of a
    /// closed-form chain by root-finding on the groups' margins; of a chain solved by
    /// Newton alone, the range its branch was traced over (between folds) when it was
    /// built.
    pub fn assembly_ranges(&self) -> AssemblyRanges {
        match (&self.closed, self.traced_range()) {
            (Some(cf), _) => cf.assembly_ranges(self.mech.links.len()),
            (None, Some([lo, hi])) => AssemblyRanges::between(lo, hi),
            (None, None) => AssemblyRanges::full_turn(),
        }
    }

    /// How group `g` of the closed-form decomposition falls short of closing at
    /// `input_rad` (the groups before it close there), as its user knows it; `None`
    /// in a chain solved by Newton alone, or a group whose failure is no distance.
    pub fn shortfall(&self, input_rad: f64, g: usize) -> Option<Shortfall> {
        self.closed.as_ref()?.shortfall(&self.mech, input_rad, g)
    }

    fn describe(&self, f: Failure, input_rad: f64) -> LinkageError {
        match f {
            Failure::CannotAssemble { group, margin } => LinkageError::CannotAssemble {
                input_deg: input_rad.to_degrees(),
                reason: match self.dyad(group) {
                    Some(dyad) => AssemblyFailure::DyadOpen {
                        dyad: Box::new(dyad),
                        margin,
                        shortfall: self.shortfall(input_rad, group).map(Box::new),
                    },
                    None => AssemblyFailure::Nowhere,
                },
                reachable: self.assembly_ranges(),
            },
            Failure::Singular { group } => LinkageError::Singular {
                input_deg: input_rad.to_degrees(),
                reason: match self.dyad(group) {
                    Some(d) => crate::error::Singularity::DyadInLine {
                        links: d.links,
                        point: d.inner_point,
                    },
                    None => crate::error::Singularity::DeadPoint,
                },
            },
        }
    }
}

/// How well the worst group of a closed-form chain closes at one input.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Closure {
    /// Its assembly margin (dimensionless; > 0 closes, < 0 how far from closing).
    pub margin: f64,
    /// The group, as [`Kinematics::group_name`] names it.
    pub group: usize,
    /// Whether the chain closes (the margin is above the solver's tangency slack; at a
    /// margin of about zero the pose is singular).
    pub assembles: bool,
}
