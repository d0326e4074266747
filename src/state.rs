//! The app's state that every panel reads: the model (the open session and the
//! drawing), the commands the panels queue for it, the playback, the view settings
//! the top bar sets, the status line, the layout and the frame's timings. The panels'
//! own state (the view's camera, the plot tab, the polygon pane's hover, the file
//! prompts, the synthesis window) is theirs ([`crate::ui::panels::Panels`]). This
//! module uses no panel: the panels use it. The commands are applied in `apply`.

use crate::command::{Command, Waiting};
use crate::drawing::DrawingEditor;
use crate::render::build::Layers;
use crate::session::Session;
use crate::ui::control_map::ControlMap;
use crate::ui::layout::LayoutState;

/// Scene opened at start when the URL names none.
pub const DEFAULT_SCENE: &str = "die_cutter";

/// Smoothed CPU cost of a frame's work, µs.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrameCost {
    /// Solver: the pose, polygons and shapes of the frame.
    pub solver_us: f64,
    /// The whole `ui` call: solver, panels, plots and layout (not the GPU).
    pub frame_us: f64,
}

impl FrameCost {
    pub(crate) fn add(&mut self, solver_us: f64, frame_us: f64) {
        // Exponential average over about 30 frames: steady enough to read.
        let k = if self.frame_us == 0.0 {
            1.0
        } else {
            1.0 / 30.0
        };
        self.solver_us += k * (solver_us - self.solver_us);
        self.frame_us += k * (frame_us - self.frame_us);
    }
}

/// CPU time of the frames in which an edit landed: what a user dragging a slider
/// waits for (the frame's `ui` call: the edit, the panels and plots; not the GPU),
/// and of the edits alone (what `cargo bench -p linkage-model --bench edit` measures natively).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct EditTiming {
    /// Frames that carried at least one edit.
    pub frames: u64,
    /// The last such frame, ms.
    pub last_ms: f64,
    /// The slowest such frame, ms.
    pub max_ms: f64,
    /// The last such frame's edits applied to the session, ms.
    pub last_edit_ms: f64,
    /// The slowest such frame's edits, ms.
    pub max_edit_ms: f64,
}

impl EditTiming {
    pub(crate) fn add(&mut self, frame_ms: f64, edit_ms: f64) {
        self.frames += 1;
        self.last_ms = frame_ms;
        self.max_ms = self.max_ms.max(frame_ms);
        self.last_edit_ms = edit_ms;
        self.max_edit_ms = self.max_edit_ms.max(edit_ms);
    }
}

/// What the panels asked of the model and the app, not yet done.
#[derive(Default)]
pub struct Commands {
    /// Changes of the model, applied between panels ([`AppState::apply_commands`]).
    pub queue: Vec<Command>,
    /// A change that would drop unsaved edits, until the user says whether it may.
    pub waiting: Option<Waiting>,
    /// Commands were applied in this frame: the panels laid out before them show the
    /// model as it was, so the app draws another frame.
    pub applied: bool,
    /// Fit the view at the next frame (after opening a scene or on request).
    pub fit: bool,
    /// Open the synthesis window, or close it when open.
    pub toggle_synthesis: bool,
    /// A file action another panel asked for (the cam panel's exports), started by
    /// the files panel.
    pub file: Option<crate::file_action::FileAction>,
}

/// Whether and how fast the animation runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Playback {
    /// Whether the animation runs.
    pub playing: bool,
    /// Animation speed, times real time.
    pub speed: f64,
}

/// What the top bar sets for the view and the exported sheet.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ViewSettings {
    /// Overlays on the mechanism.
    pub layers: Layers,
    /// Whether dragging in the view moves points (else it pans).
    pub edit_points: bool,
}

/// What the frames cost, measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timing {
    /// Frame cost.
    pub cost: FrameCost,
    /// How long the frames that carried an edit took.
    pub edit_timing: EditTiming,
    /// Time spent applying this frame's edits so far, ms.
    pub edit_ms: f64,
    /// Counts scenes opened (a frame that opens one is an edit frame).
    pub opened: u64,
    /// Show measured CPU times (off in snapshot tests, whose pixels must repeat).
    pub show: bool,
}

