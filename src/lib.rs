//! Linkage Lab: the eframe/egui viewer over the `linkage` solver.
//!
//! The same crate builds the desktop app (`src/main.rs`) and the browser demo
//! (wasm32, started by [`start_web`]).

mod app;
mod apply;
pub mod command;
pub mod exercise_desk;
pub mod file_action;
#[cfg(not(target_arch = "wasm32"))]
pub mod file_dialog;
pub mod fonts;
pub mod gear_lab;
pub mod i18n;
pub mod language_pref;
pub mod render;
pub mod start;
pub mod state;
#[cfg(test)]
mod test_sources;
pub mod train_view;
pub mod ui;
#[cfg(target_arch = "wasm32")]
mod web;
#[cfg(target_arch = "wasm32")]
mod web_font;

/// The controls on screen and the session's state as JSON, for the browser test
/// (exported to the page by the binary as `linkage_lab_controls`).
#[cfg(target_arch = "wasm32")]
pub fn controls_json() -> String {
    web::controls_json()
}

/// The CPU of a length edit of the shipped scene `key`, measured here in the page
/// (the median of repeated edits, valid and refused, ms) as JSON, for the browser
/// test (exported by the binary as `linkage_lab_edit_cpu`); `null` for no such scene.
#[cfg(target_arch = "wasm32")]
pub fn edit_cpu_json(key: &str) -> String {
    let cpu = catalog::builtin(key)
        .and_then(|b| linkage::SceneFile::parse(b.text).ok())
        .and_then(|scene| session::edit_cost::edit_cpu(&scene));
    serde_json::to_string(&cpu).unwrap_or_else(|_| "null".into())
}

pub use app::LinkageApp;
pub use state::AppState;
// The model lives in its own crate (no GUI); the app and its tests reach it here too.
pub use linkage_model::{catalog, drawing, exercise, job, session, synthesis};

pub use start::StartOptions;

/// Starts the app on the page's `<canvas id="linkage_canvas">` (browser only).
#[cfg(target_arch = "wasm32")]
pub fn start_web() {
    use eframe::wasm_bindgen::JsCast as _;
    // Log lines go to the browser console (the browser test reads them).
    let _ = eframe::WebLogger::init(log::LevelFilter::Info);
    wasm_bindgen_futures::spawn_local(async {
        let Some(document) = web_sys::window().and_then(|w| w.document()) else {
            log::error!("no document: Linkage Lab must run in a browser page");
            return;
        };
        let Some(canvas) = document
            .get_element_by_id("linkage_canvas")
            .and_then(|e| e.dyn_into::<web_sys::HtmlCanvasElement>().ok())
        else {
            log::error!("the page has no <canvas id=\"linkage_canvas\">");
            return;
        };
        #[cfg(feature = "webgl")]
        single_sampled_webgl2(&canvas);
        let result = eframe::WebRunner::new()
            .start(
                canvas,
                eframe::WebOptions::default(),
                Box::new(|cc| Ok(Box::new(LinkageApp::new(cc, web_start_options())))),
            )
            .await;
        if let Err(err) = result {
            log::error!("failed to start Linkage Lab: {err:?}");
        }
    });
}

/// Creates the canvas's WebGL2 context without multisampling or a depth buffer, before
/// eframe asks for it (a canvas hands every later `getContext("webgl2")` the context it
/// already has). eframe asks with WebGL's defaults, which multisample: egui feathers its
/// own edges and the mechanism's shader computes its coverage, so the four samples a
/// pixel bought nothing but raster work. Measured in headless Chromium on SwiftShader,
/// `tests/browser/laptop.mjs` took 30 s instead of 53 s (docs/architecture.md, "CI time").
#[cfg(all(target_arch = "wasm32", feature = "webgl"))]
fn single_sampled_webgl2(canvas: &web_sys::HtmlCanvasElement) {
    let options = js_sys::Object::new();
    for key in ["antialias", "depth"] {
        let _ = js_sys::Reflect::set(&options, &key.into(), &false.into());
    }
    if let Err(err) = canvas.get_context_with_context_options("webgl2", &options) {
        // eframe then makes its own, multisampled: slower, not wrong.
        log::warn!("no single-sampled WebGL2 context: {err:?}");
    }
}

/// The web demo's start: the language a share link asks for, else the one chosen on
/// an earlier visit, else the browser's.
#[cfg(target_arch = "wasm32")]
fn web_start_options() -> StartOptions {
    let language =
        language_pref::in_fragment(&web::fragment()).unwrap_or_else(language_pref::at_start);
    StartOptions {
        language,
        remember_choices: true,
        ..StartOptions::default()
    }
}
