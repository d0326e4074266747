//! The solver's refusals in the reader's words and language: the links by their
//! points, lengths in the scene's unit, the crank's angle in degrees, every
//! condition with its valid range. The solver keeps each refusal as data
//! ([`LinkageError`] and the enums under it) and words it in `Display` for the
//! command line; the app, its model and the sheets word it here, from the
//! catalogue (`locales/refusals.yml`), in English or Chinese.

mod assembly;
mod design;
mod parameter;
mod run;
mod scene;
mod singular;
mod train;

pub use assembly::{open, reach};
pub use design::{construction, design, positions, rows};
pub use parameter::{param, valid};
pub use run::{run_refusal, run_warning};
pub use scene::{cam, scene, share};
pub use singular::{singularity, undecomposable};
pub use train::{drive_train, train};

use linkage::LinkageError;
use linkage::error::{AssemblyFailure, MachineAnalysis};
use linkage::scene::LengthUnit;

use crate::numbers::{significant, unit_symbol};
use crate::words::{Lang, sw};

/// A length given in metres, in `unit` with four significant digits ("51.72 mm").
pub fn length(m: f64, unit: LengthUnit) -> String {
    format!(
        "{} {}",
        significant(m / unit.to_metres(), 4),
        unit_symbol(unit)
    )
}

/// An angle in degrees to four significant digits with the degree sign.
fn deg(v: f64) -> String {
    format!("{}°", significant(v, 4))
}

/// A solver's refusal in `lang`, lengths in `unit`: an assembly failure with the
/// distances that do not fit at the crank's angle and where the crank can go, a
/// parameter with its valid range, a dead point by its links.
pub fn error(lang: Lang, e: &LinkageError, unit: LengthUnit) -> String {
    match e {
        LinkageError::CannotAssemble {
            input_deg,
            reason,
            reachable,
        } => sw!(
            lang,
            "refusal.cannot_assemble",
            at = deg(*input_deg),
            why = assembly_failure(lang, reason, unit),
            reach = reach(lang, reachable)
        ),
        LinkageError::Run(r) => run_refusal(lang, r),
        LinkageError::SceneSyntax {
            line,
            column,
            message,
        } => sw!(
            lang,
            "refusal.syntax",
            line = line,
            column = column,
            message = message
        ),
        LinkageError::SceneInvalid(p) => sw!(lang, "refusal.invalid_scene", why = scene(lang, p)),
        LinkageError::NoDesign(d) => sw!(lang, "refusal.no_design", why = design(lang, d)),
        LinkageError::InvalidParameter {
            param: p,
            value,
            valid: v,
        } => sw!(
            lang,
            "refusal.invalid_parameter",
            param = param(lang, p),
            value = significant(*value, 6),
            valid = valid(lang, v)
        ),
        other => solver_state(lang, other, unit),
    }
}

/// The refusals that are about the chain's state or the analysis asked of it.
fn solver_state(lang: Lang, e: &LinkageError, unit: LengthUnit) -> String {
    match e {
        LinkageError::NeedsMotor => sw!(lang, "refusal.needs_motor"),
        LinkageError::Singular { input_deg, reason } => sw!(
            lang,
            "refusal.singular",
            at = deg(*input_deg),
            why = singularity(lang, reason)
        ),
        LinkageError::NewtonDiverged {
            input_deg,
            iterations,
            residual,
            tolerance,
        } => sw!(
            lang,
            "refusal.newton_diverged",
            at = deg(*input_deg),
            residual = significant(*residual, 3),
            iterations = iterations,
            tolerance = significant(*tolerance, 2)
        ),
        LinkageError::BranchJump { input_deg } => {
            sw!(lang, "refusal.branch_jump", at = deg(*input_deg))
        }
        LinkageError::NotDecomposable(u) => {
            sw!(
                lang,
                "refusal.not_decomposable",
                why = undecomposable(lang, u)
            )
        }
        LinkageError::SpeedOverflow {
            speed_rad_s,
            most_rad_s,
        } => sw!(
            lang,
            "refusal.speed_overflow",
            speed = significant(*speed_rad_s, 4),
            most = significant(*most_rad_s, 2)
        ),
        LinkageError::NotACoordinate { link, candidates } => sw!(
            lang,
            "refusal.not_a_coordinate",
            link = link,
            candidates = list(lang, candidates)
        ),
        LinkageError::NotACrank { needs, reachable } => sw!(
            lang,
            "refusal.not_a_crank",
            reach = reach(lang, reachable),
            needs = machine_analysis(lang, *needs)
        ),
        // `error` words these itself and never passes them here.
        LinkageError::CannotAssemble { .. }
        | LinkageError::Run(_)
        | LinkageError::SceneSyntax { .. }
        | LinkageError::SceneInvalid(_)
        | LinkageError::NoDesign(_)
        | LinkageError::InvalidParameter { .. } => error(lang, e, unit),
    }
}

