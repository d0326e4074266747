//! The App: a minimal window over the solver until the viewer issue lands.

use eframe::egui;

/// The Linkage Lab application state.
pub struct LinkageApp {
    frames_drawn: u64,
    exit_after_frames: Option<u64>,
}

impl LinkageApp {
    /// Creates the app; `exit_after_frames` closes the window after that many frames.
    pub fn new(_cc: &eframe::CreationContext<'_>, exit_after_frames: Option<u64>) -> Self {
        Self {
            frames_drawn: 0,
            exit_after_frames,
        }
    }
}

impl eframe::App for LinkageApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        ui.heading("Linkage Lab");
        ui.label("Planar linkage simulator");
        self.frames_drawn += 1;
        if let Some(n) = self.exit_after_frames {
            // egui repaints only on input: a smoke run has to ask for every frame.
            ui.ctx().request_repaint();
            if self.frames_drawn >= n {
                ui.ctx().send_viewport_cmd(egui::ViewportCommand::Close);
            }
        }
    }
}
