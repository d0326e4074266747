//! `linkage`: the headless command line over scene files.
//!
//! A contract scripts depend on: see docs/cli.md. Errors go to stderr with a
//! non-zero exit status and a message naming the cause.

#![forbid(unsafe_code)]

mod commands;
mod counts;
mod diagram;
mod io;
mod kinetostatics;
mod plot;
mod simulate;
mod synth_function;
mod synth_motion;
mod synth_path;
mod tradeoff;

use std::io::{ErrorKind, Write};
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};

/// Planar linkage kinematics, analysis and synthesis from scene files.
#[derive(Parser, Debug)]
#[command(name = "linkage", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// Output format.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
enum Format {
    Csv,
    Json,
}

/// Solver path.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
enum PathArg {
    /// Closed form when the chain decomposes into dyads, else Newton.
    Auto,
    /// Closed-form Assur dyads.
    ClosedForm,
    /// Newton–Raphson on the loop-closure constraints.
    Newton,
}

/// Options shared by the commands that solve a scene.
#[derive(clap::Args, Debug)]
struct SceneArgs {
    /// Scene file (RON).
    scene: PathBuf,
    /// Override assembly branches: POINT=left|right|along|against|flip[,...]
    #[arg(long)]
    branch: Option<String>,
    /// Solver path.
    #[arg(long, value_enum, default_value_t = PathArg::Auto)]
    path: PathArg,
    /// Input speed in rad/s for velocities (default: the scene's crank speed).
    #[arg(long, allow_hyphen_values = true)]
    speed_rad_s: Option<f64>,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// One input cycle (or the assemblable range) as CSV or JSON.
    Sweep {
        #[command(flatten)]
        scene: SceneArgs,
        /// Number of positions (at least 2: the cycle's ends).
        #[arg(long, default_value_t = 360, allow_hyphen_values = true, value_parser = counts::at_least_two)]
        steps: usize,
        /// Output format.
        #[arg(long, value_enum, default_value_t = Format::Csv)]
        format: Format,
    },
    /// One position; JSON adds the velocity and acceleration polygon equations.
    At {
        #[command(flatten)]
        scene: SceneArgs,
        /// Input (crank) angle in degrees.
        #[arg(long, allow_hyphen_values = true)]
        input_deg: f64,
        /// Output format.
        #[arg(long, value_enum, default_value_t = Format::Json)]
        format: Format,
    },
    /// Assembly range, limit positions, strokes, swings, K, Grashof, transmission angle, toggles (JSON).
    Report {
        #[command(flatten)]
        scene: SceneArgs,
    },
    /// Forward dynamics of the 1-DOF chain from rest at the scene's start angle:
    /// samples on a uniform time grid (CSV or JSON with events and cost).
    Simulate {
        #[command(flatten)]
        scene: SceneArgs,
        #[command(flatten)]
        sim: simulate::SimArgs,
        /// Output format.
        #[arg(long, value_enum, default_value_t = Format::Csv)]
        format: Format,
    },
    /// Input torque (Newton-Euler and virtual work), joint reactions and force
    /// amplification over one input cycle at the scene's crank speed.
    Kinetostatics {
        #[command(flatten)]
        scene: SceneArgs,
        /// Number of positions.
        #[arg(long, default_value_t = 360, allow_hyphen_values = true, value_parser = counts::at_least_one)]
        steps: usize,
        /// Output format.
        #[arg(long, value_enum, default_value_t = Format::Csv)]
        format: Format,
    },
    /// The work-precision table: per method and tolerance or step, CPU time, RHS
    /// evaluations and error against a DOP853 rtol-1e-13 reference (CSV; --png plots it).
    Tradeoff {
        #[command(flatten)]
        scene: SceneArgs,
        #[command(flatten)]
        args: tradeoff::TradeoffArgs,
    },
    /// An A4 sheet of one position to hand in: pose, velocity and acceleration
    /// polygons with scales, vector-equation tables, instant centres (SVG; --png too).
    Diagram {
        #[command(flatten)]
        scene: SceneArgs,
        #[command(flatten)]
        args: diagram::DiagramArgs,
    },
    /// A scene as the fragment of a share link (`doc=1.…`: the file deflated and
    /// base64url-encoded, as the app's share link carries it); with --decode, a link,
    /// fragment or payload back to the scene file, byte for byte.
    Share {
        /// Scene file (RON) to pack.
        #[arg(required_unless_present = "decode", conflicts_with = "decode")]
        scene: Option<PathBuf>,
        /// A share link, its fragment or its payload, to unpack.
        #[arg(long)]
        decode: Option<String>,
    },
    /// Dimensional synthesis.
    Synth {
        #[command(subcommand)]
        what: SynthCommand,
    },
}