/// Why a chain does not close at an input.
fn assembly_failure(lang: Lang, f: &AssemblyFailure, unit: LengthUnit) -> String {
    match f {
        AssemblyFailure::DyadOpen {
            dyad, shortfall, ..
        } => open(lang, dyad, shortfall.as_deref(), unit),
        AssemblyFailure::BranchFolds { lo_rad, hi_rad } => sw!(
            lang,
            "refusal.branch_folds",
            lo = deg(lo_rad.to_degrees()),
            hi = deg(hi_rad.to_degrees())
        ),
        AssemblyFailure::Nowhere => sw!(lang, "refusal.nowhere"),
    }
}

/// A machine analysis over one turn of the crank, named in a refusal.
fn machine_analysis(lang: Lang, a: MachineAnalysis) -> String {
    match a {
        MachineAnalysis::Flywheel => sw!(lang, "refusal.analysis_flywheel"),
        MachineAnalysis::SteadyState => sw!(lang, "refusal.analysis_steady"),
        MachineAnalysis::Shaking => sw!(lang, "refusal.analysis_shaking"),
    }
}

/// Names in a list: "a, b, c" in English, "a、b、c" in Chinese.
fn list(lang: Lang, names: &[String]) -> String {
    match lang {
        Lang::English => names.join(", "),
        Lang::Chinese => names.join("、"),
    }
}

#[cfg(test)]
mod tests {
    use linkage::error::{Param, Valid};
    use linkage::{Kinematics, Mechanism};

    use super::*;

    fn english_words(text: &str) -> Vec<String> {
        crate::words::english_words(text, &[])
    }

    /// Every Chinese text of the refusals' catalogue is Chinese: no English word
    /// but the scene file's keys.
    #[test]
    fn the_chinese_refusals_hold_no_english_words() {
        let text = include_str!("../../locales/refusals.yml");
        for (key, texts) in crate::words::catalogue_entries(text) {
            let zh = &texts["zh-CN"];
            let words = english_words(zh);
            assert!(words.is_empty(), "{key}: {zh} has {words:?}");
        }
    }

