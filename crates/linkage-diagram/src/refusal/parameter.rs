//! A refused number: the parameter by the name the reader knows it by, and what it
//! must be, with the valid range's numbers.

use linkage::error::{Param, Valid};

use crate::numbers::significant;
use crate::words::{Lang, sw};

/// A parameter's name: a scene file's key as written there, the others by the
/// quantity they set.
pub fn param(lang: Lang, p: &Param) -> String {
    match p {
        Param::Scene(key) => key.clone(),
        Param::SegmentAngle(i) => sw!(lang, "param.segment_angle", segment = i),
        Param::SegmentLift(i) => sw!(lang, "param.segment_lift", segment = i),
        Param::InputAngle => sw!(lang, "param.input_angle"),
        Param::InputSpeed => sw!(lang, "param.input_speed"),
        Param::NewtonInput => sw!(lang, "param.newton_input"),
        Param::NewtonTolerance => sw!(lang, "param.newton_tolerance"),
        Param::SweepSteps => sw!(lang, "param.sweep_steps"),
        Param::SweepStepDeg => sw!(lang, "param.sweep_step_deg"),
        Param::SampleSegment => sw!(lang, "param.sample_segment"),
        Param::Rtol => "rtol".into(),
        Param::Atol => "atol".into(),
        Param::MaxStep => sw!(lang, "param.max_step"),
        Param::Step => sw!(lang, "param.step"),
        Param::TEnd => sw!(lang, "param.t_end"),
        Param::InitialSpeed => sw!(lang, "param.initial_speed"),
        Param::OutputDt => sw!(lang, "param.output_dt"),
        Param::CrankSpeedAtStart => sw!(lang, "param.crank_speed_at_start"),
        Param::SteadyMiss => sw!(lang, "param.steady_miss"),
        Param::Delta => sw!(lang, "param.delta"),
        Param::DriverSpeed => sw!(lang, "param.driver_speed"),
        other => cam_or_design_param(lang, other),
    }
}

/// The names of a cam's, a Geneva wheel's and a synthesis's parameters.
fn cam_or_design_param(lang: Lang, p: &Param) -> String {
    match p {
        Param::BaseRadius => sw!(lang, "param.base_radius"),
        Param::FollowerOffset => sw!(lang, "param.follower_offset"),
        Param::OscillatingFlatFace => sw!(lang, "param.oscillating_flat_face"),
        Param::FollowerArm => sw!(lang, "param.follower_arm"),
        Param::RollerRadius => sw!(lang, "param.roller_radius"),
        Param::Segments => sw!(lang, "param.segments"),
        Param::SegmentAngleSum => sw!(lang, "param.segment_angle_sum"),
        Param::CamRpm => sw!(lang, "param.cam_rpm"),
        Param::PressureAngleLimit => sw!(lang, "param.pressure_angle_limit"),
        Param::GenevaSlots => sw!(lang, "param.geneva_slots"),
        Param::GenevaCrankRadius => sw!(lang, "param.geneva_crank_radius"),
        Param::Arc => sw!(lang, "param.arc"),
        Param::Swing => sw!(lang, "param.swing"),
        Param::RockerLength => sw!(lang, "param.rocker_length"),
        Param::TimeRatio => sw!(lang, "param.time_ratio"),
        Param::RockerStartAngle => sw!(lang, "param.rocker_start_angle"),
        Param::Stroke => sw!(lang, "param.stroke"),
        Param::CrankAb => "AB (m)".into(),
        Param::CrankRpm => sw!(lang, "param.crank_rpm"),
        other => synthesis_param(lang, other),
    }
}

