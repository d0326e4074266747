//! The command line as clap reads it: every subcommand and its options. A leaf of
//! the CLI: the commands read these, and `main` dispatches on them.

use std::path::PathBuf;

use linkage_diagram::words::Lang;

use clap::{Parser, Subcommand, ValueEnum};

use crate::counts;

/// Planar linkage kinematics, analysis and synthesis from scene files.
#[derive(Parser, Debug)]
#[command(name = "linkage", version, about)]
pub(crate) struct Cli {
    #[command(subcommand)]
    pub(crate) command: Command,
}

/// Output format.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub(crate) enum Format {
    Csv,
    Json,
}

/// Output format of a command that has a summary.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub(crate) enum SummaryFormat {
    /// The key figures, one a line.
    Text,
    /// The cycle, a row per angle.
    Csv,
    /// The key figures and the cycle.
    Json,
}

/// Output format of `report`.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub(crate) enum ReportFormat {
    /// A readable summary in the scene's length unit and degrees.
    Text,
    /// Every figure in SI (m, rad), for programs.
    Json,
}

/// Solver path.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub(crate) enum PathArg {
    /// Closed form when the chain decomposes into dyads, else Newton.
    Auto,
    /// Closed-form Assur dyads.
    ClosedForm,
    /// Newton–Raphson on the loop-closure constraints.
    Newton,
}

/// `linkage train`'s file and options.
#[derive(clap::Args, Debug)]
pub(crate) struct TrainArgs {
    /// Train file (RON), e.g. assets/trains/planetary_ring_fixed.ron.
    pub file: PathBuf,
    /// A member's speed in rpm, replacing the file's inputs (repeat for two).
    #[arg(long, num_args = 2, value_names = ["MEMBER", "RPM"], allow_hyphen_values = true, action = clap::ArgAction::Append)]
    pub input: Vec<String>,
    /// The member to reduce the members' inertias to (kg·m²).
    #[arg(long)]
    pub reduce_to: Option<String>,
    /// A load on a member whose speed is not given, N·m from outside,
    /// counter-clockwise positive: every member's torque and power (ideal gears).
    #[arg(long, num_args = 2, value_names = ["MEMBER", "N_M"], allow_hyphen_values = true)]
    pub load: Vec<String>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    pub format: ReportFormat,
}

/// Options shared by the commands that solve a scene.
#[derive(clap::Args, Debug)]
pub(crate) struct SceneArgs {
    /// Scene file (RON).
    pub(crate) scene: PathBuf,
    /// Override assembly branches: POINT=left|right|along|against|flip[,...]
    #[arg(long)]
    pub(crate) branch: Option<String>,
    /// Solver path.
    #[arg(long, value_enum, default_value_t = PathArg::Auto)]
    pub(crate) path: PathArg,
    /// Input speed in rad/s for velocities (default: the scene's crank speed).
    #[arg(long, allow_hyphen_values = true)]
    pub(crate) speed_rad_s: Option<f64>,
}

