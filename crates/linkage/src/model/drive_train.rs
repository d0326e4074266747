//! A drive's gear train reduced to the crank: the ratio of the motor's member to the
//! crank's, and every member's speed and inertia per crank turn (docs/trains.md, "A
//! train in a scene's drive").
//!
//! The train's inputs say which members are held (an input of 0 rpm, a brake); its
//! one turning input only scales every speed, so that the ratios, and the inertias
//! reduced by their squares, do not depend on it.

use serde::Serialize;

use crate::error::{DriveEnd, DriveTrainProblem};
use crate::gears::Train;
use crate::scene::DriveTrainSpec;

/// A drive's train, per crank turn.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DriveTrain {
    /// The train's name.
    pub name: String,
    /// The motor's turns per crank turn, signed: negative where the motor turns the
    /// other way from the crank.
    pub ratio: f64,
    /// Every member's inertia reduced to the crank, Σ J_i (ω_i/ω_crank)², kg·m².
    pub inertia_at_crank_kg_m2: f64,
    /// Each member, in the file's order.
    pub members: Vec<MemberAtCrank>,
}

/// A member of a drive's train seen from the crank.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MemberAtCrank {
    /// The member.
    pub name: String,
    /// Its speed per unit crank speed (signed).
    pub speed_per_crank: f64,
    /// Its inertia reduced to the crank, J (ω/ω_crank)², kg·m².
    pub inertia_at_crank_kg_m2: f64,
}

impl DriveTrain {
    /// The train of a scene's drive, solved and reduced to the crank.
    ///
    /// # Errors
    /// The train refused, a `motor_member` or `crank_member` that is not one of its
    /// members, a second input that turns, or a motor or crank that stands still.
    pub fn from_spec(spec: &DriveTrainSpec) -> Result<Self, DriveTrainProblem> {
        let file = &spec.train;
        let known: Vec<String> = file.members.iter().map(|m| m.name.clone()).collect();
        for (end, name) in [
            (DriveEnd::Motor, &spec.motor_member),
            (DriveEnd::Crank, &spec.crank_member),
        ] {
            if !known.contains(name) {
                return Err(DriveTrainProblem::NoSuchMember {
                    end,
                    name: name.clone(),
                    known,
                });
            }
        }
        if let Some(second) = file.inputs.iter().filter(|i| i.rpm != 0.0).nth(1) {
            return Err(DriveTrainProblem::SecondInput {
                member: second.member.clone(),
                rpm: second.rpm,
            });
        }
        let train = Train::new(file.clone()).map_err(DriveTrainProblem::Train)?;
        let solution = train.solve().map_err(DriveTrainProblem::Train)?;
        let speed = |end: DriveEnd, name: &String| match solution.speed_rpm(name) {
            Some(w) if w != 0.0 && w.is_finite() => Ok(w),
            _ => Err(DriveTrainProblem::StandsStill {
                end,
                name: name.clone(),
            }),
        };
        let w_crank = speed(DriveEnd::Crank, &spec.crank_member)?;
        let w_motor = speed(DriveEnd::Motor, &spec.motor_member)?;
        let members: Vec<MemberAtCrank> = file
            .members
            .iter()
            .zip(&solution.speeds_rpm)
            .map(|(m, w)| {
                let per_crank = w.rpm / w_crank;
                MemberAtCrank {
                    name: m.name.clone(),
                    speed_per_crank: per_crank,
                    inertia_at_crank_kg_m2: m.inertia_kg_m2 * per_crank * per_crank,
                }
            })
            .collect();
        Ok(Self {
            name: file.name.clone(),
            ratio: w_motor / w_crank,
            inertia_at_crank_kg_m2: members.iter().map(|m| m.inertia_at_crank_kg_m2).sum(),
            members,
        })
    }
}
