//! The desktop's file actions driven through the top bar's buttons (egui_kittest),
//! with the file dialog answered by the test: open reads the chosen scene, save writes
//! a scene that opens again to the same mechanism, export writes the sweep CSV, a
//! cancelled dialog changes nothing, and where no dialog can be shown a typed path
//! does the same job.

#![cfg(not(target_arch = "wasm32"))]

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use eframe::egui;
use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use linkage_lab::file_dialog::{ParentWindow, PathAnswer, PathChooser, PathRequest, Reply};
use linkage_lab::session::{SceneEdit, SceneSource};
use linkage_lab::ui::files::FileAction;
use linkage_lab::{LinkageApp, StartOptions};

/// A dialog that gives a fixed answer at once and remembers what it was asked.
struct Scripted {
    answer: PathAnswer,
    asked: Mutex<Vec<PathRequest>>,
}

impl PathChooser for Scripted {
    fn choose(&self, request: PathRequest, _parent: Option<&dyn ParentWindow>, reply: Reply) {
        self.asked.lock().expect("not poisoned").push(request);
        reply(self.answer.clone());
    }
}

/// The app (no GPU needed: these tests read state and labels) with `answer` scripted.
fn harness_answering(answer: PathAnswer) -> (Harness<'static, LinkageApp>, Arc<Scripted>) {
    let mut h = Harness::builder()
        .with_size(egui::vec2(1500.0, 950.0))
        .build_eframe(|cc| LinkageApp::new(cc, StartOptions::default()));
    let dialog = Arc::new(Scripted {
        answer,
        asked: Mutex::new(Vec::new()),
    });
    h.state_mut().panels.files.dialog.chooser = dialog.clone();
    h.state_mut().state.timing.show = false;
    h.run();
    (h, dialog)
}

fn click(h: &mut Harness<'static, LinkageApp>, label: &str) {
    h.get_by_role_and_label(Role::Button, label).click();
    h.run();
}

fn status(h: &Harness<'static, LinkageApp>) -> String {
    h.state().state.status.clone().unwrap_or_default()
}

