//! The exercise's subject as data the solver takes (a scene file or a cam file),
//! the varied dimensions written into it, and it built for the analyses.

use linkage::cam::{CamSpec, FollowerSpec, SegmentSpec};
use linkage::scene::Speed;
use linkage::{Kinematics, Mechanism, SceneFile};

use super::error::ExerciseError;
use super::file::{Subject, Values, Vary};
use super::quantity::Built;
use crate::catalog::{BUILTIN_SCENES, BuiltinScene, TEMPLATES};
use crate::session::params::{LengthParam, length_params};

/// Points over a cam's turn, where a drawing samples it.
const CAM_SAMPLES: u32 = 720;

/// A cam sampled over its turn, to draw.
#[derive(Clone, Debug, PartialEq)]
pub struct CamTurn {
    /// Its points in order over the turn (the last joins the first).
    pub points: Vec<linkage::cam::CamPoint>,
    /// Its base circle's radius, m.
    pub base_radius_m: f64,
    /// The follower where it stands at the start of the turn.
    pub follower: linkage::cam::FollowerOutline,
}

/// A subject as the solver reads it.
#[derive(Clone, Debug, PartialEq)]
pub enum SubjectData {
    /// A mechanism.
    Scene(Box<SceneFile>),
    /// A disc cam.
    Cam(Box<CamSpec>),
}

impl SubjectData {
    /// The file's subject, a shipped scene or template looked up by its key.
    ///
    /// # Errors
    /// A key that names no shipped scene or template, or one that does not parse.
    pub fn of(subject: &Subject) -> Result<Self, ExerciseError> {
        let shipped = |folder: &'static str, list: &[BuiltinScene], key: &str| {
            let found = list.iter().find(|s| s.key == key).ok_or_else(|| {
                ExerciseError::UnknownSubject {
                    folder,
                    key: key.to_string(),
                    known: list.iter().map(|s| s.key.to_string()).collect(),
                }
            })?;
            SceneFile::parse(found.text)
                .map(|s| SubjectData::Scene(Box::new(s)))
                .map_err(|e| ExerciseError::Subject(e.to_string()))
        };
        match subject {
            Subject::Scene(key) => shipped("scene", BUILTIN_SCENES, key),
            Subject::Template(key) => shipped("template", TEMPLATES, key),
            Subject::SceneFile(scene) => Ok(SubjectData::Scene(scene.clone())),
            Subject::Cam(cam) => Ok(SubjectData::Cam(cam.clone())),
        }
    }

    /// A cam's points over its turn (720, evenly spaced) and its base radius, m, as
    /// the desk and the task sheet draw it (`None` for a mechanism, or a cam the
    /// solver refuses).
    pub fn cam_turn(&self) -> Option<CamTurn> {
        let SubjectData::Cam(spec) = self else {
            return None;
        };
        let design = spec.design().ok()?;
        let at = |i: u32| {
            design
                .cam
                .at(f64::from(i) * std::f64::consts::TAU / f64::from(CAM_SAMPLES))
        };
        Some(CamTurn {
            points: (0..CAM_SAMPLES).map(at).collect(),
            base_radius_m: design.cam.base_radius_m,
            follower: design.cam.follower_outline(0.0),
        })
    }

    /// Built for the analyses.
    ///
    /// # Errors
    /// The solver's refusal, worded.
    pub fn build(&self) -> Result<Built, String> {
        match self {
            SubjectData::Scene(scene) => {
                let mech = Mechanism::from_scene(scene).map_err(|e| e.to_string())?;
                let kinematics = Kinematics::new(mech).map_err(|e| e.to_string())?;
                Ok(Built::Mechanism {
                    kinematics: Box::new(kinematics),
                    report: None,
                })
            }
            SubjectData::Cam(cam) => cam
                .design()
                .map(|d| Built::Cam(Box::new(d)))
                .map_err(|e| e.to_string()),
        }
    }

    /// The value of the varied dimension `vary` (number `index` from 1) in this
    /// subject, in its own unit.
    ///
    /// # Errors
    /// A dimension the subject does not have.
    pub fn value(&self, vary: &Vary, index: usize) -> Result<f64, ExerciseError> {
        let missing = |why| ExerciseError::NoDimension { index, why };
        match (self, vary) {
            (SubjectData::Scene(scene), Vary::Length { length, .. }) => {
                let param = length_param(scene, length, index)?;
                param.value(scene).ok_or(missing("the length's points"))
            }
            (SubjectData::Scene(scene), Vary::CrankRpm { .. }) => Ok(match scene.driver.speed {
                Speed::Rpm(rpm) => rpm,
                Speed::RadPerSecond(w) => w * 60.0 / std::f64::consts::TAU,
            }),
            (SubjectData::Cam(cam), Vary::BaseRadius { .. }) => Ok(cam.base_radius_mm),
            (SubjectData::Cam(cam), Vary::Lift { .. }) => {
                one_lift(cam).ok_or(missing("rises and returns all of one lift"))
            }
            (SubjectData::Cam(cam), Vary::Offset { .. }) => match cam.follower {
                FollowerSpec::Translating { offset_mm, .. } => Ok(offset_mm),
                FollowerSpec::Oscillating { .. } => {
                    Err(missing("an oscillating follower has no offset"))
                }
            },
            (SubjectData::Scene(_), _) => {
                Err(missing("a cam's dimension, the subject is a mechanism"))
            }
            (SubjectData::Cam(_), _) => {
                Err(missing("a mechanism's dimension, the subject is a cam"))
            }
        }
    }

    /// Writes `value` (its own unit) for the varied dimension `vary`.
    ///
    /// # Errors
    /// A dimension the subject does not have, or a length that is not positive.
    pub fn set(&mut self, vary: &Vary, index: usize, value: f64) -> Result<(), ExerciseError> {
        let missing = |why| ExerciseError::NoDimension { index, why };
        match (self, vary) {
            (SubjectData::Scene(scene), Vary::Length { length, .. }) => {
                let param = length_param(scene, length, index)?;
                param
                    .apply(scene, value)
                    .map_err(|_| ExerciseError::Values {
                        index,
                        why: "a length must be positive",
                    })
            }
            (SubjectData::Scene(scene), Vary::CrankRpm { .. }) => {
                scene.driver.speed = Speed::Rpm(value);
                Ok(())
            }
            (SubjectData::Cam(cam), Vary::BaseRadius { .. }) => {
                cam.base_radius_mm = value;
                Ok(())
            }
            (SubjectData::Cam(cam), Vary::Lift { .. }) => {
                for lift in cam.segments.iter_mut().filter_map(SegmentSpec::lift_mut) {
                    *lift = value;
                }
                Ok(())
            }
            (SubjectData::Cam(cam), Vary::Offset { .. }) => match &mut cam.follower {
                FollowerSpec::Translating { offset_mm, .. } => {
                    *offset_mm = value;
                    Ok(())
                }
                FollowerSpec::Oscillating { .. } => {
                    Err(missing("an oscillating follower has no offset"))
                }
            },
            _ => Err(missing("the subject is of another kind")),
        }
    }
}

