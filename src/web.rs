//! Browser glue: the state in the URL fragment, file download (save, CSV) and upload
//! (open a scene) through the page's DOM.

use std::cell::RefCell;
use std::rc::Rc;

use eframe::wasm_bindgen::{JsCast as _, JsValue, closure::Closure};

use crate::session::{Session, url_state};

thread_local! {
    /// The last frame's controls and state as JSON (the page's test hook reads it).
    static CONTROLS: RefCell<String> = const { RefCell::new(String::new()) };
}

/// What the page's test hook returns: the controls on screen and the session's state.
#[derive(serde::Serialize)]
struct Published<'a> {
    /// Which frame this is (the first is 1): a control's place is settled only when
    /// two different frames show it in the same place.
    frame: u64,
    controls: &'a crate::ui::control_map::ControlMap,
    /// What the last edit could not do (a refusal), if anything.
    message: Option<String>,
    /// The status line: what the last file, link or drop did, or why it did not.
    status: Option<&'a str>,
    /// CPU time of the frames that carried an edit (performance.now() in the browser).
    edit_timing: crate::state::EditTiming,
    /// Whether a dynamic run is still being computed.
    run_pending: bool,
    /// Current input angle, deg: the value that `--input-deg` turns back into exactly
    /// the angle on screen ([`degrees_exactly`]).
    input_deg: f64,
    /// The scene's name.
    scene_name: &'a str,
    /// Whether it has unsaved edits.
    dirty: bool,
    /// Every joint: its name, world place (m) and place on screen (points).
    joints: Vec<PublishedJoint<'a>>,
    /// Whether the pose holds only finite numbers.
    pose_finite: bool,
    /// Whether the GPU renderer of the mechanism view started.
    renderer: bool,
    /// The view's camera: the world point at the view's centre (m) and points per
    /// metre, so that a test can click at a world place.
    camera: [f64; 3],
    /// The drawing, while the drawing tools are out.
    drawing: Option<PublishedDrawing>,
    /// The synthesis window's path targets placed.
    path_targets: usize,
    /// The synthesis window's path search, once started.
    path_search: Option<PublishedSearch>,
    /// Why the last path search did not start, if it did not.
    path_refused: Option<&'a str>,
    /// How the panels are arranged for the screen.
    arrangement: crate::ui::layout::Arrangement,
    /// The sheet's tab shown (in the compact arrangements).
    sheet_tab: crate::ui::layout::SheetTab,
    /// The language of the app's words, as its locale code ("en", "zh-CN").
    language: &'static str,
    /// The exercise open at the desk, if any.
    exercise: Option<PublishedExercise<'a>>,
}

/// The open exercise as the test hook shows it.
#[derive(serde::Serialize)]
struct PublishedExercise<'a> {
    /// The exercise's id.
    id: &'a str,
    /// The student's number, once a variant is drawn.
    student: Option<&'a str>,
    /// The varied dimensions (no truth).
    values: Vec<f64>,
    /// The answer code, while every answer typed reads.
    code: Option<String>,
}

/// A path search as the test hook shows it.
#[derive(serde::Serialize)]
struct PublishedSearch {
    /// Targets placed.
    targets: usize,
    /// Whether it is still running.
    running: bool,
    /// Evaluations so far.
    evaluations: u64,
    /// Designs within tolerance.
    solutions: usize,
    /// The best design's largest miss over the targets' size.
    best_relative_error: f64,
    /// Time spent searching so far, ms (the slices' sum).
    search_ms: f64,
    /// What a slice may spend, ms.
    slice_budget_ms: f64,
    /// How the slices went.
    slices: crate::synthesis::path_job::Slices,
}

/// The path search of the synthesis window, if one was started.
fn path_search(synthesis: Option<&crate::ui::synthesis::SynthesisView>) -> Option<PublishedSearch> {
    let view = synthesis?;
    let job = view.path.job.as_ref()?;
    let p = job.snapshot().progress;
    Some(PublishedSearch {
        targets: view.inputs.path.targets.len(),
        running: job.is_running(),
        evaluations: p.evaluations,
        solutions: p.solutions,
        best_relative_error: p.best_relative_error,
        search_ms: p.seconds * 1e3,
        slice_budget_ms: crate::ui::synthesis::path::SLICE_MS,
        slices: job.slices(),
    })
}

/// A drawing as the test hook shows it.
#[derive(serde::Serialize)]
struct PublishedDrawing {
    points: usize,
    links: usize,
    /// Whether it is a mechanism (then it is the open scene).
    complete: bool,
}

