//! What a refused parameter must be ([`super::LinkageError::InvalidParameter`]), as
//! data: the condition with its numbers. `Display` gives the command line's words;
//! a catalogue (the app's, in another language) matches the variant instead.

/// The valid range or condition of a refused parameter.
#[derive(Clone, Debug, PartialEq)]
pub enum Valid {
    /// Any finite number ("must be a finite number").
    Finite,
    /// Finite ("must be finite").
    FiniteShort,
    /// Finite and positive ("must be finite and > 0").
    Positive,
    /// Finite and positive, in a cam's or a Geneva drive's words ("finite and > 0").
    PositiveShort,
    /// Positive ("must be > 0").
    PositiveOnly,
    /// Finite and not negative.
    NonNegative,
    /// Not negative ("must be >= 0").
    NonNegativeOnly,
    /// Finite, positive, seconds.
    PositiveSeconds,
    /// A solve's input angle and speed, finite.
    InputFinite,
    /// A scene angle within the largest a double holds to 1e-11 rad.
    AngleWithin {
        /// The largest magnitude, in the scene's angle unit.
        limit: f64,
    },
    /// A gear ratio: finite and > 0, motor turns per crank turn.
    GearRatio,
    /// A linear motor's rated speed below its no-load speed.
    BelowNoLoad {
        /// The no-load speed, rpm.
        no_load_rpm: f64,
    },
    /// A motor table of at least two points.
    TableOfTwo,
    /// A motor table's speeds rising.
    RisingSpeeds,
    /// The scene's solver tolerance: finite and > 0, typically `typical`.
    SolverTolerance {
        /// A typical value.
        typical: f64,
    },
    /// A sample of the run asked.
    SampleOfRun,
    /// At most this many sweep steps (held in memory).
    AtMostSteps(usize),
    /// "must be at least n".
    MustBeAtLeast(usize),
    /// "at least n".
    AtLeast(usize),
    /// At least one.
    AtLeastOne,
    /// Exactly n.
    Exactly(usize),
    /// From `lo` to `hi` inclusive.
    Count {
        /// The least.
        lo: usize,
        /// The most.
        hi: usize,
    },
    /// A relative tolerance in [1e-15, 1).
    Rtol,
    /// An adaptive run's largest step: finite and >= 0 s, 0 for none.
    MaxStep,
    /// A fixed step: finite and > 0 s (rad for the energy method).
    Step,
    /// An output interval that gives at most `max` samples.
    OutputSamples {
        /// The samples it gives.
        samples: f64,
        /// The run's end time, s.
        t_end_s: f64,
        /// The most samples.
        max: f64,
        /// The least interval, s.
        least_s: f64,
    },
    /// A step that takes at most `max` steps to the end.
    StepCount {
        /// The steps it takes.
        steps: f64,
        /// The run's end time, s.
        t_end_s: f64,
        /// The most steps.
        max: usize,
        /// The least step, s.
        least_s: f64,
    },
    /// A crank speed from which the motor turns the crank (it stalled or turned back).
    MotorDrives,
    /// Shooting that closes to `closure` of the nominal speed.
    ShootingCloses {
        /// The relative closure asked.
        closure: f64,
        /// The nominal speed, rad/s.
        nominal_rad_s: f64,
    },
    /// A coefficient of speed fluctuation in (0, 1).
    SpeedFluctuation,
    /// A nominal crank speed for flywheel sizing.
    NominalSpeed,
    /// A follower offset below the prime circle's radius.
    BelowPrimeCircle {
        /// The prime circle's radius, m.
        prime_m: f64,
    },
    /// A knife edge or a roller (not a flat face).
    KnifeOrRoller,
    /// An arm that reaches the prime circle from the pivot.
    ArmReachesPrime {
        /// The prime circle's radius, m.
        prime_m: f64,
    },
    /// Segment angles adding up to one turn.
    OneTurn,
    /// Finite and not 0, in a cam's words.
    NotZeroShort,
    /// Between 0 and 90.
    Between0And90,
    /// Between two numbers, both included.
    Between(f64, f64),
    /// A pressure angle limit that a base circle up to `most_m` reaches.
    BaseCircleUpTo {
        /// The largest base circle tried, m.
        most_m: f64,
    },
    /// An arc that gives a crank-rocker.
    ArcGivesDesign,
    /// A swing that admits a crank-rocker with this K.
    SwingAdmitsDesign,
    /// A swing in (0, 180) deg.
    SwingRange,
    /// K in (1, 1000).
    TimeRatio,
    /// A stroke in (0, 2L).
    StrokeBelow {
        /// 2L, m.
        two_l_m: f64,
    },
    /// A crank AB that can be placed with this BC, CD and K.
    CrankPlaceable,
    /// Finite numbers.
    FiniteNumbers,
    /// Precision points whose angles fix K1, K2 and K3.
    DistinctPoints,
    /// A positive length.
    PositiveLength,
    /// A finite angle.
    FiniteAngle,
    /// Between 0 and 1, exclusive.
    OpenUnit,
    /// A finite number, in path synthesis's words.
    AFiniteNumber,
    /// Targets that do not coincide.
    TargetsApart,
    /// One crank angle per target.
    OnePerTarget,
    /// A finite number of degrees.
    FiniteDegrees,
    /// 0 to 90 deg, exclusive of 90.
    Below90,
    /// More than 0.
    MoreThanZero,
}