#[derive(Subcommand, Debug)]
pub(crate) enum Command {
    /// One input cycle (or the assemblable range) as CSV or JSON. CSV is the table a
    /// report takes: the input in degrees, lengths in the scene's unit, columns named
    /// with their units, plain decimals. JSON is SI (m, rad), for programs.
    Sweep {
        #[command(flatten)]
        scene: SceneArgs,
        /// Number of positions, at least 2, instead of whole multiples of --step-deg.
        /// A crank's full turn is cut into N equal steps from its start angle (N = 12
        /// gives 0, 30, …, 330 deg from the start: the turn's end is its start again);
        /// an input that rocks between dead points gets N positions from one end of
        /// its range to the other, both ends included (a millionth of the range
        /// inside the dead points, which a note on stderr names). JSON's default is
        /// 360.
        #[arg(long, allow_hyphen_values = true, value_parser = counts::at_least_two, conflicts_with = "step_deg")]
        steps: Option<usize>,
        /// The input's step in degrees (0.01 to 360): the rows are the whole
        /// multiples of it, 0, 1, 2, …, 359 deg for 1 on a crank's full turn, and those
        /// between the dead points of an input that rocks. CSV's default is 1.
        #[arg(long, allow_hyphen_values = true)]
        step_deg: Option<f64>,
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
    /// Assembly range, limit positions, strokes, swings, K, Grashof, transmission
    /// angle, toggles, and each output's largest speed and acceleration (located):
    /// JSON in SI for programs, or text in the scene's unit and degrees.
    Report {
        #[command(flatten)]
        scene: SceneArgs,
        /// Output format.
        #[arg(long, value_enum, default_value_t = ReportFormat::Json)]
        format: ReportFormat,
    },
    /// Forward dynamics of the 1-DOF chain from rest at the scene's start angle:
    /// samples on a uniform time grid (CSV or JSON with events and cost).
    Simulate {
        #[command(flatten)]
        scene: SceneArgs,
        #[command(flatten)]
        sim: SimArgs,
        /// Output format.
        #[arg(long, value_enum, default_value_t = Format::Csv)]
        format: Format,
    },
    /// A disc cam from its file (RON, millimetres and degrees): s, v, a, jerk, pitch
    /// and profile points, pressure angle and radii of curvature over the turn (CSV,
    /// or JSON with the joins' continuity, the laws' peak coefficients and the cam's
    /// extremes); --dxf writes the profile for manufacture, --svg its sheet.
    Cam {
        /// The cam file.
        file: PathBuf,
        /// Cam angles over the turn.
        #[arg(long, default_value_t = 360)]
        samples: usize,
        /// Output format.
        #[arg(long, value_enum, default_value_t = CamFormat::Csv)]
        format: CamFormat,
        /// Write the profile, the pitch curve and the base circle as DXF (mm) here.
        #[arg(long)]
        dxf: Option<PathBuf>,
        /// Write the profile's sheet (full size where it fits A4, limits marked) as
        /// SVG here.
        #[arg(long)]
        svg: Option<PathBuf>,
        /// The sheet's language: en or zh-CN (简体中文).
        #[arg(long, default_value = "en", value_parser = sheet_lang)]
        lang: Lang,
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
    /// Flywheel sizing by the energy method: the crank torque over one cycle at the
    /// scene's speed, its mean (torque and power), the work surplus range and the
    /// flywheel inertia J_F = ΔW_max / (ω² δ).
    Flywheel {
        #[command(flatten)]
        scene: SceneArgs,
        /// Coefficient of speed fluctuation δ = (ω_max − ω_min)/ω_mean, in (0, 1).
        #[arg(long, default_value_t = 0.05, allow_hyphen_values = true)]
        delta: f64,
        /// Output: the key figures (text), the cycle (CSV), or both (JSON).
        #[arg(long, value_enum, default_value_t = SummaryFormat::Text)]
        format: SummaryFormat,
    },
    /// Shaking force and moment on the frame over one cycle at the scene's crank
    /// speed, before and after the counterweights that balance it best (on the crank
    /// unless --on names links pivoted to the frame), with the driving torque and
    /// flywheel (δ 0.05) each needs.
    Shaking {
        #[command(flatten)]
        scene: SceneArgs,
        /// The point moments are taken about, m (x y).
        #[arg(long, num_args = 2, value_names = ["X", "Y"], default_values_t = [0.0, 0.0], allow_hyphen_values = true)]
        about: Vec<f64>,
        /// The links that carry counterweights, by name (each pivoted to the frame:
        /// the crank, a rocker); default the crank.
        #[arg(long, num_args = 1.., value_name = "LINK")]
        on: Vec<String>,
        /// What the counterweights minimise: the force's root mean square or its
        /// peak.
        #[arg(long, value_enum, default_value_t = AimArg::Rms)]
        aim: AimArg,
        /// Output: the key figures (text), the cycle before and after (CSV), or both
        /// (JSON).
        #[arg(long, value_enum, default_value_t = SummaryFormat::Text)]
        format: SummaryFormat,
    },
    /// The work-precision table: per method and tolerance or step, CPU time, RHS
    /// evaluations and error against a DOP853 rtol-1e-13 reference (CSV; --png plots it).
    Tradeoff {
        #[command(flatten)]
        scene: SceneArgs,
        #[command(flatten)]
        args: TradeoffArgs,
    },
    /// The course sheet: the plan of positions (12 by default), the output's
    /// displacement, velocity and acceleration diagrams with the positions marked,
    /// the polygons at chosen positions and the force polygons at the first (SVG;
    /// --png too).
    CourseSheet {
        #[command(flatten)]
        scene: SceneArgs,
        #[command(flatten)]
        args: CourseArgs,
    },
    /// The course-design report (课程设计说明书): the task's data, the structure
    /// (degrees of freedom, Assur groups), the positions table, the plan, the s–v–a
    /// diagrams, the polygons with their vector equations at chosen positions, the
    /// force polygons, the flywheel, the cams and the results, on A4 pages (--pdf;
    /// --lang zh-CN for Chinese).
    CourseReport {
        #[command(flatten)]
        scene: SceneArgs,
        #[command(flatten)]
        args: CourseArgs,
    },
    /// The timing diagram: every output (links pinned to ground, sliders) against the
    /// main shaft's angle as a share of its stroke, with its dwells (CSV or JSON;
    /// --svg and --png write the sheet).
    Timing {
        #[command(flatten)]
        scene: SceneArgs,
        /// Shaft angles over the cycle.
        #[arg(long, default_value_t = 360)]
        samples: usize,
        /// Output format.
        #[arg(long, value_enum, default_value_t = Format::Csv)]
        format: Format,
        /// Where the sheet goes (no sheet without --svg or --png).
        #[command(flatten)]
        out: SheetOut,
    },
    /// An A4 sheet of one position to hand in: pose, velocity and acceleration
    /// polygons with scales, vector-equation tables, instant centres (SVG; --png too).
    Diagram {
        #[command(flatten)]
        scene: SceneArgs,
        #[command(flatten)]
        args: DiagramArgs,
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
    /// Exercises for a class: each student's variant of an exercise file (RON,
    /// docs/exercises.md), the answer codes, the class graded.
    Exercise {
        #[command(subcommand)]
        what: ExerciseCommand,
    },
    /// Dimensional synthesis.
    Synth {
        #[command(subcommand)]
        what: SynthCommand,
    },
    /// Involute spur gears: a meshing pair's geometry, contact ratio and checks.
    Gears {
        #[command(subcommand)]
        what: GearsCommand,
    },
    /// A gear train from its file (RON: members, gears, meshes, belt and chain stages,
    /// inputs): every member's speed, the ratios to the first input, Willis' converted
    /// ratios and a planetary set's assembly conditions (text, or JSON).
    Train {
        #[command(flatten)]
        args: TrainArgs,
    },
}

#[derive(Subcommand, Debug)]
pub(crate) enum ExerciseCommand {
    /// Checks an exercise file and says what it asks and what varies.
    Check {
        /// Exercise file (RON).
        file: PathBuf,
    },
    /// The class's variants: each student's dimensions and the true answers (the
    /// teacher's key), as CSV.
    Variants {
        /// Exercise file (RON).
        file: PathBuf,
        /// The class list: a CSV whose first column holds the students' numbers.
        #[arg(long)]
        students: PathBuf,
    },
    /// A student's answer code from answers typed with their units (one --answer
    /// per question, in order; "" for one not answered).
    Code {
        /// Exercise file (RON).
        file: PathBuf,
        /// The student's number.
        #[arg(long)]
        student: String,
        /// An answer, e.g. "1.25 m/s" (repeat for every question).
        #[arg(long, allow_hyphen_values = true)]
        answer: Vec<String>,
    },
    /// Every student's task sheet (A4: the title and number, the mechanism drawn,
    /// the student's data, the questions with lines for the answers), one after
    /// another in one PDF (or SVG/PNG pages).
    Sheets {
        /// Exercise file (RON).
        file: PathBuf,
        /// The class list: a CSV whose first column holds the students' numbers.
        #[arg(long)]
        students: PathBuf,
        #[command(flatten)]
        out: SheetOut,
    },
    /// Grades answer codes (one a line, or a CSV with a column of them) and writes
    /// the grades as CSV; lines that are not valid codes are reported on stderr.
    Grade {
        /// Exercise file (RON).
        file: PathBuf,
        /// The answer codes.
        #[arg(long)]
        answers: PathBuf,
        /// The class list (a CSV whose first column holds the students' numbers):
        /// codes from others are reported, students without a code graded 0.
        #[arg(long)]
        students: Option<PathBuf>,
        /// Where to write the grades (default: standard output).
        #[arg(long)]
        out: Option<PathBuf>,
    },
}

#[derive(Subcommand, Debug)]
pub(crate) enum SynthCommand {
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
pub(crate) struct PathSearchArgs {
    /// CSV of targets: `x_m, y_m` per row, or `x_m, y_m, crank_deg` with --timed
    /// (a header allowed). Untimed targets are met in the order given, once round
    /// the coupler curve, in either direction.
    #[arg(long)]
    pub(crate) points: PathBuf,
    /// The third column prescribes the crank angle at each target (only the
    /// differences matter).
    #[arg(long)]
    pub(crate) timed: bool,
    /// Untimed targets may be met in any order (each where the curve passes nearest).
    #[arg(long, conflicts_with = "timed")]
    pub(crate) any_order: bool,
    /// Seed of the search.
    #[arg(long, default_value_t = 1, allow_hyphen_values = true, value_parser = counts::any_u64)]
    pub(crate) seed: u64,
    /// Write the best design as a scene file here.
    #[arg(long, alias = "scene-out")]
    pub(crate) out: Option<PathBuf>,
    /// Write the best design's two cognates (the other four-bars that trace the same
    /// curve) as scene files here.
    #[arg(long, num_args = 2, value_names = ["COGNATE1", "COGNATE2"])]
    pub(crate) cognate_out: Option<Vec<PathBuf>>,
    /// Stop after this many distinct families (a design and its two cognates)
    /// within tolerance (the search also stops when restarts find no new one).
    #[arg(long, default_value_t = 1, allow_hyphen_values = true, value_parser = counts::at_least_one)]
    pub(crate) solutions: usize,
    /// Within tolerance: the largest miss is at most this share of the targets' size.
    #[arg(long, default_value_t = 1e-6)]
    pub(crate) tolerance: f64,
    /// Most evaluations of a candidate linkage.
    #[arg(long, default_value_t = 3_000_000, allow_hyphen_values = true, value_parser = counts::at_least_one_u64)]
    pub(crate) max_evaluations: u64,
    /// The crank must turn through a whole revolution.
    #[arg(long)]
    pub(crate) crank_turns: bool,
    /// Let the crank rock (the default; kept for scripts that ask for it).
    #[arg(long, hide = true, conflicts_with = "crank_turns")]
    pub(crate) rocking_crank: bool,
    /// Least transmission angle over the crank's travel through the targets, degrees.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub(crate) min_transmission_deg: f64,
    /// Both ground pivots within this box, m (default: within 4 times the targets'
    /// size of their centroid, each way).
    #[arg(long, num_args = 4, allow_hyphen_values = true, value_names = ["X0", "Y0", "X1", "Y1"])]
    pub(crate) ground_region: Option<Vec<f64>>,
    /// Allow the targets on different assembly branches (through a dead point).
    #[arg(long)]
    pub(crate) any_branch: bool,
}

/// Options of `linkage diagram`.
#[derive(clap::Args, Debug)]
pub(crate) struct DiagramArgs {
    /// Input (crank) angle in degrees.
    #[arg(long, allow_hyphen_values = true)]
    pub(crate) input_deg: f64,
    /// Where the sheet goes.
    #[command(flatten)]
    pub(crate) out: SheetOut,
    /// What the sheet holds, comma-separated. By default the force polygons are
    /// drawn where the scene has masses or forces and the position has them.
    #[arg(long, value_enum, value_delimiter = ',', default_values_t = DEFAULT_PARTS)]
    pub(crate) what: Vec<Part>,
}

/// Where a sheet goes: SVG, PNG and PDF files, or a one-page sheet's SVG to
/// standard output.
#[derive(clap::Args, Debug)]
pub(crate) struct SheetOut {
    /// Write the SVG here, a file per A4 page: FILE, then FILE-2, FILE-3 … (without
    /// --svg, --png or --pdf a one-page sheet goes to standard output).
    #[arg(long)]
    pub(crate) svg: Option<PathBuf>,
    /// Write a PNG here, rendered from the SVG, a file per page as for --svg.
    #[arg(long)]
    pub(crate) png: Option<PathBuf>,
    /// Write the sheet as one PDF here: every page, text selectable, fonts embedded.
    #[arg(long)]
    pub(crate) pdf: Option<PathBuf>,
    /// The sheet's language: en or zh-CN (简体中文).
    #[arg(long, default_value = "en", value_parser = sheet_lang)]
    pub(crate) lang: Lang,
    /// PNG resolution, dots per inch (the sheet is A4 wide).
    #[arg(long, default_value_t = 150.0)]
    pub(crate) dpi: f32,
}

/// Options of `linkage course-sheet`.
#[derive(clap::Args, Debug)]
pub(crate) struct CourseArgs {
    /// Positions over the crank's range, numbered from 0 at its start.
    #[arg(long, default_value_t = 12)]
    pub(crate) positions: usize,
    /// The crank angle of position 0, degrees (default the start of the crank's
    /// range): any angle on a crank that turns, one of its range on one that rocks.
    #[arg(long, allow_hyphen_values = true)]
    pub(crate) first_deg: Option<f64>,
    /// The positions drawn with their polygons (the first also with its force
    /// polygons); default the second and the one half a range on.
    #[arg(long, num_args = 1..)]
    pub(crate) chosen: Vec<usize>,
    /// Where the sheet goes.
    #[command(flatten)]
    pub(crate) out: SheetOut,
}

/// What `linkage diagram` draws unless told.
pub(crate) const DEFAULT_PARTS: [Part; 5] = [
    Part::Pose,
    Part::Velocity,
    Part::Acceleration,
    Part::Table,
    Part::Forces,
];

/// Options of a dynamics run.
#[derive(clap::Args, Debug, Clone)]
pub(crate) struct SimArgs {
    /// Instead of a run from rest: the periodic steady state with the scene's drive
    /// (shooting on the crank speed, DOP853 at rtol 1e-12), one turn sampled
    /// (`t_s,angle_rad,speed_rad_s`; JSON adds speed max, min, mean, delta, period).
    #[arg(long)]
    pub(crate) steady: bool,
    /// Integration method.
    #[arg(long, value_enum, default_value_t = MethodArg::Dop853)]
    pub(crate) method: MethodArg,
    /// Time step of the fixed-step methods, s; for the adaptive ones the largest step
    /// (default: none).
    #[arg(long, allow_hyphen_values = true)]
    pub(crate) dt: Option<f64>,
    /// Angle step of the energy-increment method, rad.
    #[arg(long, allow_hyphen_values = true, default_value_t = 1e-4)]
    pub(crate) dphi: f64,
    /// Relative tolerance of the adaptive methods.
    #[arg(long, allow_hyphen_values = true, default_value_t = 1e-10)]
    pub(crate) rtol: f64,
    /// Absolute tolerance of the adaptive methods (rad, rad/s).
    #[arg(long, allow_hyphen_values = true, default_value_t = 1e-12)]
    pub(crate) atol: f64,
    /// End time, s (or the first end stop).
    #[arg(long, allow_hyphen_values = true, default_value_t = 1.0)]
    pub(crate) t_end: f64,
    /// Ignore the scene's end stops.
    #[arg(long)]
    pub(crate) no_stops: bool,
    /// Output grid, s (the method's dense output).
    #[arg(long, allow_hyphen_values = true, default_value_t = 1e-3)]
    pub(crate) dt_out: f64,
    /// Link whose angle is the coordinate at the start (default: the scene's driver).
    #[arg(long)]
    pub(crate) coordinate: Option<String>,
    /// Keep the starting coordinate through its dead points (the run then fails
    /// there instead of switching).
    #[arg(long)]
    pub(crate) no_switch: bool,
}

/// Options of `linkage tradeoff`.
#[derive(clap::Args, Debug)]
pub(crate) struct TradeoffArgs {
    /// End time, s (or the first end stop).
    #[arg(long, allow_hyphen_values = true, default_value_t = 2.0)]
    pub(crate) t_end: f64,
    /// Ignore the scene's end stops.
    #[arg(long)]
    pub(crate) no_stops: bool,
    /// Grid on which the error against the reference is measured, s.
    #[arg(long, allow_hyphen_values = true, default_value_t = 1e-3)]
    pub(crate) grid: f64,
    /// Also write the error-against-CPU-time plot here (PNG).
    #[arg(long)]
    pub(crate) png: Option<PathBuf>,
}

/// A part of the sheet.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum Part {
    /// The mechanism's pose, with a scale bar.
    Pose,
    /// The velocity polygon.
    Velocity,
    /// The acceleration polygon.
    Acceleration,
    /// The instant centres on the pose.
    Centres,
    /// The vector-equation tables.
    Table,
    /// The force polygons, group by group from the output back to the crank, with
    /// their tables (a scene with kinetostatics or dynamics data).
    Forces,
}

/// What `linkage cam` writes.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum CamFormat {
    /// A row per cam angle.
    Csv,
    /// The figures and the rows.
    Json,
}

/// What counterweights minimise.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum AimArg {
    /// The shaking force's root mean square.
    Rms,
    /// The shaking force's peak.
    Peak,
}

/// Integration method.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum MethodArg {
    /// The flipper paper's energy increments (steps of --dphi).
    Energy,
    /// Semi-implicit (symplectic) Euler, fixed --dt.
    Euler,
    /// Classical Runge–Kutta 4, fixed --dt.
    Rk4,
    /// Implicit midpoint, fixed --dt: A-stable, for stiff springs.
    Implicit,
    /// Adaptive Dormand–Prince 5(4), --rtol/--atol.
    Dp5,
    /// Adaptive Dormand–Prince 8(5,3), --rtol/--atol.
    Dop853,
}