/// A joint as the test hook shows it.
#[derive(serde::Serialize)]
struct PublishedJoint<'a> {
    name: &'a str,
    world: [f64; 2],
    screen: [f32; 2],
}

/// The joints of the pose, with their places on screen in the mechanism view.
fn joints<'a>(
    st: &'a crate::state::AppState,
    camera: &crate::render::view::Camera,
) -> Vec<PublishedJoint<'a>> {
    let m = st.session.mechanism();
    let view = st.controls.view.map(|[x0, y0, x1, y1]| {
        eframe::egui::Rect::from_min_max(eframe::egui::pos2(x0, y0), eframe::egui::pos2(x1, y1))
    });
    st.session
        .topology()
        .joint_points
        .iter()
        .map(|&p| {
            let q = st.session.pose().points[p].position;
            let screen = view.map_or([f32::NAN; 2], |r| {
                let s = camera.to_screen([q.x, q.y], r);
                [s.x, s.y]
            });
            PublishedJoint {
                name: &m.points[p].name,
                world: [q.x, q.y],
                screen,
            }
        })
        .collect()
}

/// The angle in degrees whose `to_radians` is exactly `rad`, where one is within an
/// ulp of `rad.to_degrees()` (that alone misses by an ulp about one time in twenty,
/// and the browser test's CLI sheet at a one-ulp different angle can place a label
/// differently): the CLI given it draws the very pose on screen.
fn degrees_exactly(rad: f64) -> f64 {
    let deg = rad.to_degrees();
    [deg, deg.next_up(), deg.next_down()]
        .into_iter()
        .find(|d| d.to_radians() == rad)
        .unwrap_or(deg)
}

/// Keeps this frame's controls for [`controls_json`]; `renderer`: whether the view's
/// GPU renderer started.
pub fn publish_controls(
    st: &crate::state::AppState,
    camera: &crate::render::view::Camera,
    synthesis: Option<&crate::ui::synthesis::SynthesisView>,
    frame: u64,
    renderer: bool,
) {
    let pose = st.session.pose();
    let published = Published {
        frame,
        controls: &st.controls,
        message: st.session.message_in(crate::ui::words::lang()),
        status: st.status.as_deref(),
        edit_timing: st.timing.edit_timing,
        run_pending: st.session.run_progress().is_some(),
        input_deg: degrees_exactly(st.session.input_rad()),
        scene_name: &st.session.scene().name,
        dirty: st.session.is_dirty(),
        joints: joints(st, camera),
        pose_finite: pose.points.iter().all(|p| {
            p.position.x.is_finite() && p.position.y.is_finite() && p.velocity.x.is_finite()
        }),
        renderer,
        camera: [camera.center_m[0], camera.center_m[1], camera.points_per_m],
        drawing: st.drawing.as_ref().map(|b| PublishedDrawing {
            points: b.drawing().points.len(),
            links: b.drawing().links.len(),
            complete: b.problem.is_none(),
        }),
        path_targets: synthesis.map_or(0, |v| v.inputs.path.targets.len()),
        path_search: path_search(synthesis),
        path_refused: synthesis.and_then(|v| v.path.refused()),
        arrangement: st.layout.arrangement,
        sheet_tab: st.layout.tab,
        language: st.language.code(),
        exercise: st.exercise.as_ref().map(|d| PublishedExercise {
            id: &d.exercise.file.id,
            student: d.variant.as_ref().map(|v| v.student.as_str()),
            values: d
                .variant
                .as_ref()
                .map(|v| v.values.clone())
                .unwrap_or_default(),
            code: d.code(),
        }),
    };
    let json = serde_json::to_string(&published).unwrap_or_default();
    CONTROLS.with(|c| *c.borrow_mut() = json);
}

/// The last frame's controls and state as JSON.
pub fn controls_json() -> String {
    CONTROLS.with(|c| c.borrow().clone())
}

/// The page's URL fragment (with its `#`), or empty.
pub fn fragment() -> String {
    web_sys::window()
        .and_then(|w| w.location().hash().ok())
        .unwrap_or_default()
}

/// Writes the session's state into the URL when it changes (replaceState: no history
/// entry per slider step).
#[derive(Default)]
pub struct UrlSync {
    last: String,
}

impl UrlSync {
    /// Forgets what it wrote, so that the next update writes the state afresh.
    pub fn forget(&mut self) {
        self.last.clear();
    }

