//! Open and save a scene file, export the sweep as CSV and the diagram sheet of the
//! current position as SVG or PNG. On the desktop the system's
//! file dialog chooses the path (a typed path where no dialog can be shown); in the
//! browser the file picker uploads and the browser downloads.

use crate::i18n::tr;
use eframe::egui;

pub use crate::file_action::FileAction;
use crate::session::{SceneSource, Session};
use crate::state::AppState;
use linkage_diagram::pages::Sheet;

/// File dialog, prompt and upload state.
#[derive(Default)]
pub struct Files {
    /// The typed-path prompt (desktop, where no dialog can be shown): action and path.
    pub prompt: Option<(FileAction, String)>,
    /// The desktop's file dialog.
    #[cfg(not(target_arch = "wasm32"))]
    pub dialog: DesktopDialog,
    /// A file the browser's picker delivered, not yet opened.
    #[cfg(target_arch = "wasm32")]
    pub upload: crate::web::Upload,
}

/// The desktop's file dialog: who asks, and the answer on its way back (the dialog
/// runs on its own thread so that the window keeps drawing).
#[cfg(not(target_arch = "wasm32"))]
pub struct DesktopDialog {
    /// Asks the user for a path (the system dialog; tests put their own).
    pub chooser: std::sync::Arc<dyn crate::file_dialog::PathChooser>,
    /// The action whose dialog is open, if one is.
    pub waiting: Option<FileAction>,
    /// The folder of the last chosen file, where the next dialog starts.
    pub last_dir: Option<std::path::PathBuf>,
    send: std::sync::mpsc::Sender<(FileAction, crate::file_dialog::PathAnswer)>,
    receive: std::sync::mpsc::Receiver<(FileAction, crate::file_dialog::PathAnswer)>,
}

#[cfg(not(target_arch = "wasm32"))]
impl Default for DesktopDialog {
    fn default() -> Self {
        let (send, receive) = std::sync::mpsc::channel();
        Self {
            chooser: std::sync::Arc::new(crate::file_dialog::SystemDialog),
            waiting: None,
            last_dir: None,
            send,
            receive,
        }
    }
}

impl Files {
    /// The file buttons of the top bar (and the answers of dialogs they opened); `frame` is the window a dialog stays above.
    pub fn ui(&mut self, ui: &mut egui::Ui, st: &mut AppState, frame: &eframe::Frame) {
        // The control map keeps the English names: the tests' handles in any language.
        for (id, text, action) in [
            ("Open scene…", tr!("file.open"), FileAction::Open),
            ("Save scene…", tr!("file.save"), FileAction::SaveScene),
            ("Export CSV…", tr!("file.export_csv"), FileAction::ExportCsv),
            (
                "Export diagram…",
                tr!("file.export_sheet"),
                FileAction::ExportSheet,
            ),
            ("PNG…", tr!("file.png"), FileAction::ExportSheetPng),
            ("PDF…", tr!("file.pdf"), FileAction::ExportSheetPdf),
        ] {
            let button = ui.button(text);
            st.controls.note(
                ui,
                crate::ui::control_map::ControlKind::FileButton,
                id,
                &button,
            );
            if button.clicked() {
                self.start(ui.ctx(), st, action, frame);
            }
        }
        #[cfg(target_arch = "wasm32")]
        {
            let copy = ui
                .button(tr!("file.copy_link"))
                .on_hover_text(tr!("file.copy_link_hint"));
            st.controls.note(
                ui,
                crate::ui::control_map::ControlKind::FileButton,
                "Copy link",
                &copy,
            );
            if copy.clicked() {
                match crate::web::page_url() {
                    Some(url) => {
                        st.status = Some(tr!("file.link_copied", count = url.len()));
                        ui.ctx().copy_text(url);
                    }
                    None => st.status = Some(tr!("file.no_address")),
                }
            }
        }
        self.take_answers(st);
    }