#[derive(Subcommand, Debug)]
enum SynthCommand {
    /// Crank-rocker from rocker length, swing and time ratio K (JSON; --scene-out writes a scene).
    CrankRocker {
        /// Rocker length CD, m.
        #[arg(long, allow_hyphen_values = true)]
        rocker: f64,
        /// Rocker swing, degrees.
        #[arg(long, allow_hyphen_values = true)]
        swing_deg: f64,
        /// Time ratio K (> 1).
        #[arg(long, allow_hyphen_values = true)]
        k: f64,
        /// Angle of the first rocker limit position about D, degrees.
        #[arg(long, default_value_t = 45.0, allow_hyphen_values = true)]
        rocker_start_deg: f64,
        /// The free choice: A's angle on the synthesis circle (default: best transmission angle).
        #[arg(long, allow_hyphen_values = true)]
        arc_deg: Option<f64>,
        /// Which mirror circle A lies on when --arc-deg is given (+1 or -1).
        #[arg(long, default_value_t = 1, allow_hyphen_values = true)]
        side: i8,
        /// Write the four-bar as a scene file here.
        #[arg(long)]
        scene_out: Option<PathBuf>,
    },
    /// A four-bar function generator through precision points (Freudenstein: exact for
    /// three, least squares for more; JSON; --scene-out writes a scene).
    Function {
        /// CSV of precision points: `input_deg, output_deg` per row (a header allowed).
        #[arg(long)]
        points: PathBuf,
        /// Ground AD, m.
        #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
        ground: f64,
        /// Write the four-bar as a scene file here.
        #[arg(long)]
        scene_out: Option<PathBuf>,
    },
    /// A four-bar that carries a body through three, four or five positions (three:
    /// the centre points of two moving pivots; four: two fixed pivots on the
    /// centre-point curve; five: two of the Burmester points; JSON with the poles and
    /// a check by the solver; --scene-out).
    Motion {
        /// CSV of the body's positions: `x_m, y_m, angle_deg` per row (a header allowed).
        #[arg(long)]
        poses: PathBuf,
        /// Three positions: the moving pivots in the body's frame, m: x1 y1 x2 y2.
        #[arg(long, num_args = 4, allow_hyphen_values = true, value_names = ["X1", "Y1", "X2", "Y2"])]
        moving: Vec<f64>,
        /// Four positions: the fixed pivots are the centre-point curve's points
        /// nearest these, m: x1 y1 x2 y2.
        #[arg(long, num_args = 4, allow_hyphen_values = true, value_names = ["X1", "Y1", "X2", "Y2"])]
        fixed_near: Vec<f64>,
        /// Five positions: which two Burmester points (as listed, from 1) make the
        /// four-bar.
        #[arg(long, num_args = 2, value_names = ["I", "J"], allow_hyphen_values = true, value_parser = counts::at_least_one)]
        pair: Vec<usize>,
        /// Write the four-bar as a scene file here.
        #[arg(long)]
        scene_out: Option<PathBuf>,
    },
    /// A four-bar whose coupler point passes through 3 to 20 target points (a global
    /// search polished by least squares; JSON with the designs ranked by their
    /// largest miss and the time taken; the same designs for the same seed).
    Path(PathSearchArgs),
    /// The die cutter's toggle six-bar from stroke H, K and CD = CE = L (scene RON on stdout).
    DieCutter {
        /// Stroke H, mm.
        #[arg(long, allow_hyphen_values = true, default_value_t = 50.0)]
        stroke_mm: f64,
        /// Time ratio K.
        #[arg(long, allow_hyphen_values = true, default_value_t = 1.3)]
        k: f64,
        /// CD = CE = L, mm.
        #[arg(long, allow_hyphen_values = true, default_value_t = 600.0)]
        link_mm: f64,
        /// Crank speed, rpm.
        #[arg(long, allow_hyphen_values = true, default_value_t = 50.0)]
        rpm: f64,
        /// Build the "as printed" variant with these AB and BC (mm) instead.
        #[arg(long, allow_hyphen_values = true, num_args = 2, value_names = ["AB_MM", "BC_MM"])]
        as_printed: Option<Vec<f64>>,
    },
}

