//! Force polygons: graphical kinetostatics as the textbooks work it. The chain is
//! taken apart into its Assur groups and solved from the output back to the crank,
//! one group at a time: the group's known forces (external loads, weights,
//! d'Alembert inertia forces, the reactions of the groups already solved) and its
//! unknown outer reactions form one closed polygon, the inner joint's reaction is its
//! diagonal, and the crank's balancing torque closes the last stage.
//!
//! Each stage solves only its own equilibrium (three equations per link, moments
//! about the stage's own joint), so its reactions are an independent check of the
//! whole-chain Newton–Euler solution of [`crate::kinetostatics`].

mod parts;
mod stage;
mod symbol;

use crate::error::{LinkageError, Result};
use crate::ids::LinkId;
use crate::kinetostatics::Kinetostatics;
use crate::solve::Kinematics;

pub use parts::{CoupleTerm, ForcePolygons, ForceVector, JointForce, JointId, Stage, StagePolygon};
pub use symbol::{CoupleSymbol, ForceSymbol, SymbolParts, link_number};

/// The force polygons of the scene of `k` at `input_rad` and the scene's crank
/// speed. `ks` solves the motion (and checks the position: a dead point of the input
/// is refused as by [`Kinetostatics::at`]).
///
/// # Errors
/// A chain that is not a crank and dyads (solved by Newton alone), a position where
/// the chain does not assemble or a stage's reactions are indeterminate.
pub fn force_polygons(
    k: &mut Kinematics,
    ks: &mut Kinetostatics,
    input_rad: f64,
) -> Result<ForcePolygons> {
    let Some(cf) = k.closed_form() else {
        return Err(LinkageError::NotDecomposable(
            crate::error::Undecomposable::ForcePolygonsNeedDyads,
        ));
    };
    let groups: Vec<(LinkId, LinkId)> = cf.groups.iter().map(|g| g.links()).collect();
    ks.at(k, input_rad)?;
    let m = k.mechanism();
    let mut solver = stage::Stages::new(m, ks.solution(), ks.forces());
    let mut stages = Vec::with_capacity(groups.len() + 1);
    for (index, &(i, j)) in groups.iter().enumerate().rev() {
        let dyad = k.dyad(index).expect("a closed-form chain names its groups");
        // A cam's follower is a stage of one link: its pin and the cam's push.
        let links: &[LinkId] = if i == j { &[i] } else { &[i, j] };
        stages.push(solver.solve(Stage::Group { index, dyad }, links, input_rad)?);
    }
    let link = m.driver.link;
    stages.push(solver.solve(Stage::Crank { link }, &[link], input_rad)?);
    Ok(ForcePolygons {
        input_rad,
        stages,
        balancing_torque: solver.balancing_torque(),
        joints: solver.joint_forces(),
    })
}
