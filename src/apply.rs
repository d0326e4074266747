//! How the app applies the commands the panels queued ([`Command`]): one path for
//! every change of the session, so that each kind does the same work wherever it was
//! asked for. Opening a scene or a drawing's new version replaces the session: play
//! stops, the scene edits still queued for the old session are dropped (they name its
//! links and points), and a newly opened scene is fitted in the view.

use linkage::drawing::Drawing;

use crate::command::{Command, Waiting};
use crate::drawing::DrawingEditor;
use crate::drawing::edit::DrawingEdit;
use crate::i18n::tr;
use crate::session::{SceneEdit, SceneSource, Session};
use crate::state::AppState;

/// The file name a drawing is saved and shared under until the user names one.
const DRAWING_FILE: &str = "my_mechanism.ron";
/// The name of a drawing started from nothing.
const NEW_DRAWING: &str = "My mechanism";

impl AppState {
    /// Asks for `command`: the panels ask while they are laid out, and the app applies
    /// the commands between panels ([`Self::apply_commands`]).
    pub fn push(&mut self, command: Command) {
        self.commands.queue.push(command);
    }

    /// Asks for `edit` to the open scene.
    pub fn edit(&mut self, edit: SceneEdit) {
        self.push(Command::Edit(edit));
    }

    /// Asks to open `session` in place of the open scene.
    pub fn open(&mut self, session: Session) {
        self.push(Command::Open(Box::new(session)));
    }

    /// Opens the exercise file `text` at the student's desk, in place of the labs (a
    /// refused file is said in the status line, naming the cause).
    pub fn open_exercise(&mut self, text: &str) {
        match crate::exercise::Exercise::parse(text) {
            Ok(exercise) => {
                self.gear_lab = None;
                self.course.open = false;
                self.exercise = Some(crate::exercise_desk::ExerciseDesk::new(exercise));
            }
            Err(e) => self.status = Some(e.to_string()),
        }
    }

    /// Takes the student number typed at the open desk: draws its variant and opens
    /// its scene, with the overlays that would show the answers (vectors, instant
    /// centres) and moving points off.
    pub fn start_exercise(&mut self) {
        let Some(desk) = self.exercise.as_mut() else {
            return;
        };
        if let Some(session) = desk.start() {
            self.play.playing = false;
            self.view.edit_points = false;
            self.view.layers.velocities = false;
            self.view.layers.accelerations = false;
            self.view.layers.centres = false;
            self.open(session);
        }
    }

    /// Opens the shipped exercise `key` (a link's), with `student`'s variant if one
    /// is given; an unknown key is said in the status line.
    pub fn open_exercise_link(&mut self, key: &str, student: Option<&str>) {
        let Some(e) = crate::catalog::EXERCISES.iter().find(|e| e.key == key) else {
            let known: Vec<&str> = crate::catalog::EXERCISES.iter().map(|e| e.key).collect();
            self.status = Some(format!(
                "no exercise \"{key}\" (one of {})",
                known.join(", ")
            ));
            return;
        };
        self.open_exercise(e.text);
        if let (Some(desk), Some(student)) = (self.exercise.as_mut(), student) {
            desk.student_text = student.to_string();
            self.start_exercise();
        }
    }

    /// Applies the commands asked for, in order, and adds their time to the frame's.
    pub fn apply_commands(&mut self) {
        if self.commands.queue.is_empty() {
            return;
        }
        self.commands.applied = true;
        let started = web_time::Instant::now();
        let mut queue = std::mem::take(&mut self.commands.queue).into_iter();
        while let Some(command) = queue.next() {
            if self.apply(command) == Replaced::Yes {
                // Scene edits asked of the old session mean nothing to the new one. An
                // undo or redo left in the queue finds the new session's history (empty
                // after an open) or, while drawing, the drawing's.
                let rest = queue.filter(|c| !matches!(c, Command::Edit(_)));
                queue = rest.collect::<Vec<_>>().into_iter();
            }
        }
        self.timing.edit_ms += started.elapsed().as_secs_f64() * 1e3;
    }