/// A fresh folder for one test's files.
fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("linkage-lab-{test}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

fn shipped(file: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("assets/scenes")
        .join(file)
}

#[test]
fn open_reads_the_scene_the_dialog_chose() {
    let path = shipped("slider_crank.ron");
    let (mut h, dialog) = harness_answering(PathAnswer::Chosen(path.clone()));
    click(&mut h, "Open scene…");
    let asked = dialog.asked.lock().expect("not poisoned").clone();
    assert_eq!(asked.len(), 1);
    assert_eq!(asked[0].action, FileAction::Open);
    let st = &h.state().state;
    assert_eq!(
        st.session.source(),
        &SceneSource::File("slider_crank.ron".into())
    );
    let text = std::fs::read_to_string(&path).expect("shipped scene");
    let expected = linkage::SceneFile::parse(&text).expect("parses");
    assert_eq!(st.session.scene(), &expected);
    assert_eq!(status(&h), "opened slider_crank.ron");
    assert!(h.query_by_label("opened slider_crank.ron").is_some());
    // The next dialog starts where this file was.
    assert_eq!(
        h.state().panels.files.dialog.last_dir.as_deref(),
        path.parent(),
        "last folder"
    );
}

#[test]
fn save_writes_a_scene_that_reopens_to_the_same_mechanism() {
    let dir = scratch("save");
    // The user typed a name without extension: the scene still lands in a .ron file.
    let (mut h, dialog) = harness_answering(PathAnswer::Chosen(dir.join("my_cutter")));
    let edited = {
        let session = &mut h.state_mut().state.session;
        let first = session.lengths()[0]
            .value(session.scene())
            .expect("a length");
        session.apply(SceneEdit::Length {
            index: 0,
            value: 1.02 * first,
        });
        assert_eq!(session.message(), None, "a 2 % longer link assembles");
        assert_ne!(session.scene(), session.original(), "edited");
        session.scene().clone()
    };
    click(&mut h, "Save scene…");
    let asked = dialog.asked.lock().expect("not poisoned").clone();
    assert_eq!(asked[0].action, FileAction::SaveScene);
    assert_eq!(asked[0].suggested_name, "die_cutter.ron");
    let written = dir.join("my_cutter.ron");
    assert_eq!(status(&h), format!("wrote {}", written.display()));
    let text = std::fs::read_to_string(&written).expect("the scene was written");
    assert_eq!(linkage::SceneFile::parse(&text).expect("parses"), edited);

    // Opening the written file through the dialog gives the edited mechanism back.
    let (mut h, _) = harness_answering(PathAnswer::Chosen(written));
    click(&mut h, "Open scene…");
    assert_eq!(h.state().state.session.scene(), &edited);
    std::fs::remove_dir_all(dir).expect("clean up");
}

#[test]
fn export_writes_the_sweep_csv() {
    let dir = scratch("export");
    let path = dir.join("sweep.csv");
    let (mut h, dialog) = harness_answering(PathAnswer::Chosen(path.clone()));
    click(&mut h, "Export CSV…");
    let asked = dialog.asked.lock().expect("not poisoned").clone();
    assert_eq!(asked[0].action, FileAction::ExportCsv);
    assert_eq!(asked[0].suggested_name, "die_cutter_sweep.csv");
    let text = std::fs::read_to_string(&path).expect("the CSV was written");
    assert_eq!(
        text,
        h.state().state.session.sweep_csv().expect("sweeps"),
        "file = the session's sweep"
    );
    // The table a report takes, as `linkage sweep` writes it: whole degrees, the
    // die cutter's millimetres, columns named with their units.
    assert!(text.starts_with("input (deg),"), "{}", &text[..40]);
    assert!(
        text.lines().next().is_some_and(|h| h.contains(" x (mm),")),
        "{}",
        &text[..80]
    );
    assert_eq!(text.lines().count(), 361, "a header and 360 rows");
    assert!(
        text.lines().any(|row| row.starts_with("60,")),
        "a row at 60°"
    );
    std::fs::remove_dir_all(dir).expect("clean up");
}

#[test]
fn a_cancelled_dialog_changes_nothing() {
    let (mut h, _) = harness_answering(PathAnswer::Cancelled);
    let before = h.state().state.session.scene().clone();
    click(&mut h, "Open scene…");
    assert_eq!(h.state().state.session.scene(), &before);
    assert_eq!(status(&h), "no file chosen");
    assert!(h.state().panels.files.prompt.is_none());
    assert!(h.state().panels.files.dialog.waiting.is_none());
}

#[test]
fn without_a_dialog_a_typed_path_opens_the_scene() {
    let (mut h, _) = harness_answering(PathAnswer::Unavailable);
    click(&mut h, "Open scene…");
    let msg = status(&h);
    assert!(msg.contains("xdg-desktop-portal or zenity"), "{msg}");
    assert!(
        h.query_by_label("Open scene file").is_some(),
        "prompt window"
    );
    let path = shipped("quick_return.ron");
    h.get_by_role_and_label(Role::TextInput, "Path (relative to the working directory):")
        .set_text_value_accesskit(path.to_str().expect("utf-8 path"));
    h.run();
    click(&mut h, "OK");
    assert_eq!(
        h.state().state.session.source(),
        &SceneSource::File("quick_return.ron".into())
    );
    assert!(h.state().panels.files.prompt.is_none());
}

#[test]
fn an_unreadable_file_is_named_in_the_message_and_the_scene_stays() {
    let dir = scratch("unreadable");
    let broken = dir.join("broken.ron");
    std::fs::write(&broken, "(name: \"half a scene\", links: [").expect("write");
    let (mut h, _) = harness_answering(PathAnswer::Chosen(broken));
    let before = h.state().state.session.scene().clone();
    click(&mut h, "Open scene…");
    let msg = status(&h);
    assert!(msg.starts_with("broken.ron: "), "{msg}");
    assert!(
        msg.contains("line 1"),
        "the parse error gives its place: {msg}"
    );
    assert_eq!(h.state().state.session.scene(), &before);
    std::fs::remove_dir_all(dir).expect("clean up");
}

/// The sheet `linkage diagram SCENE --input-deg X` writes, built here the CLI's way:
/// from the scene file, solved afresh at the input.
fn sheet_as_the_cli_draws_it(key: &str, input_rad: f64, centres: bool) -> String {
    let path = format!("{}/assets/scenes/{key}.ron", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).expect("a shipped scene");
    let m = linkage::Mechanism::from_ron(&text).expect("valid");
    let mut k = linkage::Kinematics::new(m).expect("kinematics");
    let s = k.solve(input_rad).expect("solves");
    let eqs = linkage::polygon::polygons(&k, &s);
    let found = linkage::instant_centres::instant_centres(k.mechanism(), &s);
    let forces = linkage::kinetostatics::Kinetostatics::new(&mut k)
        .and_then(|mut ks| linkage::force_polygon::force_polygons(&mut k, &mut ks, input_rad))
        .ok();
    let position = linkage_diagram::svg::Position {
        mechanism: k.mechanism(),
        solution: &s,
        equations: &eqs,
        centres: Some(&found),
        forces: forces.as_ref(),
    };
    let parts = linkage_diagram::svg::Parts {
        centres,
        forces: true,
        ..Default::default()
    };
    let lang = linkage_diagram::words::Lang::English;
    linkage_diagram::svg::sheet(&position, parts, lang)
        .pages
        .concat()
}

#[test]
fn export_diagram_writes_the_sheet_the_cli_draws() {
    let dir = scratch("sheet");
    let path = dir.join("sheet.svg");
    let (mut h, dialog) = harness_answering(PathAnswer::Chosen(path.clone()));
    click(&mut h, "Export diagram…");
    let asked = dialog.asked.lock().expect("not poisoned").clone();
    assert_eq!(asked[0].action, FileAction::ExportSheet);
    let input = h.state().state.session.input_rad();
    assert_eq!(
        asked[0].suggested_name,
        format!("die_cutter_at_{:.0}deg.svg", input.to_degrees())
    );
    // A page a file: sheet.svg, sheet-2.svg, …
    let pages: Vec<String> = (0..)
        .map(|i| linkage_diagram::pages::page_path(&path, i))
        .map_while(|p| std::fs::read_to_string(p).ok())
        .collect();
    assert!(
        pages.len() > 1,
        "the die cutter's sheet takes more than a page"
    );
    for page in &pages {
        assert!(page.starts_with("<?xml") && page.contains("height=\"297.0mm\""));
    }
    assert_eq!(
        pages.concat(),
        sheet_as_the_cli_draws_it("die_cutter", input, false)
    );
    std::fs::remove_dir_all(dir).expect("clean up");
}

#[test]
fn every_scene_exports_the_sheet_the_cli_draws_with_instant_centres() {
    for scene in linkage_lab::catalog::BUILTIN_SCENES {
        let mut s = linkage_lab::session::Session::open_builtin(scene.key).expect("opens");
        let [lo, hi] = s.input_range_deg();
        s.apply(SceneEdit::Input {
            deg: lo + 0.37 * (hi - lo),
        });
        assert!(s.message().is_none(), "{}: {:?}", scene.key, s.message());
        assert_eq!(
            s.sheet(true, linkage_diagram::words::Lang::English)
                .pages
                .concat(),
            sheet_as_the_cli_draws_it(scene.key, s.input_rad(), true),
            "{}",
            scene.key
        );
    }
}

#[test]
fn png_export_writes_the_sheet_rendered_at_150_dpi() {
    let dir = scratch("sheet-png");
    let path = dir.join("sheet.png");
    let (mut h, dialog) = harness_answering(PathAnswer::Chosen(path.clone()));
    click(&mut h, "PNG…");
    let asked = dialog.asked.lock().expect("not poisoned").clone();
    assert_eq!(asked[0].action, FileAction::ExportSheetPng);
    assert!(
        asked[0].suggested_name.ends_with("deg.png"),
        "{}",
        asked[0].suggested_name
    );
    let bytes = std::fs::read(&path).expect("the PNG was written");
    assert_eq!(&bytes[1..4], b"PNG");
    let width = u32::from_be_bytes([bytes[16], bytes[17], bytes[18], bytes[19]]);
    // A4 is 210 mm wide: 1240 px at 150 dpi.
    assert!((1239..=1241).contains(&width), "{width} px wide");
    std::fs::remove_dir_all(dir).expect("clean up");
}

/// The PDF of the sheet: A4 pages, one a page of the SVG sheet, text kept as text.
#[test]
fn pdf_export_writes_every_page_of_the_sheet() {
    let dir = scratch("sheet-pdf");
    let path = dir.join("sheet.pdf");
    let (mut h, dialog) = harness_answering(PathAnswer::Chosen(path.clone()));
    click(&mut h, "PDF…");
    let asked = dialog.asked.lock().expect("not poisoned").clone();
    assert_eq!(asked[0].action, FileAction::ExportSheetPdf);
    let bytes = std::fs::read(&path).expect("the PDF was written");
    assert!(bytes.starts_with(b"%PDF-"));
    let pages = h
        .state()
        .state
        .session
        .sheet(false, linkage_diagram::words::Lang::English)
        .pages
        .len();
    let text = String::from_utf8_lossy(&bytes);
    assert!(text.contains(&format!("/Count {pages}")), "{pages} pages");
    std::fs::remove_dir_all(dir).expect("clean up");
}

/// The course sheet's window: the positions and the chosen ones typed, a mistyped
/// one refused with the range, and the PDF written with the sheet's pages.
#[test]
fn the_course_sheet_window_exports_the_sheet_asked_for() {
    let dir = scratch("course-pdf");
    let path = dir.join("course.pdf");
    let (mut h, dialog) = harness_answering(PathAnswer::Chosen(path.clone()));
    click(&mut h, "Course sheet…");
    assert!(h.state().state.course.open);
    h.state_mut().state.course.chosen = "2, 40".into();
    h.run();
    let refused = h.state().state.course.chosen_numbers();
    assert!(
        refused.as_ref().is_err_and(|why| why.contains("0 to 11")),
        "{refused:?}"
    );
    h.state_mut().state.course.positions = 6;
    h.state_mut().state.course.chosen = "1, 4".into();
    // Position 0 at a crank angle of the user's.
    h.state_mut().state.course.from_start = false;
    h.state_mut().state.course.first_deg = 45.0;
    h.run();
    let choice = h.state().state.course.choice().expect("a choice");
    assert_eq!(choice.first_deg, Some(45.0));
    // The top bar's PDF… is the position's sheet; the window's is the course's.
    h.get_all_by_role_and_label(Role::Button, "PDF…")
        .last()
        .expect("the window's PDF button")
        .click();
    h.run();
    let asked = dialog.asked.lock().expect("not poisoned").clone();
    let course = asked.iter().find(|a| a.action == FileAction::CoursePdf);
    let course = course.expect("the course sheet's dialog");
    assert!(
        course.suggested_name.ends_with("_course.pdf"),
        "{}",
        course.suggested_name
    );
    let bytes = std::fs::read(&path).expect("the PDF was written");
    let pages = h
        .state()
        .state
        .session
        .course_sheet(&choice, linkage_diagram::words::Lang::English)
        .expect("the sheet")
        .pages
        .len();
    assert!(
        pages >= 3,
        "plan and diagrams, two positions' polygons, forces"
    );
    let text = String::from_utf8_lossy(&bytes);
    assert!(text.contains(&format!("/Count {pages}")), "{pages} pages");
    // The course-design report from the same choices.
    click(&mut h, "Course design report (PDF)…");
    let asked = dialog.asked.lock().expect("not poisoned").clone();
    assert!(
        asked.iter().any(|a| a.action == FileAction::ReportPdf),
        "{}",
        status(&h)
    );
    let bytes = std::fs::read(&path).expect("the report was written");
    let pages = h
        .state()
        .state
        .session
        .course_report(&choice, linkage_diagram::words::Lang::English)
        .expect("the report")
        .pages
        .len();
    let text = String::from_utf8_lossy(&bytes);
    assert!(text.contains(&format!("/Count {pages}")), "{pages} pages");
    std::fs::remove_dir_all(dir).expect("clean up");
}

/// A file dropped on the window, as winit hands it to egui.
#[derive(Debug)]
struct Dropped(PathBuf);

impl egui::DroppedFile for Dropped {
    fn path(&self) -> &Path {
        &self.0
    }

    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|e| e.to_string())
    }
}

