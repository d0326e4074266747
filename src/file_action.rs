//! What a file prompt does: open or save a scene, export the sweep, the sheet or a
//! cam.
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
    /// Write a cam joint (by its index) over its turn as CSV.
    CamCsv(usize),
    /// Write a cam joint's profile sheet as SVG.
    CamSvg(usize),
    /// Write a cam joint's profile as DXF for manufacture (the desktop app).
    CamDxf(usize),
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
            Self::CamCsv(_) => "Export cam table (CSV)",
            Self::CamSvg(_) => "Export cam profile (SVG)",
            Self::CamDxf(_) => "Export cam profile (DXF)",
        }
    }

    /// The file type read or written, as (name, extension without the dot).
    pub fn file_type(self) -> (&'static str, &'static str) {
        match self {
            Self::Open | Self::SaveScene => ("Linkage scene", "ron"),
            Self::ExportCsv | Self::CamCsv(_) => ("CSV table", "csv"),
            Self::ExportSheet | Self::CamSvg(_) => ("SVG drawing", "svg"),
            Self::ExportSheetPng => ("PNG picture", "png"),
            Self::CamDxf(_) => ("DXF drawing", "dxf"),
        }
    }
}