    /// Updates the URL if the state differs from the last one written (the
    /// language, a preference, beside it where it is not English). Returns why the
    /// scene cannot travel in the URL, once, when that becomes so.
    pub fn update(&mut self, s: &Session, language: crate::i18n::Language) -> Option<String> {
        let scene = url_state::encode(s);
        let now = if scene.is_empty() {
            scene
        } else {
            scene + &crate::language_pref::fragment_entry(language)
        };
        if now == self.last {
            return None;
        }
        self.last = now.clone();
        if now.is_empty() {
            return s.share_payload().err().map(|e| {
                crate::i18n::tr!(
                    "file.link_not_kept",
                    why = linkage_diagram::refusal::share(crate::ui::words::lang(), e)
                )
            });
        }
        if let Some(history) = web_sys::window().and_then(|w| w.history().ok()) {
            let _ = history.replace_state_with_url(&JsValue::NULL, "", Some(&format!("#{now}")));
        }
        None
    }
}

/// Watches the page's fragment for changes the user makes: a link pasted into the
/// address bar of the open page, back, forward. The app's own writes go through
/// `replaceState`, which fires no `hashchange`.
#[derive(Default)]
pub struct FragmentWatch {
    changed: Rc<std::cell::Cell<bool>>,
    installed: bool,
}

impl FragmentWatch {
    /// Listens for `hashchange` (once), asking `ctx` for a frame when one comes.
    pub fn install(&mut self, ctx: &eframe::egui::Context) {
        if self.installed {
            return;
        }
        self.installed = true;
        let Some(window) = web_sys::window() else {
            return;
        };
        let changed = self.changed.clone();
        let ctx = ctx.clone();
        let on_change = Closure::<dyn FnMut()>::new(move || {
            changed.set(true);
            ctx.request_repaint();
        });
        let listened = window
            .add_event_listener_with_callback("hashchange", on_change.as_ref().unchecked_ref());
        if let Err(e) = listened {
            log::warn!("links pasted into the open page will not open: {e:?}");
        }
        // The listener lives as long as the page.
        on_change.forget();
    }

    /// Whether the fragment changed since the last call.
    pub fn take(&self) -> bool {
        self.changed.replace(false)
    }
}

/// Opens what the page's fragment names, if it is not what the app shows (asking
/// first over unsaved edits, as opening a file does); a link that does not open is
/// said in the status line. The address then follows the app again (`url` writes it
/// afresh): the current scene's until the new one opens.
pub fn follow_fragment(st: &mut crate::state::AppState, url: &mut UrlSync) {
    let fragment = fragment();
    // The language a link asks for is a preference, followed at once; the rest is
    // the scene.
    if let Some(language) = crate::language_pref::in_fragment(&fragment) {
        st.language = language;
    }
    if let Some((key, student)) = crate::exercise_desk::exercise_link(&fragment) {
        st.open_exercise_link(&key, student.as_deref());
        return;
    }
    let wanted = crate::language_pref::without_language(&fragment);
    if wanted == url_state::encode(&st.session) {
        return;
    }
    match url_state::open(&url_state::decode(&fragment)) {
        Ok(session) => {
            log::info!("opening the link's scene: {}", session.scene().name);
            st.open(session);
        }
        Err(e) => {
            let why = e.words(crate::ui::words::lang());
            st.status = Some(crate::i18n::tr!("file.link_failed", why = why));
        }
    }
    url.forget();
}

/// The page's address, which carries the scene (the share link).
pub fn page_url() -> Option<String> {
    web_sys::window().and_then(|w| w.location().href().ok())
}

/// Offers `bytes` as a download named `file_name`, of type `mime`.
pub fn download(file_name: &str, mime: &str, bytes: &[u8]) -> Result<(), String> {
    let err = |e: JsValue| format!("download failed: {e:?}");
    let parts = js_sys::Array::of1(&js_sys::Uint8Array::from(bytes));
    let options = web_sys::BlobPropertyBag::new();
    options.set_type(mime);
    let blob =
        web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options).map_err(err)?;
    download_blob(file_name, &blob).map_err(err)
}

/// Hands `blob` to the browser as a download named `file_name`.
fn download_blob(file_name: &str, blob: &web_sys::Blob) -> Result<(), JsValue> {
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?;
    let url = web_sys::Url::create_object_url_with_blob(blob)?;
    let a: web_sys::HtmlAnchorElement = document.create_element("a")?.dyn_into()?;
    a.set_href(&url);
    a.set_download(file_name);
    a.click();
    web_sys::Url::revoke_object_url(&url)
}