impl Valid {
    /// The words of a condition with no number in it; `None` for one that has
    /// numbers (written by `fmt`). Every variant is named here, so that a new one
    /// cannot go without words.
    fn plain_words(&self) -> Option<&'static str> {
        Some(match self {
            Self::Finite => "must be a finite number",
            Self::FiniteShort => "must be finite",
            Self::Positive => "must be finite and > 0",
            Self::PositiveShort => "finite and > 0",
            Self::PositiveOnly => "must be > 0",
            Self::NonNegative => "must be finite and >= 0",
            Self::NonNegativeOnly => "must be >= 0",
            Self::PositiveSeconds => "must be finite and > 0 s",
            Self::InputFinite => "input angle and speed must be finite",
            Self::NotZeroShort => "finite and not 0",
            Self::GearRatio => "must be finite and > 0 (motor turns per crank turn)",
            Self::TableOfTwo => "a table needs at least 2 points",
            Self::RisingSpeeds => "speeds must rise from point to point",
            Self::SampleOfRun => "a sample of this run",
            Self::AtLeastOne => "at least one",
            Self::Rtol => "must be in [1e-15, 1)",
            Self::MaxStep => "must be finite and >= 0 s (0: no limit)",
            Self::Step => "must be finite and > 0 (s, or rad for the energy method)",
            Self::MotorDrives => {
                "the crank did not complete a turn in four nominal periods: the motor cannot drive this load (it stalls or turns back)"
            }
            Self::SpeedFluctuation => {
                "the coefficient of speed fluctuation (ω_max − ω_min)/ω_mean must lie in (0, 1); machines use 0.002 to 0.2"
            }
            Self::NominalSpeed => {
                "flywheel sizing needs the crank's nominal speed: give the driver a finite speed other than 0"
            }
            Self::KnifeOrRoller => "a knife edge or a roller",
            Self::OneTurn => "the segments' angles must add up to one turn, 2π rad (360°)",
            Self::Between0And90 => "between 0 and 90",
            Self::ArcGivesDesign => "gives no crank-rocker here; omit it to get the best design",
            Self::SwingAdmitsDesign => "admits no crank-rocker with this K",
            Self::SwingRange => "must be in (0, 180) deg",
            Self::TimeRatio => {
                "must be in (1, 1000): K = 1 puts A at infinity on this circle (use a centred design)"
            }
            Self::CrankPlaceable => "cannot be placed with this BC, CD and K",
            Self::FiniteNumbers => "finite numbers",
            Self::DistinctPoints => "points whose angles fix K1, K2 and K3 (no two alike)",
            Self::PositiveLength => "a positive length",
            Self::FiniteAngle => "a finite angle",
            Self::OpenUnit => "between 0 and 1, exclusive",
            Self::AFiniteNumber => "a finite number",
            Self::TargetsApart => "more than 0: the targets coincide",
            Self::OnePerTarget => "one per target",
            Self::FiniteDegrees => "a finite number of degrees",
            Self::Below90 => "0 to 90, exclusive of 90",
            Self::MoreThanZero => "more than 0",
            Self::AngleWithin { .. }
            | Self::ArmReachesPrime { .. }
            | Self::AtLeast(_)
            | Self::AtMostSteps(_)
            | Self::BaseCircleUpTo { .. }
            | Self::Between(..)
            | Self::BelowNoLoad { .. }
            | Self::BelowPrimeCircle { .. }
            | Self::Count { .. }
            | Self::Exactly(_)
            | Self::MustBeAtLeast(_)
            | Self::OutputSamples { .. }
            | Self::ShootingCloses { .. }
            | Self::SolverTolerance { .. }
            | Self::StepCount { .. }
            | Self::StrokeBelow { .. } => return None,
        })
    }
}

