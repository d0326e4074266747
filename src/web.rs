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
    /// CPU time of the frames that carried an edit (performance.now() in the browser).
    edit_timing: crate::app::EditTiming,
    /// Whether a dynamic run is still being computed.
    run_pending: bool,
    /// Current input angle, deg.
    input_deg: f64,
    /// Whether the pose holds only finite numbers.
    pose_finite: bool,
}

/// Keeps this frame's controls for [`controls_json`].
pub fn publish_controls(st: &crate::app::AppState, frame: u64) {
    let pose = st.session.pose();
    let published = Published {
        frame,
        controls: &st.controls,
        message: st.session.message(),
        edit_timing: st.edit_timing,
        run_pending: st.session.run_progress().is_some(),
        input_deg: st.session.input_rad().to_degrees(),
        pose_finite: pose.points.iter().all(|p| {
            p.position.x.is_finite() && p.position.y.is_finite() && p.velocity.x.is_finite()
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
    /// Updates the URL if the state differs from the last one written.
    pub fn update(&mut self, s: &Session) {
        let now = url_state::encode(s);
        if now == self.last || now.is_empty() {
            return;
        }
        if let Some(history) = web_sys::window().and_then(|w| w.history().ok()) {
            let _ = history.replace_state_with_url(&JsValue::NULL, "", Some(&format!("#{now}")));
        }
        self.last = now;
    }
}

/// Offers `text` as a download named `file_name`.
pub fn download(file_name: &str, mime: &str, text: &str) -> Result<(), String> {
    let err = |e: JsValue| format!("download failed: {e:?}");
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?;
    let parts = js_sys::Array::of1(&JsValue::from_str(text));
    let options = web_sys::BlobPropertyBag::new();
    options.set_type(mime);
    let blob = web_sys::Blob::new_with_str_sequence_and_options(&parts, &options).map_err(err)?;
    let url = web_sys::Url::create_object_url_with_blob(&blob).map_err(err)?;
    let a: web_sys::HtmlAnchorElement = document
        .create_element("a")
        .map_err(err)?
        .dyn_into()
        .map_err(|_| "not an anchor")?;
    a.set_href(&url);
    a.set_download(file_name);
    a.click();
    web_sys::Url::revoke_object_url(&url).map_err(err)?;
    Ok(())
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
