//! The Chinese face in the web demo, fetched from beside the page
//! ([`crate::fonts::CJK_FONT_URL`]) only once the app is to show Chinese text: egui
//! asks a font provider for a glyph no installed face has, the provider notes that a
//! Chinese character was wanted, and the next frame starts the fetch. Until the face
//! arrives, those characters draw as boxes; then every text is laid out again.
//! An English user's first download does not grow by the face's 1.5 MB.

use std::cell::RefCell;
use std::rc::Rc;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use eframe::egui::{self, FallbackRequest, FontData, FontInsert};
use wasm_bindgen::JsCast;

use crate::fonts::{CJK_FONT_URL, cjk_insert, has_cjk};

/// Where the fetch stands.
enum Fetch {
    /// Not started: no Chinese text has been shown.
    Idle,
    /// Under way.
    Pending,
    /// The face's bytes, to install next frame.
    Arrived(Vec<u8>),
    /// Installed, or failed (logged; the characters stay boxes).
    Done,
}

/// The Chinese face's fetch, started the first time Chinese text is laid out.
pub struct CjkFont {
    wanted: Arc<AtomicBool>,
    fetch: Rc<RefCell<Fetch>>,
}

impl CjkFont {
    /// Watches `ctx`'s text for a Chinese character no face has.
    pub fn watch(ctx: &egui::Context) -> Self {
        let wanted = Arc::new(AtomicBool::new(false));
        let flag = Arc::clone(&wanted);
        let provider = move |request: &FallbackRequest<'_>| -> Option<FontInsert> {
            if has_cjk(request.cluster) {
                flag.store(true, Ordering::Relaxed);
            }
            None
        };
        ctx.add_font_provider(Arc::new(provider));
        Self {
            wanted,
            fetch: Rc::new(RefCell::new(Fetch::Idle)),
        }
    }

    /// Starts the fetch once a Chinese character was wanted; installs the face once
    /// it has arrived. Called once a frame.
    pub fn update(&self, ctx: &egui::Context) {
        let mut fetch = self.fetch.borrow_mut();
        match &*fetch {
            Fetch::Idle if self.wanted.load(Ordering::Relaxed) => {
                *fetch = Fetch::Pending;
                start(Rc::clone(&self.fetch), ctx.clone());
            }
            Fetch::Arrived(_) => {
                if let Fetch::Arrived(bytes) = std::mem::replace(&mut *fetch, Fetch::Done) {
                    ctx.add_font(cjk_insert(FontData::from_owned(bytes)));
                }
            }
            _ => {}
        }
    }
}

/// Fetches the face; on arrival (or failure) records it and asks for a frame.
fn start(slot: Rc<RefCell<Fetch>>, ctx: egui::Context) {
    wasm_bindgen_futures::spawn_local(async move {
        let outcome = bytes_at(CJK_FONT_URL).await;
        *slot.borrow_mut() = match outcome {
            Ok(bytes) => Fetch::Arrived(bytes),
            Err(why) => {
                log::error!("the Chinese font {CJK_FONT_URL} did not load: {why:?}");
                Fetch::Done
            }
        };
        ctx.request_repaint();
    });
}

/// The body of `url`, relative to the page.
async fn bytes_at(url: &str) -> Result<Vec<u8>, wasm_bindgen::JsValue> {
    use wasm_bindgen_futures::JsFuture;
    let window = web_sys::window().ok_or("no window")?;
    let response: web_sys::Response = JsFuture::from(window.fetch_with_str(url))
        .await?
        .dyn_into()?;
    if !response.ok() {
        return Err(format!("HTTP {}", response.status()).into());
    }
    let buffer = JsFuture::from(response.array_buffer()?).await?;
    Ok(js_sys::Uint8Array::new(&buffer).to_vec())
}