/// The app given `start`, with no GPU renderer.
fn harness_starting(start: StartOptions) -> Harness<'static, LinkageApp> {
    let mut h = Harness::builder()
        .with_size(egui::vec2(1500.0, 950.0))
        .build_eframe(move |cc| LinkageApp::new(cc, start.clone()));
    h.run();
    h
}

/// Regression (issue 22, finding 7): `linkage-lab FILE.ron` opened the default scene;
/// the file named on the command line opens at start.
#[test]
fn a_scene_file_named_on_the_command_line_opens_at_start() {
    let file = shipped("quick_return.ron");
    let h = harness_starting(StartOptions {
        file: Some(file),
        ..StartOptions::default()
    });
    let s = &h.state().state.session;
    assert_eq!(
        s.source(),
        &SceneSource::File("quick_return.ron".into()),
        "{}",
        status(&h)
    );
    // A file that cannot be read leaves the default scene, saying why.
    let h = harness_starting(StartOptions {
        file: Some(PathBuf::from("/no/such/scene.ron")),
        ..StartOptions::default()
    });
    assert!(status(&h).contains("/no/such/scene.ron"), "{}", status(&h));
}

/// Regression (issue 22, finding 7): a scene file dropped on the window did nothing;
/// it opens, and over unsaved edits the app asks first, as Open does.
#[test]
fn a_scene_file_dropped_on_the_window_opens() {
    let mut h = harness_starting(StartOptions::default());
    let drop = |h: &mut Harness<'static, LinkageApp>, file: &str| {
        h.input_mut()
            .dropped_files
            .push(Arc::new(Dropped(shipped(file))));
        h.run();
    };
    drop(&mut h, "slider_crank.ron");
    assert_eq!(
        h.state().state.session.source(),
        &SceneSource::File("slider_crank.ron".into())
    );
    h.state_mut().state.edit(SceneEdit::Length {
        index: 0,
        value: 0.11,
    });
    h.run();
    drop(&mut h, "quick_return.ron");
    assert!(
        h.state().state.commands.waiting.is_some(),
        "asks over unsaved edits"
    );
}

