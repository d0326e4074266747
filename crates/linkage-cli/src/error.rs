//! Why a command failed, as data: the file it could not read or write, what in a
//! file was refused, the solver's refusal, a speed that overflows, a value it will
//! not print; worded only by `Display`, where `main` prints it.

use std::path::PathBuf;

use linkage::LinkageError;
use linkage::synthesis::rows::RowError;
use thiserror::Error;

/// Everything a command can fail with.
#[derive(Debug, Error)]
pub enum CliError {
    /// A scene file could not be read.
    #[error("cannot read scene {}: {source}", path.display())]
    ReadScene {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A table of inputs could not be read.
    #[error("cannot read {}: {source}", path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A file could not be written.
    #[error("cannot write {}: {source}", path.display())]
    Write {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A file was read and what it holds was refused.
    #[error("{}: {source}", path.display())]
    InFile {
        /// The file.
        path: PathBuf,
        /// What was refused in it.
        source: Box<CliError>,
    },
    /// The solver refused (a dynamic run's settings named by their options).
    #[error("{}", solver_words(.0))]
    Solver(#[from] LinkageError),
    /// The input speed makes velocities or accelerations overflow: named by where it
    /// came from, the option or the scene's driver.
    #[error("{}", overflow_words(*from_option, *speed_rad_s, *most_rad_s))]
    SpeedOverflow {
        /// Whether `--speed-rad-s` gave the speed (else the scene's driver did).
        from_option: bool,
        /// The speed, rad/s.
        speed_rad_s: f64,
        /// The largest speed that stays finite, rad/s.
        most_rad_s: f64,
    },
    /// A share link that does not carry a scene, or a scene too large for one.
    #[error(transparent)]
    Share(#[from] linkage::share::ShareError),
    /// Rows of numbers that are not what the command reads.
    #[error(transparent)]
    Rows(#[from] RowError),
    /// A value that is not a finite number, not printed.
    #[error("non-finite value in {what} (column {column}); refusing to print it")]
    NonFinite {
        /// What holds it.
        what: String,
        /// Its column.
        column: usize,
    },
    /// An option or input the command refuses, with the valid range where one exists.
    #[error("{0}")]
    Refused(String),
    /// An exercise file refused, or no variant for a student.
    #[error(transparent)]
    Exercise(#[from] linkage_model::exercise::ExerciseError),
    /// The output as JSON.
    #[error(transparent)]
    Json(#[from] serde_json::Error),
    /// The output as CSV.
    #[error(transparent)]
    Csv(#[from] csv::Error),
    /// The plot (the plotting library's own message).
    #[error("{0}")]
    Plot(String),
    /// Writing the output failed (a closed pipe, a full disk).
    #[error("cannot write the output: {0}")]
    Output(#[from] std::io::Error),
}

/// Shorthand for a command's result.
pub type Result<T> = std::result::Result<T, CliError>;

impl CliError {
    /// `source`, refused in the file at `path`.
    pub fn in_file(path: impl Into<PathBuf>, source: impl Into<CliError>) -> Self {
        Self::InFile {
            path: path.into(),
            source: Box::new(source.into()),
        }
    }

    /// A refusal in the command's words.
    pub fn refused(why: impl Into<String>) -> Self {
        Self::Refused(why.into())
    }
}

/// The solver's error as the solver words it, but a dynamic run's refusal, which
/// names the option to change, and a missing motor, which names the file that
/// documents the scene format.
fn solver_words(e: &LinkageError) -> String {
    match e {
        LinkageError::Run(r) => crate::run_words::refusal(r),
        // The scene format's guide is a file of this repository.
        LinkageError::NeedsMotor => "drive = NaN is invalid: the steady state needs a motor: give the scene a `drive` (see assets/scenes/README.md)".to_string(),
        other => other.to_string(),
    }
}

/// An overflowing speed in the words of this command line.
fn overflow_words(from_option: bool, speed_rad_s: f64, most_rad_s: f64) -> String {
    let rpm = |w: f64| w * 60.0 / std::f64::consts::TAU;
    if from_option {
        format!(
            "--speed-rad-s {speed_rad_s:e} makes velocities or accelerations overflow: give at most {most_rad_s:.1e} rad/s"
        )
    } else {
        format!(
            "the scene's driver speed ({speed_rad_s:e} rad/s, {:e} rpm) makes velocities or accelerations overflow: at most {most_rad_s:.1e} rad/s ({:.1e} rpm), or give --speed-rad-s",
            rpm(speed_rad_s),
            rpm(most_rad_s)
        )
    }
}