/// Everything the panels read and change.
pub struct AppState {
    /// The mechanism being viewed.
    pub session: Session,
    /// The mechanism being drawn, while the drawing tools are out.
    pub drawing: Option<DrawingEditor>,
    /// The gear-cutting lab, while it is open in place of the mechanism view.
    pub gear_lab: Option<crate::gear_lab::GearLab>,
    /// The exercise open on the student's side, in place of the analyses.
    pub exercise: Option<crate::exercise_desk::ExerciseDesk>,
    /// What the panels asked for and the app has not yet done.
    pub commands: Commands,
    /// The animation.
    pub play: Playback,
    /// The view's overlays and mode.
    pub view: ViewSettings,
    /// A line about the last file action (saved, exported, failed).
    pub status: Option<String>,
    /// Where this frame's controls are (tests drive the app through it).
    pub controls: ControlMap,
    /// The arrangement of the panels for the screen, and the sheet's tab.
    pub layout: LayoutState,
    /// What the frames cost.
    pub timing: Timing,
    /// The language of the app's words (`crate::i18n`), set by the top bar's switch.
    pub language: crate::i18n::Language,
    /// Whether the language chosen is kept for the next run
    /// ([`crate::StartOptions::remember_choices`]).
    pub remember_choices: bool,
    /// The course sheet's window and its choices.
    pub course: CourseOptions,
}

/// The course sheet's choices, as its window holds them.
#[derive(Clone, Debug, PartialEq)]
pub struct CourseOptions {
    /// Whether its window is open.
    pub open: bool,
    /// Positions over the crank's range (12, as the course asks).
    pub positions: usize,
    /// Whether position 0 is at the start of the crank's range.
    pub from_start: bool,
    /// Otherwise the crank angle of position 0, degrees.
    pub first_deg: f64,
    /// The positions drawn with their polygons, as typed ("1, 7").
    pub chosen: String,
}

impl Default for CourseOptions {
    fn default() -> Self {
        Self {
            open: false,
            positions: linkage_diagram::course::DEFAULT_POSITIONS,
            from_start: true,
            first_deg: 0.0,
            chosen: "1, 7".into(),
        }
    }
}

impl CourseOptions {
    /// What the window asks for, or what is wrong with its text.
    pub fn choice(&self) -> Result<crate::session::CourseChoice, String> {
        Ok(crate::session::CourseChoice {
            positions: self.positions,
            first_deg: (!self.from_start).then_some(self.first_deg),
            chosen: self.chosen_numbers()?,
        })
    }

    /// The chosen positions' numbers, or what is wrong with the text (with the
    /// valid range).
    pub fn chosen_numbers(&self) -> Result<Vec<usize>, String> {
        let last = self.positions.saturating_sub(1);
        self.chosen
            .split(|c: char| c == ',' || c == '，' || c.is_whitespace())
            .filter(|t| !t.is_empty())
            .map(|t| match t.parse::<usize>() {
                Ok(n) if n <= last => Ok(n),
                _ => Err(crate::i18n::tr!("course.bad_chosen", text = t, last = last)),
            })
            .collect()
    }
}

impl AppState {
    /// State over `session`, paused, fitted at the first frame.
    pub fn new(session: Session) -> Self {
        Self {
            session,
            drawing: None,
            gear_lab: None,
            exercise: None,
            commands: Commands {
                fit: true,
                ..Commands::default()
            },
            play: Playback {
                playing: false,
                speed: 1.0,
            },
            view: ViewSettings::default(),
            status: None,
            controls: ControlMap::default(),
            layout: LayoutState::default(),
            timing: Timing {
                cost: FrameCost::default(),
                edit_timing: EditTiming::default(),
                edit_ms: 0.0,
                opened: 0,
                show: true,
            },
            language: crate::i18n::Language::English,
            remember_choices: false,
            course: CourseOptions::default(),
        }
    }
}
