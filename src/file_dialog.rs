//! The desktop's file dialog: the system's own, through rfd (on Linux the XDG desktop
//! portal, reached through a libdbus loaded at run time, and zenity where no portal
//! answers; no GTK at build time). It sits behind [`PathChooser`] so that UI tests can
//! answer the dialog themselves.

use std::path::PathBuf;
use std::time::Duration;

use web_time::Instant;

use raw_window_handle::{HasDisplayHandle, HasWindowHandle};

use crate::file_action::FileAction;

/// One question to the dialog.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PathRequest {
    /// Open or save, and what.
    pub action: FileAction,
    /// The file name proposed when saving.
    pub suggested_name: String,
    /// The folder the dialog starts in.
    pub directory: Option<PathBuf>,
}

/// The dialog's answer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PathAnswer {
    /// The user chose this path.
    Chosen(PathBuf),
    /// The user closed the dialog without choosing.
    Cancelled,
    /// No dialog could be shown (no portal and no zenity on this desktop).
    Unavailable,
}

/// A window the dialog stays above.
pub trait ParentWindow: HasWindowHandle + HasDisplayHandle {}

impl<T: HasWindowHandle + HasDisplayHandle + ?Sized> ParentWindow for T {}

/// Called once with the dialog's answer, possibly from another thread.
pub type Reply = Box<dyn FnOnce(PathAnswer) + Send>;

/// Something that asks the user for a path.
pub trait PathChooser: Send + Sync {
    /// Shows the question without blocking the caller; `reply` gets the answer.
    fn choose(&self, request: PathRequest, parent: Option<&dyn ParentWindow>, reply: Reply);
}

/// The system's file dialog.
#[derive(Clone, Copy, Debug, Default)]
pub struct SystemDialog;

/// rfd answers `None` both when the user cancels and when no dialog could be shown.
/// Nobody closes a dialog within this time, so a quicker `None` means none appeared.
/// Finding that no backend answers took over 250 ms on a loaded 2-core machine with a
/// cold disk cache; a person who cancels this fast gets the path prompt, which is
/// harmless.
const NO_DIALOG_WITHIN: Duration = Duration::from_millis(600);

impl PathChooser for SystemDialog {
    fn choose(&self, request: PathRequest, parent: Option<&dyn ParentWindow>, reply: Reply) {
        let (type_name, extension) = request.action.file_type();
        let mut dialog = rfd::AsyncFileDialog::new()
            .set_title(request.action.title())
            .add_filter(type_name, &[extension]);
        if let Some(dir) = &request.directory {
            dialog = dialog.set_directory(dir);
        }
        if let Some(parent) = parent {
            dialog = dialog.set_parent(parent);
        }
        // The future is made here, on the UI thread (macOS requires it), and awaited
        // on a helper thread so that the window keeps drawing while the dialog is open.
        let pending: PendingDialog = match request.action {
            FileAction::Open => Box::pin(dialog.pick_file()),
            _ => Box::pin(dialog.set_file_name(&request.suggested_name).save_file()),
        };
        spawn_waiting(pending, reply);
    }
}

/// An open dialog's answer, to be awaited.
type PendingDialog = std::pin::Pin<Box<dyn Future<Output = Option<rfd::FileHandle>> + Send>>;

/// Awaits the dialog on a helper thread and replies from there.
fn spawn_waiting(pending: PendingDialog, reply: Reply) {
    let asked = Instant::now();
    std::thread::spawn(move || {
        // A panic in the dialog backend must still answer: the app waits for one
        // answer before it opens another dialog.
        let waited =
            std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| pollster::block_on(pending)));
        let answer = match waited {
            Ok(Some(handle)) => PathAnswer::Chosen(handle.path().into()),
            Ok(None) if asked.elapsed() < NO_DIALOG_WITHIN => PathAnswer::Unavailable,
            Ok(None) => PathAnswer::Cancelled,
            Err(_) => PathAnswer::Unavailable,
        };
        reply(answer);
    });
}

/// `path`, with `.extension` added when the user typed a name without one: save
/// dialogs do not add it, and a scene saved as `cam` would not show under the `.ron`
/// filter when opened again.
pub fn with_extension(path: PathBuf, extension: &str) -> PathBuf {
    if path.extension().is_some() {
        path
    } else {
        path.with_extension(extension)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_name_without_extension_gets_the_file_types() {
        assert_eq!(
            with_extension("/tmp/cam".into(), "ron"),
            PathBuf::from("/tmp/cam.ron")
        );
        assert_eq!(
            with_extension("/tmp/cam.txt".into(), "ron"),
            PathBuf::from("/tmp/cam.txt")
        );
    }
}
