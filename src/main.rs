//! Entry points only: the native window and the browser start.

#![cfg_attr(not(debug_assertions), windows_subsystem = "windows")]

#[cfg(not(target_arch = "wasm32"))]
fn main() -> eframe::Result {
    // The app's own messages (opened files, scenes that failed) at info, the
    // libraries' only when they warn; RUST_LOG overrides.
    env_logger::Builder::from_env(
        env_logger::Env::default().default_filter_or("warn,linkage_lab=info"),
    )
    .init();
    let options = eframe::NativeOptions {
        viewport: eframe::egui::ViewportBuilder::default()
            .with_title("Linkage Lab")
            .with_inner_size([1100.0, 720.0]),
        ..Default::default()
    };
    let start = linkage_lab::StartOptions::from_args(std::env::args());
    eframe::run_native(
        "Linkage Lab",
        options,
        Box::new(move |cc| Ok(Box::new(linkage_lab::LinkageApp::new(cc, start)))),
    )
}

#[cfg(target_arch = "wasm32")]
fn main() {
    linkage_lab::start_web();
}

/// The browser test's hook: where each control is and the session's state, as JSON
/// (`window.wasmBindings.linkage_lab_controls()`).
#[cfg(target_arch = "wasm32")]
#[wasm_bindgen::prelude::wasm_bindgen]
pub fn linkage_lab_controls() -> String {
    linkage_lab::controls_json()
}