    /// Acts on the answer of a dialog opened while the file buttons are not shown
    /// (the exercise desk's task sheet).
    pub fn take_dialog_answers(&mut self, st: &mut AppState) {
        self.take_answers(st);
    }

    /// Starts a file action another panel asked for (the cam panel's exports): the
    /// file buttons may be out of sight, in a phone's menu.
    pub fn take_requested(
        &mut self,
        ctx: &egui::Context,
        st: &mut AppState,
        frame: &eframe::Frame,
    ) {
        if let Some(action) = st.commands.file.take() {
            self.start(ctx, st, action, frame);
        }
    }

    /// Acts on a file the browser delivered.
    #[cfg(target_arch = "wasm32")]
    fn take_answers(&mut self, st: &mut AppState) {
        let uploaded = self.upload.borrow_mut().take();
        if let Some((name, text)) = uploaded {
            open_text(st, name, &text);
        }
    }

    /// Acts on the desktop dialog's answer, once it has come.
    #[cfg(not(target_arch = "wasm32"))]
    fn take_answers(&mut self, st: &mut AppState) {
        use crate::file_dialog::PathAnswer;
        while let Ok((action, answer)) = self.dialog.receive.try_recv() {
            self.dialog.waiting = None;
            match answer {
                PathAnswer::Chosen(path) => {
                    let path = match action {
                        FileAction::Open => path,
                        _ => crate::file_dialog::with_extension(path, action.file_type().1),
                    };
                    self.dialog.last_dir = path.parent().map(std::path::Path::to_path_buf);
                    run(st, action, &path);
                }
                PathAnswer::Cancelled => st.status = Some(tr!("file.none_chosen")),
                PathAnswer::Unavailable => {
                    st.status = Some(tr!("file.no_dialog"));
                    self.prompt = Some((action, default_name(st, action)));
                }
            }
        }
    }