/// The names of the synthesis's and the course sheet's parameters.
fn synthesis_param(lang: Lang, p: &Param) -> String {
    match p {
        Param::PoseOrMovingPivot => sw!(lang, "param.pose_or_moving_pivot"),
        Param::PrecisionPoints => sw!(lang, "param.precision_points"),
        Param::GroundLength => sw!(lang, "param.ground_length"),
        Param::PrecisionPointAngle => sw!(lang, "param.precision_point_angle"),
        Param::Positions => sw!(lang, "param.positions"),
        Param::Pose => sw!(lang, "param.pose"),
        Param::SearchTolerance => sw!(lang, "param.search_tolerance"),
        Param::Solutions => sw!(lang, "param.solutions"),
        Param::Population => sw!(lang, "param.population"),
        Param::Targets => sw!(lang, "param.targets"),
        Param::TargetCoordinate => sw!(lang, "param.target_coordinate"),
        Param::TargetSpread => sw!(lang, "param.target_spread"),
        Param::CrankAngles => sw!(lang, "param.crank_angles"),
        Param::CrankAngle => sw!(lang, "param.crank_angle"),
        Param::LeastTransmission => sw!(lang, "param.least_transmission"),
        Param::GroundRegionCorner => sw!(lang, "param.ground_region_corner"),
        Param::GroundRegionWidth => sw!(lang, "param.ground_region_width"),
        Param::CoursePositions => sw!(lang, "param.course_positions"),
        Param::ChosenPosition => sw!(lang, "param.chosen_position"),
        Param::FirstPosition => sw!(lang, "param.first_position"),
        // `param` and `cam_or_design_param` name the others before they come here;
        // one added to the solver and not yet here reads in the solver's English.
        other => other.to_string(),
    }
}

/// What a refused parameter must be.
pub fn valid(lang: Lang, v: &Valid) -> String {
    match v {
        Valid::Finite => sw!(lang, "valid.finite"),
        Valid::FiniteShort => sw!(lang, "valid.finite_short"),
        Valid::Positive => sw!(lang, "valid.positive"),
        Valid::PositiveShort => sw!(lang, "valid.positive_short"),
        Valid::PositiveOnly => sw!(lang, "valid.positive_only"),
        Valid::NonNegative => sw!(lang, "valid.non_negative"),
        Valid::NonNegativeOnly => sw!(lang, "valid.non_negative_only"),
        Valid::PositiveSeconds => sw!(lang, "valid.positive_seconds"),
        Valid::InputFinite => sw!(lang, "valid.input_finite"),
        Valid::NotZeroShort => sw!(lang, "valid.not_zero"),
        Valid::GearRatio => sw!(lang, "valid.gear_ratio"),
        Valid::TableOfTwo => sw!(lang, "valid.table_of_two"),
        Valid::RisingSpeeds => sw!(lang, "valid.rising_speeds"),
        Valid::SampleOfRun => sw!(lang, "valid.sample_of_run"),
        Valid::AtLeastOne => sw!(lang, "valid.at_least_one"),
        Valid::Rtol => sw!(lang, "valid.rtol"),
        Valid::MaxStep => sw!(lang, "valid.max_step"),
        Valid::Step => sw!(lang, "valid.step"),
        Valid::MotorDrives => sw!(lang, "valid.motor_drives"),
        Valid::SpeedFluctuation => sw!(lang, "valid.speed_fluctuation"),
        Valid::NominalSpeed => sw!(lang, "valid.nominal_speed"),
        other => valid_with_numbers(lang, other),
    }
}

