//! What the rendering UI tests share: the app as a user opens it, in a kittest
//! harness drawing through wgpu (Mesa's lavapipe in CI), timings hidden so that the
//! pixels repeat.

use eframe::egui;
use egui_kittest::Harness;
use linkage_lab::{LinkageApp, StartOptions};

/// The app at its default scene, 1500×950, before its first frame.
pub fn app_harness() -> Harness<'static, LinkageApp> {
    let mut h = Harness::builder()
        .with_size(egui::vec2(1500.0, 950.0))
        .wgpu()
        .build_eframe(|cc| LinkageApp::new(cc, StartOptions::default()));
    h.state_mut().state.show_timings = false;
    h
}