    /// A four-bar whose coupler and rocker are too short to reach across at half a
    /// turn: refused in both languages with the distances in the scene's unit.
    #[test]
    fn a_chain_that_does_not_close_is_refused_in_the_readers_words() {
        let text = r#"Scene(
            name: "short", models: Kinematics, length_unit: Millimetre, angle_unit: Degree,
            links: [
                (name: "ground", ground: true, points: {"A": (0.0, 0.0), "D": (100.0, 0.0)}),
                (name: "crank", points: {"A": (0.0, 0.0), "B": (60.0, 0.0)}),
                (name: "coupler", points: {"B": (0.0, 0.0), "C": (20.0, 22.36068)}),
                (name: "rocker", points: {"C": (0.0, 0.0), "D": (20.0, -22.36068)}),
            ],
            driver: (link: "crank", speed: Rpm(60.0), start: 0.0),
            branches: {"C": Left("B", "D")},
        )"#;
        let mut k = Kinematics::new(Mechanism::from_ron(text).expect("parses")).expect("builds");
        let e = k
            .solve(std::f64::consts::PI)
            .expect_err("open at half a turn");
        let en = error(Lang::English, &e, LengthUnit::Millimetre);
        let zh = error(Lang::Chinese, &e, LengthUnit::Millimetre);
        assert!(
            en.starts_with("at crank 180°, BC (30 mm) and DC (30 mm)"),
            "{en}"
        );
        assert!(en.contains("B and D are 160 mm apart"), "{en}");
        assert!(
            zh.starts_with("曲柄转角 180° 时，BC（30 mm）与 DC（30 mm）"),
            "{zh}"
        );
        assert!(
            zh.contains("B 与 D 相距 160 mm，大于两杆长之和 60 mm"),
            "{zh}"
        );
        assert!(english_words(&zh).is_empty(), "{zh}");
    }

    /// Every parameter and condition has its Chinese words: none falls back to the
    /// solver's English.
    #[test]
    fn every_parameter_and_condition_is_worded_in_chinese() {
        let params = [
            Param::InputAngle,
            Param::InputSpeed,
            Param::NewtonInput,
            Param::NewtonTolerance,
            Param::SweepSteps,
            Param::SweepStepDeg,
            Param::SampleSegment,
            Param::MaxStep,
            Param::Step,
            Param::TEnd,
            Param::InitialSpeed,
            Param::OutputDt,
            Param::CrankSpeedAtStart,
            Param::SteadyMiss,
            Param::DriverSpeed,
            Param::BaseRadius,
            Param::FollowerOffset,
            Param::OscillatingFlatFace,
            Param::FollowerArm,
            Param::RollerRadius,
            Param::Segments,
            Param::SegmentAngle(2),
            Param::SegmentLift(2),
            Param::SegmentAngleSum,
            Param::CamRpm,
            Param::PressureAngleLimit,
            Param::GenevaSlots,
            Param::GenevaCrankRadius,
            Param::Arc,
            Param::Swing,
            Param::RockerLength,
            Param::TimeRatio,
            Param::RockerStartAngle,
            Param::Stroke,
            Param::CrankRpm,
            Param::PoseOrMovingPivot,
            Param::PrecisionPoints,
            Param::GroundLength,
            Param::PrecisionPointAngle,
            Param::Positions,
            Param::Pose,
            Param::SearchTolerance,
            Param::Solutions,
            Param::Population,
            Param::Targets,
            Param::TargetCoordinate,
            Param::TargetSpread,
            Param::CrankAngles,
            Param::CrankAngle,
            Param::LeastTransmission,
            Param::GroundRegionCorner,
            Param::GroundRegionWidth,
            Param::CoursePositions,
            Param::ChosenPosition,
            Param::FirstPosition,
        ];
        for p in &params {
            let zh = param(Lang::Chinese, p);
            assert!(
                zh != p.to_string() && english_words(&zh).is_empty(),
                "{p:?}: {zh}"
            );
        }
        let conditions = [
            Valid::Finite,
            Valid::FiniteShort,
            Valid::Positive,
            Valid::PositiveShort,
            Valid::PositiveOnly,
            Valid::NonNegative,
            Valid::NonNegativeOnly,
            Valid::PositiveSeconds,
            Valid::InputFinite,
            Valid::AngleWithin { limit: 2e4 },
            Valid::GearRatio,
            Valid::BelowNoLoad {
                no_load_rpm: 1500.0,
            },
            Valid::TableOfTwo,
            Valid::RisingSpeeds,
            Valid::SolverTolerance { typical: 1e-9 },
            Valid::SampleOfRun,
            Valid::AtMostSteps(9),
            Valid::MustBeAtLeast(2),
            Valid::AtLeast(2),
            Valid::AtLeastOne,
            Valid::Count { lo: 1, hi: 3 },
            Valid::Rtol,
            Valid::MaxStep,
            Valid::Step,
            Valid::OutputSamples {
                samples: 1e9,
                t_end_s: 2.0,
                max: 1e6,
                least_s: 0.1,
            },
            Valid::StepCount {
                steps: 1e9,
                t_end_s: 2.0,
                max: 9,
                least_s: 0.1,
            },
            Valid::MotorDrives,
            Valid::ShootingCloses {
                closure: 1e-9,
                nominal_rad_s: 5.0,
            },
            Valid::SpeedFluctuation,
            Valid::NominalSpeed,
            Valid::BelowPrimeCircle { prime_m: 0.05 },
            Valid::KnifeOrRoller,
            Valid::ArmReachesPrime { prime_m: 0.05 },
            Valid::OneTurn,
            Valid::NotZeroShort,
            Valid::Between0And90,
            Valid::Between(1.0, 2.0),
            Valid::BaseCircleUpTo { most_m: 0.1 },
            Valid::ArcGivesDesign,
            Valid::SwingAdmitsDesign,
            Valid::SwingRange,
            Valid::TimeRatio,
            Valid::StrokeBelow { two_l_m: 0.2 },
            Valid::CrankPlaceable,
            Valid::FiniteNumbers,
            Valid::DistinctPoints,
            Valid::PositiveLength,
            Valid::FiniteAngle,
            Valid::OpenUnit,
            Valid::AFiniteNumber,
            Valid::TargetsApart,
            Valid::OnePerTarget,
            Valid::FiniteDegrees,
            Valid::Below90,
            Valid::MoreThanZero,
        ];
        for v in &conditions {
            let zh = valid(Lang::Chinese, v);
            assert!(
                zh != v.to_string() && english_words(&zh).is_empty(),
                "{v:?}: {zh}"
            );
        }
    }
}
