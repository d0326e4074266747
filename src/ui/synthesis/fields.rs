//! The synthesis window's input fields: numbers and rows of numbers, each labelled
//! so that screen readers and tests find it by its name.

use eframe::egui;

/// A number field with its label (which names it for screen readers and tests).
pub fn number(ui: &mut egui::Ui, v: &mut f64, label: &str, speed: f64) {
    ui.horizontal(|ui| {
        let name = ui.label(label);
        ui.add(egui::DragValue::new(v).speed(speed))
            .labelled_by(name.id);
    });
}

/// A labelled text field for rows of numbers (typed or pasted CSV).
pub fn text_area(ui: &mut egui::Ui, text: &mut String, label: &str) {
    ui.label(label);
    let r = ui.add(
        egui::TextEdit::multiline(text)
            .desired_rows(4)
            .code_editor(),
    );
    r.widget_info(|| {
        egui::WidgetInfo::labeled(egui::accesskit::Role::MultilineTextInput, true, label)
    });
}