/// The arguments of `linkage synth path`.
#[derive(clap::Args, Debug)]
struct PathSearchArgs {
    /// CSV of targets: `x_m, y_m` per row, or `x_m, y_m, crank_deg` with --timed
    /// (a header allowed). Untimed targets are met in the order given, once round
    /// the coupler curve, in either direction.
    #[arg(long)]
    points: PathBuf,
    /// The third column prescribes the crank angle at each target (only the
    /// differences matter).
    #[arg(long)]
    timed: bool,
    /// Untimed targets may be met in any order (each where the curve passes nearest).
    #[arg(long, conflicts_with = "timed")]
    any_order: bool,
    /// Seed of the search.
    #[arg(long, default_value_t = 1, allow_hyphen_values = true, value_parser = counts::any_u64)]
    seed: u64,
    /// Write the best design as a scene file here.
    #[arg(long, alias = "scene-out")]
    out: Option<PathBuf>,
    /// Write the best design's two cognates (the other four-bars that trace the same
    /// curve) as scene files here.
    #[arg(long, num_args = 2, value_names = ["COGNATE1", "COGNATE2"])]
    cognate_out: Option<Vec<PathBuf>>,
    /// Stop after this many distinct families (a design and its two cognates)
    /// within tolerance (the search also stops when restarts find no new one).
    #[arg(long, default_value_t = 1, allow_hyphen_values = true, value_parser = counts::at_least_one)]
    solutions: usize,
    /// Within tolerance: the largest miss is at most this share of the targets' size.
    #[arg(long, default_value_t = 1e-6)]
    tolerance: f64,
    /// Most evaluations of a candidate linkage.
    #[arg(long, default_value_t = 3_000_000, allow_hyphen_values = true, value_parser = counts::at_least_one_u64)]
    max_evaluations: u64,
    /// The crank must turn through a whole revolution.
    #[arg(long)]
    crank_turns: bool,
    /// Let the crank rock (the default; kept for scripts that ask for it).
    #[arg(long, hide = true, conflicts_with = "crank_turns")]
    rocking_crank: bool,
    /// Least transmission angle over the crank's travel through the targets, degrees.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    min_transmission_deg: f64,
    /// Both ground pivots within this box, m (default: within 4 times the targets'
    /// size of their centroid, each way).
    #[arg(long, num_args = 4, allow_hyphen_values = true, value_names = ["X0", "Y0", "X1", "Y1"])]
    ground_region: Option<Vec<f64>>,
    /// Allow the targets on different assembly branches (through a dead point).
    #[arg(long)]
    any_branch: bool,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let result = commands::run(cli.command, &mut out).and_then(|()| Ok(out.flush()?));
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // A reader that closed the pipe (`| head`) has all it wanted: not an error.
        Err(commands::Failure::Output(e)) if e.kind() == ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(commands::Failure::Output(e)) => {
            eprintln!("error: cannot write the output: {e}");
            ExitCode::FAILURE
        }
        Err(commands::Failure::Message(message)) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
        Err(commands::Failure::Solver(e)) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