    /// Opens the scene file at `path` (from the command line, or dropped on the window),
    /// asking first over unsaved edits as Open does; later dialogs start in its folder.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn open_path(&mut self, st: &mut AppState, path: &std::path::Path) {
        self.dialog.last_dir = path.parent().map(std::path::Path::to_path_buf);
        run(st, FileAction::Open, path);
    }

    /// Opens a scene file dropped on the window, or on the page (read by the browser,
    /// then opened in a later frame as an upload is). Of several, the first.
    // In the browser the file is read first and opened with the uploads.
    #[cfg_attr(target_arch = "wasm32", allow(unused_variables))]
    pub fn take_dropped(&mut self, ctx: &egui::Context, st: &mut AppState) {
        let dropped = ctx.input(|i| i.raw.dropped_files.clone());
        let Some(file) = dropped.first() else {
            return;
        };
        if dropped.len() > 1 {
            log::info!("{} files dropped: opening the first", dropped.len());
        }
        #[cfg(not(target_arch = "wasm32"))]
        self.open_path(st, file.path());
        #[cfg(target_arch = "wasm32")]
        crate::web::read_dropped(file.clone(), &self.upload, ctx);
    }

    /// Opens the system's dialog for `action`; its answer comes back in a later frame.
    #[cfg(not(target_arch = "wasm32"))]
    pub(crate) fn start(
        &mut self,
        ctx: &egui::Context,
        st: &mut AppState,
        action: FileAction,
        frame: &eframe::Frame,
    ) {
        use crate::file_dialog::PathRequest;
        if self.dialog.waiting.is_some() {
            st.status = Some(tr!("file.dialog_open"));
            return;
        }
        let request = PathRequest {
            action,
            suggested_name: default_name(st, action),
            directory: self.dialog.last_dir.clone(),
        };
        let send = self.dialog.send.clone();
        let ctx = ctx.clone();
        self.dialog.waiting = Some(action);
        st.status = Some(tr!("file.waiting", action = action.title()));
        self.dialog.chooser.clone().choose(
            request,
            Some(frame),
            Box::new(move |answer| {
                // The receiver lives as long as the app; a closed app needs no answer.
                let _ = send.send((action, answer));
                ctx.request_repaint();
            }),
        );
        // A chooser that answers at once is taken by `ui` right after this call.
    }

    #[cfg(target_arch = "wasm32")]
    pub(crate) fn start(
        &mut self,
        ctx: &egui::Context,
        st: &mut AppState,
        action: FileAction,
        _frame: &eframe::Frame,
    ) {
        let result = match action {
            FileAction::Open => {
                crate::web::pick_file(&self.upload, ctx).map_err(WriteError::Browser)
            }
            FileAction::ExportSheetPng | FileAction::CoursePng => {
                let name = std::path::PathBuf::from(default_name(st, action));
                pages_of(st, action).and_then(|sheet| {
                    sheet.pages.iter().enumerate().try_for_each(|(i, page)| {
                        let file = page_name(&name, i);
                        crate::web::download_svg_as_png(&file, page, SHEET_DPI)
                            .map_err(WriteError::Browser)
                    })
                })
            }
            FileAction::ExportSheetPdf
            | FileAction::CoursePdf
            | FileAction::ReportPdf
            | FileAction::TaskSheetPdf => {
                let printed = pages_of(st, action)
                    .and_then(|sheet| crate::web::print_pages(&sheet).map_err(WriteError::Browser));
                if printed.is_ok() {
                    st.status = Some(tr!("file.print_hint"));
                }
                printed
            }
            _ => {
                let mime = match action {
                    FileAction::ExportCsv | FileAction::CamCsv(_) => "text/csv",
                    FileAction::ExportSheet | FileAction::CamSvg(_) | FileAction::CourseSvg => {
                        "image/svg+xml"
                    }
                    _ => "text/plain",
                };
                let name = std::path::PathBuf::from(default_name(st, action));
                contents(st, action).and_then(|files| {
                    files.iter().enumerate().try_for_each(|(i, bytes)| {
                        crate::web::download(&page_name(&name, i), mime, bytes)
                            .map_err(WriteError::Browser)
                    })
                })
            }
        };
        match result {
            Ok(()) if action == FileAction::SaveScene => st.session.mark_saved(),
            Ok(()) => {}
            Err(e) => st.status = Some(e.words(st.session.scene().length_unit)),
        }
    }

    /// The desktop's path prompt, while one is open.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn prompt_window(&mut self, ctx: &egui::Context, st: &mut AppState) {
        let Some((action, mut path)) = self.prompt.take() else {
            return;
        };
        let title = action.title();
        let mut keep = true;
        let mut go = false;
        egui::Window::new(title).collapsible(false).show(ctx, |ui| {
            let label = ui.label(tr!("file.path_prompt"));
            let edit = ui.text_edit_singleline(&mut path).labelled_by(label.id);
            if edit.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) {
                go = true;
            }
            ui.horizontal(|ui| {
                go |= ui.button(tr!("file.ok")).clicked();
                keep = !ui.button(tr!("file.cancel")).clicked();
            });
        });
        if go {
            run(st, action, std::path::Path::new(&path));
        } else if keep {
            self.prompt = Some((action, path));
        }
    }

    #[cfg(target_arch = "wasm32")]
    pub fn prompt_window(&mut self, _ctx: &egui::Context, _st: &mut AppState) {}
}

fn default_name(st: &AppState, action: FileAction) -> String {
    let stem = match st.session.source() {
        SceneSource::Builtin(key) => key.clone(),
        SceneSource::File(name) => name.trim_end_matches(".ron").to_string(),
    };
    match action {
        FileAction::Open | FileAction::SaveScene => format!("{stem}.ron"),
        FileAction::ExportCsv => format!("{stem}_sweep.csv"),
        FileAction::ExportSheet | FileAction::ExportSheetPng | FileAction::ExportSheetPdf => {
            format!(
                "{stem}_at_{:.0}deg.{}",
                st.session.input_rad().to_degrees(),
                action.file_type().1
            )
        }
        FileAction::CamCsv(i) | FileAction::CamSvg(i) | FileAction::CamDxf(i) => {
            format!("{stem}_cam{}.{}", i + 1, action.file_type().1)
        }
        FileAction::CourseSvg | FileAction::CoursePng | FileAction::CoursePdf => {
            format!("{stem}_course.{}", action.file_type().1)
        }
        FileAction::ReportPdf => format!("{stem}_report.pdf"),
        FileAction::TaskSheetPdf => format!("{stem}_task.pdf"),
    }
}