    fn apply(&mut self, command: Command) -> Replaced {
        match command {
            Command::Edit(edit) => {
                self.session.apply(edit);
                Replaced::No
            }
            Command::Open(session) if self.session.is_dirty() => self.ask(Waiting::Open(session)),
            Command::Open(session) => self.open_scene(*session),
            Command::StartDrawing if self.session.is_dirty() => self.ask(Waiting::Drawing),
            Command::StartDrawing => self.resume_drawing(Drawing::new(NEW_DRAWING)),
            Command::DrawCurrent => self.draw_current(),
            Command::ResumeDrawing(drawing) => self.resume_drawing(*drawing),
            Command::Drawing(edit) => self.edit_drawing(edit),
            Command::FinishDrawing => {
                self.drawing = None;
                self.commands.fit = true;
                Replaced::No
            }
            Command::Undo => self.history(DrawingEditor::undo, SceneEdit::Undo),
            Command::Redo => self.history(DrawingEditor::redo, SceneEdit::Redo),
            Command::Answer(drop_edits) => self.answer(drop_edits),
        }
    }

    /// Keeps a change that would drop unsaved edits until the user answers
    /// (`ui::scene_picker`'s question).
    fn ask(&mut self, waiting: Waiting) -> Replaced {
        self.commands.waiting = Some(waiting);
        Replaced::No
    }

    fn answer(&mut self, drop_edits: bool) -> Replaced {
        match (drop_edits, self.commands.waiting.take()) {
            (true, Some(Waiting::Open(session))) => self.open_scene(*session),
            (true, Some(Waiting::Drawing)) => self.resume_drawing(Drawing::new(NEW_DRAWING)),
            _ => Replaced::No,
        }
    }

    /// Opens `session` whatever the open scene holds, leaving any drawing.
    fn open_scene(&mut self, session: Session) -> Replaced {
        self.commands.waiting = None;
        self.drawing = None;
        self.replace_session(session);
        self.commands.fit = true;
        Replaced::Yes
    }

    fn replace_session(&mut self, session: Session) {
        self.session = session;
        self.timing.opened += 1;
        self.play.playing = false;
    }

    /// The open scene, in its current pose, as a drawing, or the reason it cannot
    /// be one in the status line.
    fn draw_current(&mut self) -> Replaced {
        let s = &self.session;
        match Drawing::from_pose(s.scene(), s.mechanism(), s.pose()) {
            Ok(drawing) => self.resume_drawing(drawing),
            Err(why) => {
                let why = crate::ui::words::not_drawable(&why);
                self.status = Some(tr!("drawing.cannot_become", why = why));
                Replaced::No
            }
        }
    }

    fn resume_drawing(&mut self, drawing: Drawing) -> Replaced {
        self.drawing = Some(DrawingEditor::new(drawing));
        self.play.playing = false;
        self.view.edit_points = false;
        self.sync_drawing()
    }

    fn edit_drawing(&mut self, edit: DrawingEdit) -> Replaced {
        if self.drawing.as_mut().is_some_and(|d| d.apply(edit)) {
            return self.sync_drawing();
        }
        Replaced::No
    }

    /// Undo or redo: of the drawing while drawing, else of the scene's edits.
    fn history(
        &mut self,
        of_drawing: fn(&mut DrawingEditor) -> bool,
        of_scene: SceneEdit,
    ) -> Replaced {
        match self.drawing.as_mut().map(of_drawing) {
            Some(true) => self.sync_drawing(),
            Some(false) => Replaced::No,
            None => self.apply(Command::Edit(of_scene)),
        }
    }

    /// Opens the drawing as the session when it is a mechanism, unsaved until the
    /// user saves it.
    fn sync_drawing(&mut self) -> Replaced {
        let Some(scene) = self.drawing.as_mut().and_then(DrawingEditor::refresh) else {
            return Replaced::No;
        };
        match Session::open_scene(SceneSource::File(DRAWING_FILE.into()), scene) {
            Ok(mut session) => {
                session.mark_unsaved();
                self.replace_session(session);
                Replaced::Yes
            }
            Err(why) => {
                let why = crate::ui::words::refusal(&why, linkage::scene::LengthUnit::Metre);
                self.status = Some(tr!("drawing.does_not_solve", why = why));
                Replaced::No
            }
        }
    }
}

/// Whether a command replaced the session.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Replaced {
    Yes,
    No,
}