/// A sheet's language from `--lang`: English (en) or Simplified Chinese (zh-CN, zh).
fn sheet_lang(text: &str) -> Result<Lang, String> {
    let lower = text.trim().to_ascii_lowercase();
    match lower.as_str() {
        "en" | "en-us" | "en-gb" | "english" => Ok(Lang::English),
        _ if Lang::from_tag(&lower) == Lang::Chinese => Ok(Lang::Chinese),
        _ => Err(format!("{text:?} is not a sheet language: en or zh-CN")),
    }
}

/// What `linkage gears` does.
#[derive(Subcommand, Debug)]
pub(crate) enum GearsCommand {
    /// A meshing pair: circles, tooth thicknesses, working pressure angle, centre
    /// distance, contact ratio and the checks (undercut, interference, pointed tips,
    /// clearance). Text in mm and degrees; JSON in SI (m, rad).
    Pair(PairArgs),
    /// One gear as a rack cutter cuts it (GB/T 1356's basic rack, its tip rounded):
    /// the whole outline with its fillets and any undercut, as SVG (mm) or DXF.
    Profile(ProfileArgs),
}

/// A gear's numbers for its cut profile: millimetres and degrees.
#[derive(clap::Args, Debug)]
pub(crate) struct ProfileArgs {
    /// Module, mm.
    #[arg(long, allow_hyphen_values = true)]
    pub(crate) module: f64,
    /// Number of teeth.
    #[arg(long)]
    pub(crate) teeth: u32,
    /// Profile shift coefficient.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub(crate) shift: f64,
    /// The basic rack's pressure angle, degrees.
    #[arg(long, default_value_t = 20.0, allow_hyphen_values = true)]
    pub(crate) pressure_angle_deg: f64,
    /// Write the drawing as SVG here.
    #[arg(long)]
    pub(crate) svg: Option<PathBuf>,
    /// Write the outline as DXF (millimetres) here.
    #[arg(long)]
    pub(crate) dxf: Option<PathBuf>,
    /// An internal gear (a ring), cut by a pinion cutter (a gear shaper) instead of
    /// a rack.
    #[arg(long)]
    pub(crate) internal: bool,
    /// The pinion cutter's number of teeth, for an internal gear.
    #[arg(long, default_value_t = 25)]
    pub(crate) cutter_teeth: u32,
}