/// Why a file action has nothing to write.
#[derive(Debug, thiserror::Error)]
enum WriteError {
    /// The scene or its sweep could not be made.
    #[error(transparent)]
    Solver(#[from] linkage::LinkageError),
    /// The sheet could not be rasterised or printed (resvg's or krilla's own words).
    #[cfg(not(target_arch = "wasm32"))]
    #[error("{0}")]
    Png(String),
    /// The file could not be written.
    #[cfg(not(target_arch = "wasm32"))]
    #[error(transparent)]
    File(std::io::Error),
    /// Open reads; it writes nothing.
    #[error("nothing to write when opening")]
    Opening,
    /// The course sheet's positions to draw, mistyped (the words say the range).
    #[error("{0}")]
    Course(String),
    /// No exercise open with a student's variant.
    #[error("no student's exercise is open")]
    NoVariant,
    /// The scene has no cam joint of that number (an edit took it away).
    #[error("the scene has no cam joint {0}")]
    NoCam(usize),
    /// The DXF crate's own words.
    #[cfg(not(target_arch = "wasm32"))]
    #[error("{0}")]
    Dxf(String),
    /// The browser build has no DXF writer (its crate needs randomness wasm32 lacks).
    #[cfg(target_arch = "wasm32")]
    #[error("the DXF is written by the desktop app; the browser exports CSV and SVG")]
    DxfInBrowser,
    /// The browser refused (its own words).
    #[cfg(target_arch = "wasm32")]
    #[error("{0}")]
    Browser(String),
    /// In the browser the page rasterises and prints the sheet, not the app.
    #[cfg(target_arch = "wasm32")]
    #[error("in the browser the page draws the PNG and the PDF")]
    PngInBrowser,
}

impl WriteError {
    /// Why nothing was written, in the app's language: the solver's refusal in the
    /// user's words, a library's or the system's own words quoted.
    fn words(&self, unit: linkage::scene::LengthUnit) -> String {
        match self {
            Self::Solver(e) => crate::ui::words::refusal(e, unit),
            #[cfg(not(target_arch = "wasm32"))]
            Self::Png(why) | Self::Dxf(why) => why.clone(),
            #[cfg(not(target_arch = "wasm32"))]
            Self::File(e) => e.to_string(),
            Self::Opening => tr!("file.nothing_to_write"),
            Self::Course(why) => why.clone(),
            Self::NoCam(n) => tr!("file.no_cam", number = n),
            Self::NoVariant => tr!("file.no_variant"),
            #[cfg(target_arch = "wasm32")]
            Self::DxfInBrowser => tr!("file.dxf_in_browser"),
            #[cfg(target_arch = "wasm32")]
            Self::Browser(why) => tr!("file.browser_refused", why = why),
            #[cfg(target_arch = "wasm32")]
            Self::PngInBrowser => tr!("file.png_in_browser"),
        }
    }
}

/// The files an action writes (a sheet's SVG and PNG: a file per page), or why
/// there are none.
fn contents(st: &AppState, action: FileAction) -> Result<Vec<Vec<u8>>, WriteError> {
    let one = |bytes: Vec<u8>| vec![bytes];
    match action {
        FileAction::SaveScene => Ok(one(st.session.to_ron()?.into_bytes())),
        FileAction::ExportCsv => Ok(one(st.session.sweep_csv()?.into_bytes())),
        FileAction::ExportSheet | FileAction::CourseSvg => Ok(pages_of(st, action)?
            .pages
            .into_iter()
            .map(String::into_bytes)
            .collect()),
        FileAction::ExportSheetPng | FileAction::CoursePng => sheet_png(st, action),
        FileAction::ExportSheetPdf
        | FileAction::CoursePdf
        | FileAction::ReportPdf
        | FileAction::TaskSheetPdf => sheet_pdf(st, action).map(one),
        FileAction::CamCsv(i) => st
            .session
            .cam_csv(i)
            .map(|t| one(t.into_bytes()))
            .ok_or(WriteError::NoCam(i + 1)),
        FileAction::CamSvg(i) => st
            .session
            .cam_svg(i, crate::ui::words::lang())
            .map(|t| one(t.into_bytes()))
            .ok_or(WriteError::NoCam(i + 1)),
        FileAction::CamDxf(i) => cam_dxf(st, i).map(one),
        FileAction::Open => Err(WriteError::Opening),
    }
}

/// The file of page `index` of a sheet saved as `path`: `path` itself for the
/// first, `name-2.svg` … for the others.
#[cfg(target_arch = "wasm32")]
fn page_name(path: &std::path::Path, index: usize) -> String {
    linkage_diagram::pages::page_path(path, index)
        .to_string_lossy()
        .into_owned()
}

/// Cam joint `i`'s profile, pitch curve and base circle as DXF.
#[cfg(not(target_arch = "wasm32"))]
fn cam_dxf(st: &AppState, i: usize) -> Result<Vec<u8>, WriteError> {
    let c = st
        .session
        .curves()
        .cams
        .get(i)
        .ok_or(WriteError::NoCam(i + 1))?;
    let profile: Vec<[f64; 2]> = c.points.iter().map(|p| p.profile_m).collect();
    let pitch: Vec<[f64; 2]> = c.points.iter().map(|p| p.pitch_m).collect();
    linkage_diagram::cam_dxf::cam_dxf(&profile, &pitch, c.base_radius_m)
        .map_err(|e| WriteError::Dxf(e.to_string()))
}

#[cfg(target_arch = "wasm32")]
fn cam_dxf(_: &AppState, _: usize) -> Result<Vec<u8>, WriteError> {
    Err(WriteError::DxfInBrowser)
}

/// The sheet of the current position, instant centres as the view shows them.
fn sheet(st: &AppState) -> Sheet {
    st.session
        .sheet(st.view.layers.centres, crate::ui::words::lang())
}

/// The pages `action` exports: the position's sheet, or the course sheet or the
/// course-design report of the course window's choices.
fn pages_of(st: &AppState, action: FileAction) -> Result<Sheet, WriteError> {
    let lang = crate::ui::words::lang();
    let course = || st.course.choice().map_err(WriteError::Course);
    match action {
        FileAction::CourseSvg | FileAction::CoursePng | FileAction::CoursePdf => {
            Ok(st.session.course_sheet(&course()?, lang)?)
        }
        FileAction::ReportPdf => Ok(st.session.course_report(&course()?, lang)?),
        FileAction::TaskSheetPdf => {
            let desk = st.exercise.as_ref();
            let variant = desk
                .and_then(|d| d.variant.as_ref())
                .ok_or(WriteError::NoVariant)?;
            Ok(desk
                .map(|d| d.exercise.task_sheet(variant, lang))
                .ok_or(WriteError::NoVariant)?)
        }
        _ => Ok(sheet(st)),
    }
}

/// Resolution of the exported PNG sheet: 150 dpi, print quality for A4.
pub const SHEET_DPI: f32 = 150.0;

/// The sheet rendered by resvg with the app's font (the browser rasterises the SVG
/// itself instead: `crate::web::download_svg_as_png`).
#[cfg(not(target_arch = "wasm32"))]
fn sheet_png(st: &AppState, action: FileAction) -> Result<Vec<Vec<u8>>, WriteError> {
    let font = epaint_default_fonts::UBUNTU_LIGHT;
    pages_of(st, action)?
        .pages
        .iter()
        .map(|page| linkage_diagram::png::render(page, SHEET_DPI, font, "Ubuntu"))
        .collect::<Result<_, _>>()
        .map_err(WriteError::Png)
}

#[cfg(target_arch = "wasm32")]
fn sheet_png(_st: &AppState, _action: FileAction) -> Result<Vec<Vec<u8>>, WriteError> {
    Err(WriteError::PngInBrowser)
}

/// The sheet as one PDF, its text set in the app's own face.
#[cfg(not(target_arch = "wasm32"))]
fn sheet_pdf(st: &AppState, action: FileAction) -> Result<Vec<u8>, WriteError> {
    let font = epaint_default_fonts::UBUNTU_LIGHT;
    let lang = crate::ui::words::lang().code();
    let pages = pages_of(st, action)?;
    linkage_diagram::pdf::document(&pages, font, "Ubuntu", lang).map_err(WriteError::Png)
}

#[cfg(target_arch = "wasm32")]
fn sheet_pdf(_st: &AppState, _action: FileAction) -> Result<Vec<u8>, WriteError> {
    Err(WriteError::PngInBrowser)
}

/// Shows the outcome of a file action in the top bar and logs it: the browser test
/// and the desktop smoke run read the log.
fn report(st: &mut AppState, level: log::Level, message: String) {
    log::log!(level, "{message}");
    st.status = Some(message);
}

/// Opens scene text read from a file named `name`.
pub fn open_text(st: &mut AppState, name: String, text: &str) {
    if crate::exercise::is_exercise_file(text) {
        st.open_exercise(text);
        return;
    }
    match Session::open_text(SceneSource::File(name.clone()), text) {
        Ok(s) => {
            st.open(s);
            report(st, log::Level::Info, tr!("file.opened", name = name));
        }
        Err(e) => {
            let why = crate::ui::words::refusal(&e, linkage::scene::LengthUnit::Metre);
            report(st, log::Level::Warn, format!("{name}: {why}"));
        }
    }
}

/// While files are dragged over the window: a veil that says what a drop does.
pub fn drop_hint(ctx: &egui::Context) {
    if ctx.input(|i| i.raw.hovered_files.is_empty()) {
        return;
    }
    let screen = ctx.content_rect();
    let painter = ctx.layer_painter(egui::LayerId::new(
        egui::Order::Foreground,
        egui::Id::unique("drop hint"),
    ));
    painter.rect_filled(screen, 0.0, egui::Color32::from_black_alpha(160));
    painter.text(
        screen.center(),
        egui::Align2::CENTER_CENTER,
        tr!("file.drop_hint"),
        egui::FontId::proportional(24.0),
        egui::Color32::WHITE,
    );
}

#[cfg(not(target_arch = "wasm32"))]
fn run(st: &mut AppState, action: FileAction, path: &std::path::Path) {
    let shown = path.display();
    let name = path
        .file_name()
        .map_or_else(|| shown.to_string(), |n| n.to_string_lossy().into_owned());
    match action {
        FileAction::Open => match std::fs::read_to_string(path) {
            Ok(text) => open_text(st, name, &text),
            Err(e) => report(
                st,
                log::Level::Warn,
                tr!("file.cannot_read", path = shown, why = e),
            ),
        },
        _ => {
            let written = contents(st, action).and_then(|files| {
                for (i, bytes) in files.iter().enumerate() {
                    let file = linkage_diagram::pages::page_path(path, i);
                    std::fs::write(file, bytes).map_err(WriteError::File)?;
                }
                Ok(files.len())
            });
            match written {
                Ok(count) => {
                    if action == FileAction::SaveScene {
                        st.session.mark_saved();
                    }
                    let message = if count > 1 {
                        tr!("file.wrote_pages", path = shown, count = count)
                    } else {
                        tr!("file.wrote", path = shown)
                    };
                    report(st, log::Level::Info, message);
                }
                Err(e) => {
                    let why = e.words(st.session.scene().length_unit);
                    let message = tr!("file.cannot_write", path = shown, why = why);
                    report(st, log::Level::Warn, message);
                }
            }
        }
    }
}
