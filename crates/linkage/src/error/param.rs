//! The parameter a refusal names ([`super::LinkageError::InvalidParameter`]), as
//! data: a number of the scene file by its key, or one of the solver's arguments.
//! `Display` gives the command line's words; a catalogue (the app's, in another
//! language) matches the variant instead.

/// A parameter of a scene, an analysis or a design, named in a refusal.
#[derive(Clone, Debug, PartialEq)]
pub enum Param {
    /// A number of the scene file, by its key there as the user wrote it
    /// (`driver.speed`, `drive.gear_ratio`, `sliders[0].angle`, `spring A-B k_n_per_m`).
    Scene(String),
    /// The input angle asked of a solve.
    InputAngle,
    /// The input speed asked of a solve.
    InputSpeed,
    /// The input angle or speed of a Newton solve.
    NewtonInput,
    /// The Newton solver's tolerance.
    NewtonTolerance,
    /// The steps of a sweep.
    SweepSteps,
    /// The input's step of a table of the cycle, degrees.
    SweepStepDeg,
    /// Which segment of a dynamic run a sample is from.
    SampleSegment,
    /// A dynamic run's relative tolerance.
    Rtol,
    /// A dynamic run's absolute tolerance.
    Atol,
    /// An adaptive run's largest step.
    MaxStep,
    /// A fixed-step run's step.
    Step,
    /// A dynamic run's end time.
    TEnd,
    /// A dynamic run's initial speed.
    InitialSpeed,
    /// A dynamic run's output interval.
    OutputDt,
    /// The crank speed a steady-state search starts from.
    CrankSpeedAtStart,
    /// The steady-state search's miss after a turn.
    SteadyMiss,
    /// The coefficient of speed fluctuation of flywheel sizing.
    Delta,
    /// The driver's speed, for flywheel sizing.
    DriverSpeed,
    /// A disc cam's base radius, m.
    BaseRadius,
    /// A translating follower's offset, m.
    FollowerOffset,
    /// A flat face on an oscillating follower.
    OscillatingFlatFace,
    /// An oscillating follower's arm, m.
    FollowerArm,
    /// A roller's radius, m.
    RollerRadius,
    /// A cam program's segments.
    Segments,
    /// The angle of a cam program's segment (its index).
    SegmentAngle(usize),
    /// The lift of a cam program's segment (its index).
    SegmentLift(usize),
    /// The sum of a cam program's segment angles.
    SegmentAngleSum,
    /// A cam design's speed, rpm.
    CamRpm,
    /// The pressure angle limit of cam sizing, deg.
    PressureAngleLimit,
    /// A Geneva wheel's slots.
    GenevaSlots,
    /// A Geneva drive's crank radius, m.
    GenevaCrankRadius,
    /// The arc on which a crank-rocker's pivot is chosen, deg.
    Arc,
    /// A rocker's swing, deg.
    Swing,
    /// A rocker's length.
    RockerLength,
    /// The time ratio K.
    TimeRatio,
    /// The rocker's start angle.
    RockerStartAngle,
    /// The die cutter's stroke H, m.
    Stroke,
    /// The die cutter's crank AB, m.
    CrankAb,
    /// The die cutter's crank speed, rpm.
    CrankRpm,
    /// A pose or moving pivot of motion synthesis.
    PoseOrMovingPivot,
    /// Function synthesis's precision points.
    PrecisionPoints,
    /// Function synthesis's ground length.
    GroundLength,
    /// An angle of a precision point.
    PrecisionPointAngle,
    /// The number of positions of Burmester synthesis.
    Positions,
    /// A pose of Burmester synthesis.
    Pose,
    /// Path synthesis's tolerance.
    SearchTolerance,
    /// How many designs path synthesis keeps.
    Solutions,
    /// Path synthesis's population.
    Population,
    /// The number of path targets.
    Targets,
    /// A target's coordinate.
    TargetCoordinate,
    /// The size of the targets' spread.
    TargetSpread,
    /// The number of crank angles given with the targets.
    CrankAngles,
    /// A crank angle given with a target.
    CrankAngle,
    /// The least transmission angle asked of path synthesis, deg.
    LeastTransmission,
    /// A corner of the ground pivots' region.
    GroundRegionCorner,
    /// The width of the ground pivots' region.
    GroundRegionWidth,
    /// The positions of a course sheet.
    CoursePositions,
    /// A position chosen on a course sheet.
    ChosenPosition,
    /// The crank angle of a course sheet's first position, degrees.
    FirstPosition,
}

impl std::fmt::Display for Param {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let words = match self {
            Self::Scene(key) => key,
            Self::SegmentAngle(i) => return write!(f, "segment {i} angle (rad)"),
            Self::SegmentLift(i) => return write!(f, "segment {i} lift"),
            Self::InputAngle => "input angle",
            Self::InputSpeed => "input speed",
            Self::NewtonInput => "input",
            Self::NewtonTolerance => "Newton tolerance",
            Self::SweepSteps => "steps",
            Self::SweepStepDeg => "step (deg)",
            Self::SampleSegment => "sample segment",
            Self::Rtol => "rtol",
            Self::Atol => "atol",
            Self::MaxStep => "max step",
            Self::Step => "step",
            Self::TEnd => "t_end",
            Self::InitialSpeed => "initial speed",
            Self::OutputDt => "output dt",
            Self::CrankSpeedAtStart => "crank speed at the start",
            Self::SteadyMiss => "steady-state miss after a turn",
            Self::Delta => "delta",
            Self::DriverSpeed => "driver speed",
            Self::BaseRadius => "base radius (m)",
            Self::FollowerOffset => "follower offset (m)",
            Self::OscillatingFlatFace => "oscillating flat face",
            Self::FollowerArm => "follower arm (m)",
            Self::RollerRadius => "roller radius (m)",
            Self::Segments => "segments",
            Self::SegmentAngleSum => "sum of the segment angles (rad)",
            Self::CamRpm => "rpm",
            Self::PressureAngleLimit => "pressure angle limit (deg)",
            Self::GenevaSlots => "Geneva slots",
            Self::GenevaCrankRadius => "Geneva crank radius (m)",
            Self::Arc => "arc (deg)",
            Self::Swing => "swing (deg)",
            Self::RockerLength => "rocker length",
            Self::TimeRatio => "time ratio K",
            Self::RockerStartAngle => "rocker start angle",
            Self::Stroke => "stroke H (m)",
            Self::CrankAb => "AB (m)",
            Self::CrankRpm => "crank speed (rpm)",
            Self::PoseOrMovingPivot => "pose or moving pivot",
            Self::PrecisionPoints => "precision points",
            Self::GroundLength => "ground length",
            Self::PrecisionPointAngle => "precision point angle",
            Self::Positions => "number of positions",
            Self::Pose => "pose",
            Self::SearchTolerance => "tolerance",
            Self::Solutions => "solutions",
            Self::Population => "population",
            Self::Targets => "number of targets",
            Self::TargetCoordinate => "target coordinate",
            Self::TargetSpread => "size of the targets' spread",
            Self::CrankAngles => "number of crank angles",
            Self::CrankAngle => "crank angle",
            Self::LeastTransmission => "least transmission angle (deg)",
            Self::GroundRegionCorner => "ground region corner",
            Self::GroundRegionWidth => "ground region width",
            Self::CoursePositions => "positions",
            Self::ChosenPosition => "chosen position",
            Self::FirstPosition => "first position's crank angle (deg)",
        };
        f.write_str(words)
    }
}
