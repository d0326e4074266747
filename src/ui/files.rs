//! Open and save a scene file, export the sweep as CSV. On the desktop a path prompt
//! reads and writes the file system; in the browser the file picker uploads and the
//! browser downloads.

use eframe::egui;

use crate::app::AppState;
use crate::session::{SceneSource, Session};

/// What a file prompt will do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileAction {
    /// Read a scene file.
    Open,
    /// Write the edited scene.
    SaveScene,
    /// Write the sweep as CSV.
    ExportCsv,
}

/// File prompt state.
#[derive(Default)]
pub struct Files {
    /// The open prompt (desktop): action and path typed so far.
    pub prompt: Option<(FileAction, String)>,
    /// A file the browser's picker delivered, not yet opened.
    #[cfg(target_arch = "wasm32")]
    pub upload: crate::web::Upload,
}

/// The file buttons of the top bar.
pub fn buttons(ui: &mut egui::Ui, st: &mut AppState) {
    for (label, action) in [
        ("Open scene…", FileAction::Open),
        ("Save scene…", FileAction::SaveScene),
        ("Export CSV…", FileAction::ExportCsv),
    ] {
        if ui.button(label).clicked() {
            start(st, action);
        }
    }
    #[cfg(target_arch = "wasm32")]
    {
        let uploaded = st.files.upload.borrow_mut().take();
        if let Some((name, text)) = uploaded {
            open_text(st, name, &text);
        }
    }
}

fn default_name(st: &AppState, action: FileAction) -> String {
    let stem = match st.session.source() {
        SceneSource::Builtin(key) => key.clone(),
        SceneSource::File(name) => name.trim_end_matches(".ron").to_string(),
    };
    match action {
        FileAction::Open | FileAction::SaveScene => format!("{stem}.ron"),
        FileAction::ExportCsv => format!("{stem}_sweep.csv"),
    }
}

/// The text an action writes, or why there is none.
fn contents(st: &AppState, action: FileAction) -> Result<String, String> {
    match action {
        FileAction::SaveScene => st.session.to_ron(),
        FileAction::ExportCsv => st.session.sweep_csv(),
        FileAction::Open => Err("nothing to write when opening".into()),
    }
}

/// Opens scene text read from a file named `name`.
pub fn open_text(st: &mut AppState, name: String, text: &str) {
    match Session::open_text(SceneSource::File(name.clone()), text) {
        Ok(s) => {
            st.open(s);
            st.status = Some(format!("opened {name}"));
        }
        Err(e) => st.status = Some(format!("{name}: {e}")),
    }
}

#[cfg(not(target_arch = "wasm32"))]
fn start(st: &mut AppState, action: FileAction) {
    st.files.prompt = Some((action, default_name(st, action)));
}

#[cfg(target_arch = "wasm32")]
fn start(st: &mut AppState, action: FileAction) {
    let result = match action {
        FileAction::Open => crate::web::pick_file(&st.files.upload),
        FileAction::SaveScene | FileAction::ExportCsv => {
            let mime = if action == FileAction::ExportCsv {
                "text/csv"
            } else {
                "text/plain"
            };
            contents(st, action)
                .and_then(|t| crate::web::download(&default_name(st, action), mime, &t))
        }
    };
    if let Err(e) = result {
        st.status = Some(e);
    }
}

/// The desktop's path prompt, while one is open.
#[cfg(not(target_arch = "wasm32"))]
pub fn prompt_window(ctx: &egui::Context, st: &mut AppState) {
    let Some((action, mut path)) = st.files.prompt.take() else {
        return;
    };
    let title = match action {
        FileAction::Open => "Open scene file",
        FileAction::SaveScene => "Save scene file",
        FileAction::ExportCsv => "Export sweep CSV",
    };
    let mut keep = true;
    let mut go = false;
    egui::Window::new(title).collapsible(false).show(ctx, |ui| {
        ui.label("Path (relative to the working directory):");
        let edit = ui.text_edit_singleline(&mut path);
        if edit.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) {
            go = true;
        }
        ui.horizontal(|ui| {
            go |= ui.button("OK").clicked();
            keep = !ui.button("Cancel").clicked();
        });
    });
    if go {
        run(st, action, &path);
    } else if keep {
        st.files.prompt = Some((action, path));
    }
}

#[cfg(target_arch = "wasm32")]
pub fn prompt_window(_ctx: &egui::Context, _st: &mut AppState) {}

#[cfg(not(target_arch = "wasm32"))]
fn run(st: &mut AppState, action: FileAction, path: &str) {
    let name = std::path::Path::new(path)
        .file_name()
        .map_or_else(|| path.to_string(), |n| n.to_string_lossy().into_owned());
    match action {
        FileAction::Open => match std::fs::read_to_string(path) {
            Ok(text) => open_text(st, name, &text),
            Err(e) => st.status = Some(format!("cannot read {path}: {e}")),
        },
        FileAction::SaveScene | FileAction::ExportCsv => {
            st.status = Some(
                match contents(st, action)
                    .and_then(|t| std::fs::write(path, t).map_err(|e| e.to_string()))
                {
                    Ok(()) => format!("wrote {path}"),
                    Err(e) => format!("cannot write {path}: {e}"),
                },
            );
        }
    }
}