/// The desktop binary's own doors (issue 22, finding 7): `--help` and `--version`
/// print without opening a window, an unknown argument is refused with status 2, and
/// with no display the app says so in one line instead of winit's error structure.
#[test]
fn the_desktop_binary_answers_its_command_line_and_names_a_missing_display() {
    let run = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_linkage-lab"))
            .args(args)
            .env_remove("DISPLAY")
            .env_remove("WAYLAND_DISPLAY")
            .output()
            .expect("runs")
    };
    let help = run(&["--help"]);
    assert_eq!(help.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&help.stdout).contains("--scene"));
    let version = run(&["--version"]);
    assert!(String::from_utf8_lossy(&version.stdout).contains(env!("CARGO_PKG_VERSION")));
    let unknown = run(&["--frobnicate"]);
    assert_eq!(unknown.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&unknown.stderr).contains("--frobnicate"));
    let headless = run(&["--scene", "quick_return"]);
    let err = String::from_utf8_lossy(&headless.stderr);
    assert_eq!(headless.status.code(), Some(1), "{err}");
    assert!(
        err.trim().lines().count() == 1 && err.contains("DISPLAY") && !err.contains("OsError"),
        "{err}"
    );
}

/// The cam panel's exports of the paper-cup feed's cam: the table as CSV (the
/// session's, every cam angle), the profile sheet as SVG, and the DXF read back by
/// the `dxf` crate with every profile point of the table in it (to 1e-9 mm).
#[test]
fn the_cam_panel_exports_csv_svg_and_a_dxf_holding_every_profile_point() {
    let dir = scratch("cam-export");
    let (mut h, _) = harness_answering(PathAnswer::Cancelled);
    let session = linkage_lab::session::Session::open_builtin("paper_cup_cam_feed").expect("opens");
    h.state_mut().state.session = session;
    h.run();
    let mut written = Vec::new();
    for (label, file) in [
        ("Cam CSV…", "cam.csv"),
        ("Cam SVG…", "cam.svg"),
        ("Cam DXF…", "cam.dxf"),
    ] {
        let path = dir.join(file);
        let dialog = Arc::new(Scripted {
            answer: PathAnswer::Chosen(path.clone()),
            asked: Mutex::new(Vec::new()),
        });
        h.state_mut().panels.files.dialog.chooser = dialog.clone();
        click(&mut h, label);
        h.run();
        let asked = dialog.asked.lock().expect("not poisoned").clone();
        assert_eq!(asked.len(), 1, "{label}");
        assert!(path.exists(), "{label}: {}", status(&h));
        written.push(path);
    }
    let csv = std::fs::read_to_string(&written[0]).expect("csv");
    assert_eq!(
        Some(csv.as_str()),
        h.state().state.session.cam_csv(0).as_deref()
    );
    let svg = std::fs::read_to_string(&written[1]).expect("svg");
    assert!(
        // The title names the links as the user named them, not the joint's id.
        svg.contains(": cam on crank, follower bell_crank") && !svg.contains("crank/bell_crank"),
        "{}",
        &svg[..200]
    );
    let drawing = dxf::Drawing::load_file(&written[2]).expect("the DXF parses");
    let profile = drawing
        .entities()
        .find_map(|e| match &e.specific {
            dxf::entities::EntityType::LwPolyline(p) if e.common.layer == "PROFILE" => {
                Some(p.clone())
            }
            _ => None,
        })
        .expect("a profile polyline");
    let rows: Vec<Vec<f64>> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().expect("a number")).collect())
        .collect();
    assert_eq!(profile.vertices.len(), rows.len());
    for (v, row) in profile.vertices.iter().zip(&rows) {
        let (x, y) = (row[7] * 1e3, row[8] * 1e3);
        assert!(
            (v.x - x).abs() < 1e-9 && (v.y - y).abs() < 1e-9,
            "({}, {}) vs ({x}, {y})",
            v.x,
            v.y
        );
    }
    std::fs::remove_dir_all(dir).expect("clean up");
}