/// Downloads `svg` as a PNG at `dpi` (the sheet's units are CSS pixels, 96 to the
/// inch), rasterised by the browser itself: an image of the SVG drawn on a canvas.
/// The work finishes in the image's load callback, after this returns; a failure
/// there is logged.
pub fn download_svg_as_png(file_name: &str, svg: &str, dpi: f32) -> Result<(), String> {
    let err = |e: JsValue| format!("PNG export failed: {e:?}");
    let parts = js_sys::Array::of1(&JsValue::from_str(svg));
    let options = web_sys::BlobPropertyBag::new();
    options.set_type("image/svg+xml");
    let blob = web_sys::Blob::new_with_str_sequence_and_options(&parts, &options).map_err(err)?;
    let url = web_sys::Url::create_object_url_with_blob(&blob).map_err(err)?;
    let image = web_sys::HtmlImageElement::new().map_err(err)?;
    let (name, loaded, src) = (file_name.to_string(), image.clone(), url.clone());
    let onload = Closure::once_into_js(move || {
        let _ = web_sys::Url::revoke_object_url(&src);
        if let Err(e) = draw_and_download(&loaded, f64::from(dpi) / 96.0, name) {
            log::warn!("PNG export failed: {e:?}");
        }
    });
    image.set_onload(Some(onload.unchecked_ref()));
    image.set_src(&url);
    Ok(())
}

/// Draws the loaded `image` on a white canvas `scale` times its size and downloads it.
fn draw_and_download(
    image: &web_sys::HtmlImageElement,
    scale: f64,
    name: String,
) -> Result<(), JsValue> {
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?;
    let canvas: web_sys::HtmlCanvasElement = document.create_element("canvas")?.dyn_into()?;
    let (w, h) = (
        f64::from(image.natural_width()) * scale,
        f64::from(image.natural_height()) * scale,
    );
    canvas.set_width(w.round() as u32);
    canvas.set_height(h.round() as u32);
    let context: web_sys::CanvasRenderingContext2d = canvas
        .get_context("2d")?
        .ok_or("no 2d context")?
        .dyn_into()?;
    context.set_fill_style_str("white");
    context.fill_rect(0.0, 0.0, w, h);
    context.draw_image_with_html_image_element_and_dw_and_dh(image, 0.0, 0.0, w, h)?;
    let done = Closure::once_into_js(move |blob: Option<web_sys::Blob>| {
        let sent = blob
            .ok_or_else(|| JsValue::from_str("the canvas gave no PNG"))
            .and_then(|b| download_blob(&name, &b));
        if let Err(e) = sent {
            log::warn!("PNG export failed: {e:?}");
        }
    });
    canvas.to_blob(done.unchecked_ref())
}

/// Prints `sheet`'s A4 pages through the browser's own print dialog, where the user
/// saves them as one PDF (text stays text, the browser embeds the fonts): a hidden
/// frame holds the pages, each an A4 box, and prints itself once loaded. The PDF
/// writer of the desktop app (krilla) would add to every English user's first
/// download; the browser already has one.
pub fn print_pages(sheet: &linkage_diagram::pages::Sheet) -> Result<(), String> {
    let err = |e: JsValue| format!("printing failed: {e:?}");
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?;
    let body = document.body().ok_or("no page body")?;
    let frame: web_sys::HtmlIFrameElement = document
        .create_element("iframe")
        .and_then(|e| e.dyn_into().map_err(JsValue::from))
        .map_err(err)?;
    frame
        .set_attribute(
            "style",
            "position:fixed;width:0;height:0;border:0;left:-10px",
        )
        .map_err(err)?;
    frame.set_srcdoc(&print_document(sheet));
    let printed = frame.clone();
    let onload = Closure::once_into_js(move || {
        if let Some(w) = printed.content_window()
            && let Err(e) = w.print()
        {
            log::warn!("printing failed: {e:?}");
        }
    });
    frame.set_onload(Some(onload.unchecked_ref()));
    body.append_child(&frame).map_err(err)?;
    Ok(())
}

/// The pages as one HTML document for print: A4 paper, no margins (each page has
/// its own), a page break after each.
fn print_document(sheet: &linkage_diagram::pages::Sheet) -> String {
    let pages: String = sheet
        .pages
        .iter()
        .map(|p| {
            // The XML declaration belongs to a file, not to inline SVG.
            let svg = p.split_once("?>").map_or(p.as_str(), |(_, rest)| rest);
            format!("<div class=\"page\">{svg}</div>")
        })
        .collect();
    let title = sheet.title.replace('&', "&amp;").replace('<', "&lt;");
    format!(
        "<!doctype html><html><head><meta charset=\"utf-8\"><title>{title}</title><style>\
         @page {{ size: A4; margin: 0 }} html, body {{ margin: 0 }} \
         .page {{ width: 210mm; height: 297mm; overflow: hidden; break-after: page }} \
         .page svg {{ display: block; width: 210mm; height: 297mm }}</style></head>\
         <body>{pages}</body></html>"
    )
}

