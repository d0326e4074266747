//! The joints as the decomposition sees them: which links a joint joins, a pin on
//! its link, a link's length between two joints.

use nalgebra::UnitComplex;

use super::parts::{Pin, direction};
use crate::error::{LinkageError, Result};
use crate::ids::LinkId;
use crate::model::Mechanism;
use crate::model::SceneProblem;
use crate::motion::Vec2;

/// A joint seen from the decomposition.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum JointRef {
    Rev(usize),
    Pri(usize),
}

pub(super) fn joint_links(m: &Mechanism, j: JointRef) -> (LinkId, LinkId) {
    match j {
        JointRef::Rev(r) => (m.revolutes[r].a, m.revolutes[r].b),
        JointRef::Pri(p) => (m.sliders[p].slider, m.sliders[p].guide),
    }
}

/// Local coordinates of a revolute's point on `link`.
pub(super) fn rev_local(m: &Mechanism, r: usize, link: LinkId) -> Vec2 {
    let rv = &m.revolutes[r];
    if rv.a == link { rv.a_local } else { rv.b_local }
}

pub(super) fn rev_pin(m: &Mechanism, r: usize, known: LinkId, unknown: LinkId) -> (Pin, Vec2) {
    (
        Pin {
            link: known,
            local: rev_local(m, r, known),
            on_ground: known == m.ground,
        },
        rev_local(m, r, unknown),
    )
}

pub(super) fn link_len(
    m: &Mechanism,
    from: Vec2,
    to: Vec2,
    link: LinkId,
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