/// A pair's numbers as typed: millimetres and degrees.
#[derive(clap::Args, Debug)]
pub(crate) struct PairArgs {
    /// Module, mm.
    #[arg(long, allow_hyphen_values = true)]
    pub(crate) module: f64,
    /// The pinion's and the wheel's numbers of teeth.
    #[arg(long, num_args = 2, value_names = ["Z1", "Z2"], required = true)]
    pub(crate) teeth: Vec<u32>,
    /// The pinion's and the wheel's profile shift coefficients.
    #[arg(long, num_args = 2, value_names = ["X1", "X2"], allow_hyphen_values = true, default_values_t = [0.0, 0.0])]
    pub(crate) shift: Vec<f64>,
    /// The basic rack's pressure angle, degrees.
    #[arg(long, default_value_t = 20.0, allow_hyphen_values = true)]
    pub(crate) pressure_angle_deg: f64,
    /// Addendum coefficient h_a*.
    #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
    pub(crate) addendum: f64,
    /// Clearance coefficient c*.
    #[arg(long, default_value_t = 0.25, allow_hyphen_values = true)]
    pub(crate) clearance: f64,
    /// A centre distance, mm (else the one the shifts give, without backlash).
    #[arg(long, allow_hyphen_values = true)]
    pub(crate) centre_distance: Option<f64>,
    /// The wheel has internal teeth (a ring round the pinion).
    #[arg(long)]
    pub(crate) internal: bool,
    /// Output format.
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    pub(crate) format: ReportFormat,
}
