//! Entry points only: the native window and the browser start.

#![cfg_attr(not(debug_assertions), windows_subsystem = "windows")]

#[cfg(not(target_arch = "wasm32"))]
fn main() -> std::process::ExitCode {
    use std::process::ExitCode;
    // `--help`, `--version` and argument errors end here (clap: status 0 or 2).
    let start = linkage_lab::StartOptions::from_command_line();
    // The app's own messages (opened files, scenes that failed) at info, the
    // libraries' only when they warn; RUST_LOG overrides.
    env_logger::Builder::from_env(
        env_logger::Env::default().default_filter_or("warn,linkage_lab=info"),
    )
    .init();
    let env = |name: &str| std::env::var(name).ok();
    if let Some(why) =
        linkage_lab::start::no_display(env("DISPLAY").as_deref(), env("WAYLAND_DISPLAY").as_deref())
    {
        eprintln!("{why}");
        return ExitCode::FAILURE;
    }
    let options = eframe::NativeOptions {
        viewport: eframe::egui::ViewportBuilder::default()
            .with_title("Linkage Lab")
            .with_inner_size([1280.0, 720.0])
            .with_drag_and_drop(true),
        ..Default::default()
    };
    let result = eframe::run_native(
        "Linkage Lab",
        options,
        Box::new(move |cc| Ok(Box::new(linkage_lab::LinkageApp::new(cc, start)))),
    );
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // One line: winit's errors print as nested debug structures.
            let text = e
                .to_string()
                .split_whitespace()
                .collect::<Vec<_>>()
                .join(" ");
            eprintln!("linkage-lab: cannot open a window: {text}");
            ExitCode::FAILURE
        }
    }
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

/// The browser test's hook: the CPU of a length edit of the shipped scene `key`,
/// measured in the page (`window.wasmBindings.linkage_lab_edit_cpu(key)`).
#[cfg(target_arch = "wasm32")]
#[wasm_bindgen::prelude::wasm_bindgen]
pub fn linkage_lab_edit_cpu(key: String) -> String {
    linkage_lab::edit_cpu_json(&key)
}

/// The browser test's hook: the varied dimensions of a student's variant of a
/// shipped exercise, as JSON (`window.wasmBindings.linkage_lab_exercise_variant`).
#[cfg(target_arch = "wasm32")]
#[wasm_bindgen::prelude::wasm_bindgen]
pub fn linkage_lab_exercise_variant(key: String, student: String) -> String {
    linkage_lab::exercise_desk::variant_json(&key, &student)
}

/// The browser test's hook: a student's answer code made in the page as the desk
/// makes it (`window.wasmBindings.linkage_lab_exercise_code`).
#[cfg(target_arch = "wasm32")]
#[wasm_bindgen::prelude::wasm_bindgen]
pub fn linkage_lab_exercise_code(key: String, student: String, answers: String) -> String {
    linkage_lab::exercise_desk::code_for(&key, &student, &answers)
}
