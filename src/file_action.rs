//! What a file prompt does: open or save a scene, export the sweep or the sheet.
//! Shared by the files panel, the desktop's dialog and the browser's picker.

/// What a file prompt will do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileAction {
    /// Read a scene file.
    Open,
    /// Write the edited scene.
    SaveScene,
    /// Write the sweep as CSV.
    ExportCsv,
    /// Write the sheet of the current position (pose, polygons, tables) as SVG.
    ExportSheet,
    /// The same sheet as PNG.
    ExportSheetPng,
}

impl FileAction {
    /// The dialog's title.
    pub fn title(self) -> &'static str {
        match self {
            Self::Open => "Open scene file",
            Self::SaveScene => "Save scene file",
            Self::ExportCsv => "Export sweep CSV",
            Self::ExportSheet => "Export diagram sheet (SVG)",
            Self::ExportSheetPng => "Export diagram sheet (PNG)",
        }
    }

    /// The file type read or written, as (name, extension without the dot).
    pub fn file_type(self) -> (&'static str, &'static str) {
        match self {
            Self::Open | Self::SaveScene => ("Linkage scene", "ron"),
            Self::ExportCsv => ("CSV table", "csv"),
            Self::ExportSheet => ("SVG drawing", "svg"),
            Self::ExportSheetPng => ("PNG picture", "png"),
        }
    }
}