impl std::fmt::Display for Valid {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if let Some(words) = self.plain_words() {
            return f.write_str(words);
        }
        match self {
            Self::Between(low, high) => write!(f, "must be between {low} and {high}"),
            Self::AngleWithin { limit } => {
                write!(
                    f,
                    "must lie within ±{limit:.6} (the scene's angle unit; about 3200 turns), beyond which a double cannot hold the angle to 1e-11 rad: give it within one turn"
                )
            }
            Self::BelowNoLoad { no_load_rpm } => {
                write!(
                    f,
                    "must be below the no-load speed {no_load_rpm} rpm (the torque falls to zero there)"
                )
            }
            Self::SolverTolerance { typical } => {
                write!(f, "must be finite and > 0 (typical {typical:e})")
            }
            Self::AtMostSteps(n) => write!(f, "must be at most {n} (held in memory)"),
            Self::MustBeAtLeast(n) => write!(f, "must be at least {n}"),
            Self::AtLeast(n) => write!(f, "at least {n}"),
            Self::Exactly(n) => write!(f, "{n}"),
            Self::Count { lo, hi } => write!(f, "{lo} to {hi}"),
            Self::OutputSamples {
                samples,
                t_end_s,
                max,
                least_s,
            } => {
                write!(
                    f,
                    "gives {samples:.3e} samples over t_end = {t_end_s} s; at most {max:.0e}: make it at least {least_s:.3e} s"
                )
            }
            Self::StepCount {
                steps,
                t_end_s,
                max,
                least_s,
            } => {
                write!(
                    f,
                    "takes {steps:.3e} steps to t_end = {t_end_s} s; at most {max}: make it at least {least_s:.3e} s or shorten the run"
                )
            }
            Self::ShootingCloses {
                closure,
                nominal_rad_s,
            } => {
                write!(
                    f,
                    "shooting did not close to {closure:e} of the speed {nominal_rad_s} rad/s"
                )
            }
            Self::BelowPrimeCircle { prime_m } => {
                write!(f, "|offset| below the prime circle's radius, {prime_m} m")
            }
            Self::ArmReachesPrime { prime_m } => {
                write!(
                    f,
                    "the arm must reach the prime circle ({prime_m} m) from the pivot"
                )
            }
            Self::BaseCircleUpTo { most_m } => {
                write!(f, "one a base circle up to {most_m:.3e} m reaches")
            }
            Self::StrokeBelow { two_l_m } => {
                write!(f, "must be in (0, 2L) = (0, {two_l_m}) m")
            }
            // Every other condition has plain words (`plain_words` names each).
            _ => Ok(()),
        }
    }
}