/// The lift of every rise and return, if they have one.
fn one_lift(cam: &CamSpec) -> Option<f64> {
    let mut lifts = cam.segments.iter().filter_map(SegmentSpec::lift);
    let first = lifts.next()?;
    lifts.all(|l| l == first).then_some(first)
}

fn length_param(
    scene: &SceneFile,
    length: &str,
    index: usize,
) -> Result<LengthParam, ExerciseError> {
    let params = length_params(scene);
    let known = || params.iter().map(|p| p.label.clone()).collect();
    params
        .iter()
        .find(|p| p.label == length)
        .cloned()
        .ok_or_else(|| ExerciseError::UnknownLength {
            index,
            length: length.to_string(),
            known: known(),
        })
}

/// The whole multiples of the step a varied dimension takes: `(first, count)`, the
/// values being `(first + i) * step` for `i` in `0..count`. `base` is the subject's
/// own value (for [`Values::Around`]).
///
/// # Errors
/// A step or spread that is not finite and positive, or a range with no multiple.
pub fn grid(values: &Values, base: f64, index: usize) -> Result<(i64, i64, f64), ExerciseError> {
    let bad = |why| ExerciseError::Values { index, why };
    let (min, max, step) = match *values {
        Values::Range { min, max, step } => (min, max, step),
        Values::Around { spread, step } => {
            if !(spread.is_finite() && spread > 0.0 && spread < 1.0) {
                return Err(bad("the spread must lie between 0 and 1"));
            }
            (base * (1.0 - spread), base * (1.0 + spread), step)
        }
    };
    if !(step.is_finite() && step > 0.0 && min.is_finite() && max.is_finite()) {
        return Err(bad("the step must be positive and the range finite"));
    }
    if min > max {
        return Err(bad("min is above max"));
    }
    let (first, last) = ((min / step).ceil(), (max / step).floor());
    if last < first || last - first > 1e9 {
        return Err(bad(
            "the range holds no whole multiple of the step (or over 10^9 of them)",
        ));
    }
    if last == first {
        return Err(bad(
            "the range holds one whole multiple of the step only, so it would not vary: widen it or take the entry out",
        ));
    }
    Ok((first as i64, (last - first) as i64 + 1, step))
}
