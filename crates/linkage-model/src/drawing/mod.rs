//! Building one's own mechanism: the drawing being made (a [`Drawing`]), its undo and
//! redo history, the tool in hand and the first end of a link being drawn. The
//! canvas (`ui::drawing_canvas`) turns pointer events into [`edit::DrawingEdit`]
//! values; [`DrawingEditor::apply`] makes them. Whenever the drawing is a complete
//! mechanism the app opens it as its session, so the report, the plots and the
//! polygons follow the drawing as it grows.

pub mod drawing_edit;
pub mod edit;
pub mod loads;
pub mod stored;

use linkage::SceneFile;
use linkage::drawing::{Drawing, DrawingProblem};

use edit::{DrawingEdit, End, Refusal};

/// What a click on the canvas does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tool {
    /// Places a ground pivot (or fixes a point to ground).
    Pivot,
    /// Draws a link between two points, or adds a point to a link.
    Link,
    /// Puts a slider block on a point, on a horizontal ground guide.
    Slider,
    /// Picks the input link.
    Driver,
    /// Drags points.
    Move,
    /// Joins two points by a spring.
    Spring,
    /// Joins two points by a damper.
    Damper,
    /// Puts a force on a point.
    Force,
    /// Deletes a point or a link.
    Delete,
}

impl Tool {
    /// Every tool, in the panel's order.
    pub const ALL: [Tool; 9] = [
        Tool::Pivot,
        Tool::Link,
        Tool::Slider,
        Tool::Driver,
        Tool::Move,
        Tool::Spring,
        Tool::Damper,
        Tool::Force,
        Tool::Delete,
    ];

    /// The tool's id in English (the control map's name; the app words it in the
    /// user's language).
    pub fn label(self) -> &'static str {
        match self {
            Tool::Pivot => "Pivot",
            Tool::Link => "Link",
            Tool::Slider => "Slider",
            Tool::Driver => "Driver",
            Tool::Move => "Move",
            Tool::Spring => "Spring",
            Tool::Damper => "Damper",
            Tool::Force => "Force",
            Tool::Delete => "Delete",
        }
    }
}

/// The first click of a two-click edit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pending {
    /// A link's first end.
    LinkFrom(End),
    /// The link a point is being added to.
    OnLink(usize),
    /// A spring's or damper's first point.
    ElementFrom {
        /// A damper (else a spring).
        damper: bool,
        /// The first point.
        point: usize,
    },
}

/// The drawing being built and how.
pub struct DrawingEditor {
    drawing: Drawing,
    undo: Vec<Drawing>,
    redo: Vec<Drawing>,
    /// Whether a drag's edits are being merged into one undo step.
    gesture_open: bool,
    /// The tool in hand.
    pub tool: Tool,
    /// The first click of a link, if made.
    pub pending: Option<Pending>,
    /// The point being dragged (move tool).
    pub dragged: Option<usize>,
    /// Why the last edit was refused, until the next one.
    pub refusal: Option<Refusal>,
    /// Why the drawing is not yet a mechanism (`None`: it is one), as of the last
    /// [`DrawingEditor::refresh`].
    pub problem: Option<DrawingProblem>,
    /// Fit the view to the drawing at the next frame.
    pub fit_pending: bool,
    /// Counts the drawing's changes (to store it only when it changed).
    revision: u64,
    /// A name being typed in the side panel, and whose.
    pub naming: Option<(edit::Named, String)>,
}

impl DrawingEditor {
    /// Starts from `drawing` (empty for a new drawing).
    pub fn new(drawing: Drawing) -> Self {
        Self {
            drawing,
            undo: Vec::new(),
            redo: Vec::new(),
            gesture_open: false,
            tool: Tool::Pivot,
            pending: None,
            dragged: None,
            refusal: None,
            problem: Some(DrawingProblem::NoLinks),
            fit_pending: true,
            revision: 0,
            naming: None,
        }
    }

    /// How many times the drawing changed (edits, undo and redo).
    pub fn revision(&self) -> u64 {
        self.revision
    }

    /// The drawing.
    pub fn drawing(&self) -> &Drawing {
        &self.drawing
    }

    /// The scene of the drawing when it is a mechanism; else notes why not in
    /// [`DrawingEditor::problem`].
    pub fn refresh(&mut self) -> Option<SceneFile> {
        match self.drawing.to_scene() {
            Ok(scene) => {
                self.problem = None;
                Some(scene)
            }
            Err(why) => {
                self.problem = Some(why);
                None
            }
        }
    }

    /// Makes `edit`; returns whether the drawing changed. A refused edit leaves the
    /// drawing and says why ([`DrawingEditor::refusal`]). Edits during a gesture (a drag)
    /// are one undo step.
    pub fn apply(&mut self, edit: DrawingEdit) -> bool {
        let is_move = matches!(edit, DrawingEdit::MovePoint { .. });
        // Indices shift when something goes: a name being typed would land elsewhere.
        if matches!(
            edit,
            DrawingEdit::DeletePoint(_) | DrawingEdit::DeleteLink(_)
        ) {
            self.naming = None;
        }
        match edit::apply(&self.drawing, edit) {
            Ok(next) if next == self.drawing => false,
            Ok(next) => {
                if !self.gesture_open {
                    self.undo.push(self.drawing.clone());
                    self.redo.clear();
                }
                self.gesture_open = is_move && self.dragged.is_some();
                self.drawing = next;
                self.refusal = None;
                self.revision += 1;
                true
            }
            Err(why) => {
                self.refusal = Some(why);
                false
            }
        }
    }

    /// Ends a drag: the next edit is a new undo step.
    pub fn end_gesture(&mut self) {
        self.gesture_open = false;
        self.dragged = None;
    }

    /// Takes back the last edit; returns whether there was one.
    pub fn undo(&mut self) -> bool {
        self.travel(true)
    }

    /// Makes the last undone edit again; returns whether there was one.
    pub fn redo(&mut self) -> bool {
        self.travel(false)
    }

    /// Whether there is an edit to take back.
    pub fn can_undo(&self) -> bool {
        !self.undo.is_empty()
    }

    /// Whether there is an undone edit to make again.
    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }

    fn travel(&mut self, back: bool) -> bool {
        self.end_gesture();
        self.pending = None;
        self.naming = None;
        let (from, to) = if back {
            (&mut self.undo, &mut self.redo)
        } else {
            (&mut self.redo, &mut self.undo)
        };
        let Some(drawing) = from.pop() else {
            return false;
        };
        to.push(std::mem::replace(&mut self.drawing, drawing));
        self.refusal = None;
        self.revision += 1;
        true
    }
}