/// The conditions that carry numbers: a range, a limit, a count.
fn valid_with_numbers(lang: Lang, v: &Valid) -> String {
    match v {
        Valid::Between(low, high) => sw!(lang, "valid.between", low = low, high = high),
        Valid::AngleWithin { limit } => {
            sw!(lang, "valid.angle_within", limit = significant(*limit, 6))
        }
        Valid::BelowNoLoad { no_load_rpm } => {
            sw!(
                lang,
                "valid.below_no_load",
                rpm = significant(*no_load_rpm, 5)
            )
        }
        Valid::SolverTolerance { typical } => {
            sw!(
                lang,
                "valid.solver_tolerance",
                typical = format!("{typical:e}")
            )
        }
        Valid::AtMostSteps(n) => sw!(lang, "valid.at_most_steps", n = n),
        Valid::MustBeAtLeast(n) => sw!(lang, "valid.must_be_at_least", n = n),
        Valid::AtLeast(n) => sw!(lang, "valid.at_least", n = n),
        Valid::Exactly(n) => n.to_string(),
        Valid::Count { lo, hi } => sw!(lang, "valid.count", lo = lo, hi = hi),
        Valid::OutputSamples {
            samples,
            t_end_s,
            max,
            least_s,
        } => sw!(
            lang,
            "valid.output_samples",
            samples = significant(*samples, 4),
            end = significant(*t_end_s, 4),
            max = significant(*max, 2),
            least = significant(*least_s, 4)
        ),
        Valid::StepCount {
            steps,
            t_end_s,
            max,
            least_s,
        } => sw!(
            lang,
            "valid.step_count",
            steps = significant(*steps, 4),
            end = significant(*t_end_s, 4),
            max = max,
            least = significant(*least_s, 4)
        ),
        Valid::ShootingCloses {
            closure,
            nominal_rad_s,
        } => sw!(
            lang,
            "valid.shooting_closes",
            closure = format!("{closure:e}"),
            speed = significant(*nominal_rad_s, 4)
        ),
        other => valid_of_cam_or_design(lang, other),
    }
}

/// The conditions of a cam's and a synthesis's inputs.
fn valid_of_cam_or_design(lang: Lang, v: &Valid) -> String {
    match v {
        Valid::BelowPrimeCircle { prime_m } => {
            sw!(
                lang,
                "valid.below_prime_circle",
                prime = significant(*prime_m, 4)
            )
        }
        Valid::ArmReachesPrime { prime_m } => {
            sw!(
                lang,
                "valid.arm_reaches_prime",
                prime = significant(*prime_m, 4)
            )
        }
        Valid::BaseCircleUpTo { most_m } => {
            sw!(
                lang,
                "valid.base_circle_up_to",
                most = significant(*most_m, 4)
            )
        }
        Valid::StrokeBelow { two_l_m } => {
            sw!(lang, "valid.stroke_below", two_l = significant(*two_l_m, 4))
        }
        Valid::KnifeOrRoller => sw!(lang, "valid.knife_or_roller"),
        Valid::OneTurn => sw!(lang, "valid.one_turn"),
        Valid::Between0And90 => sw!(lang, "valid.between_0_and_90"),
        Valid::ArcGivesDesign => sw!(lang, "valid.arc_gives_design"),
        Valid::SwingAdmitsDesign => sw!(lang, "valid.swing_admits_design"),
        Valid::SwingRange => sw!(lang, "valid.swing_range"),
        Valid::TimeRatio => sw!(lang, "valid.time_ratio"),
        Valid::CrankPlaceable => sw!(lang, "valid.crank_placeable"),
        Valid::FiniteNumbers => sw!(lang, "valid.finite_numbers"),
        Valid::DistinctPoints => sw!(lang, "valid.distinct_points"),
        Valid::PositiveLength => sw!(lang, "valid.positive_length"),
        Valid::FiniteAngle => sw!(lang, "valid.finite_angle"),
        Valid::OpenUnit => sw!(lang, "valid.open_unit"),
        Valid::AFiniteNumber => sw!(lang, "valid.a_finite_number"),
        Valid::TargetsApart => sw!(lang, "valid.targets_apart"),
        Valid::OnePerTarget => sw!(lang, "valid.one_per_target"),
        Valid::FiniteDegrees => sw!(lang, "valid.finite_degrees"),
        Valid::Below90 => sw!(lang, "valid.below_90"),
        Valid::MoreThanZero => sw!(lang, "valid.more_than_zero"),
        // `valid` and `valid_with_numbers` word the others before they come here;
        // one added to the solver and not yet here reads in the solver's English.
        other => other.to_string(),
    }
}
