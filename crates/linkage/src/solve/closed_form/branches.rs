//! The assembly branch of each dyad, from the scene (or any branch while a pose is
//! matched), and the sign it gives the dyad's solution.

use crate::dyad::DyadKind;
use crate::error::{LinkageError, Result};
use crate::ids::PointId;
use crate::model::Mechanism;
use crate::model::SceneProblem;
use crate::scene::Branch;

/// The scene's assembly branches, or while a pose is matched (`provisional`) any
/// valid branch of the right kind (`ClosedForm::match_pose` fixes it).
pub(super) struct Branches<'a> {
    pub(super) m: &'a Mechanism,
    pub(super) provisional: bool,
}

impl Branches<'_> {
    /// The branch of the `kind` dyad whose inner joint is `point`.
    pub(super) fn of(&self, point: PointId, kind: DyadKind) -> Result<Branch> {
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
    pub(super) fn rrr_sign(&self, mid: PointId, pa: PointId, pc: PointId) -> Result<f64> {
        let m = self.m;
        let names = |p: PointId| m.points[p].name.clone();
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
    pub(super) fn slide_sign(
        &self,
        point: PointId,
        kind: DyadKind,
        joint_kind: &str,
    ) -> Result<f64> {
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
