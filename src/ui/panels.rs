//! The panels' own state, each panel's in its struct: the view's camera and drag,
//! the plot tab, the polygon pane's hover and construction, the file prompts and the
//! synthesis window. The app owns them beside the [`crate::state::AppState`] they
//! all read; a panel changes the model only through the state's commands.

use crate::ui::files::Files;
use crate::ui::plots::PlotsPanel;
use crate::ui::polygons::PolygonPane;
use crate::ui::synthesis::SynthesisWindow;
use crate::ui::viewport::Viewport;

/// Every panel's own state.
#[derive(Default)]
pub struct Panels {
    /// The mechanism view (and the drawing canvas, which shares its camera).
    pub viewport: Viewport,
    /// The plot pane.
    pub plots: PlotsPanel,
    /// The polygon pane.
    pub polygons: PolygonPane,
    /// File prompts, dialogs and uploads.
    pub files: Files,
    /// The synthesis window.
    pub synthesis: SynthesisWindow,
}