/// A file the user picked, read as text, waiting for the next frame to take it.
pub type Upload = Rc<RefCell<Option<(String, String)>>>;

/// Opens the browser's file picker; the chosen file's text lands in `slot`, and `ctx`
/// is asked to repaint so that a paused app takes it at once.
pub fn pick_file(slot: &Upload, ctx: &eframe::egui::Context) -> Result<(), String> {
    let err = |e: JsValue| format!("file picker failed: {e:?}");
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?;
    let input: web_sys::HtmlInputElement = document
        .create_element("input")
        .map_err(err)?
        .dyn_into()
        .map_err(|_| "not an input")?;
    input.set_type("file");
    input.set_accept(".ron,text/plain");
    let slot = slot.clone();
    let ctx = ctx.clone();
    let picked = input.clone();
    let on_change = Closure::<dyn FnMut()>::new(move || {
        let Some(file) = picked.files().and_then(|f| f.get(0)) else {
            return;
        };
        let name = file.name();
        let slot = slot.clone();
        let ctx = ctx.clone();
        let promise = file.text();
        wasm_bindgen_futures::spawn_local(async move {
            if let Ok(text) = wasm_bindgen_futures::JsFuture::from(promise).await {
                *slot.borrow_mut() = Some((name, text.as_string().unwrap_or_default()));
                ctx.request_repaint();
            }
        });
    });
    input.set_onchange(Some(on_change.as_ref().unchecked_ref()));
    // The closure must outlive this call: the picker answers later, once.
    on_change.forget();
    input.click();
    Ok(())
}

/// Reads a file dropped on the page (the browser reads it asynchronously) into
/// `slot`, for the next frame to open as an upload; asks `ctx` for that frame.
pub fn read_dropped(
    file: eframe::egui::DroppedFileHandle,
    slot: &Upload,
    ctx: &eframe::egui::Context,
) {
    let slot = slot.clone();
    let ctx = ctx.clone();
    wasm_bindgen_futures::spawn_local(async move {
        let name = file.path().file_name().map_or_else(
            || "dropped.ron".to_string(),
            |n| n.to_string_lossy().into_owned(),
        );
        match file.bytes_async().await {
            Ok(bytes) => {
                *slot.borrow_mut() = Some((name, String::from_utf8_lossy(&bytes).into_owned()));
            }
            Err(e) => log::warn!("the dropped file {name} could not be read: {e}"),
        }
        ctx.request_repaint();
    });
}

/// The local-storage key of the drawing being made.
const DRAWING_KEY: &str = "linkage-lab.drawing";

fn local_storage() -> Option<web_sys::Storage> {
    web_sys::window()?.local_storage().ok().flatten()
}

/// Keeps the drawing in the browser's local storage while the drawing tools are
/// out, with the page's address, so that a reload of that address goes on with an
/// unfinished drawing; forgets it when the tools are put away.
#[derive(Default)]
pub struct DrawingStore {
    /// The drawing's revision and the address last stored.
    stored: Option<(u64, String)>,
}

impl DrawingStore {
    /// Stores the drawing if it or the address changed, or forgets it.
    pub fn update(&mut self, drawing: Option<&crate::drawing::DrawingEditor>) {
        let Some(storage) = local_storage() else {
            return;
        };
        match drawing {
            Some(b) => {
                let now = (b.revision(), fragment());
                if self.stored.as_ref() != Some(&now) {
                    let text = crate::drawing::stored::to_text(b.drawing());
                    // A full or refused store only loses the reload's copy.
                    let _ = storage.set_item(DRAWING_KEY, &format!("{}\n{text}", now.1));
                    self.stored = Some(now);
                }
            }
            None if self.stored.is_some() => {
                let _ = storage.remove_item(DRAWING_KEY);
                self.stored = None;
            }
            None => {}
        }
    }
}

/// The drawing an earlier load of this same address kept, or why it cannot be read;
/// `None` when there is none for this address (a shared link opens what it names).
pub fn stored_drawing() -> Option<Result<linkage::drawing::Drawing, String>> {
    let text = local_storage()?.get_item(DRAWING_KEY).ok().flatten()?;
    let (address, drawing) = text.split_once('\n')?;
    (address == fragment()).then(|| crate::drawing::stored::from_text(drawing))
}
