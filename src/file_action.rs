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
    /// The same sheet as PNG, a picture per page.
    ExportSheetPng,
    /// The same sheet as one PDF (in the browser: its print dialog, to save as PDF).
    ExportSheetPdf,
    /// The course sheet (its window's choices) as SVG, a file per page.
    CourseSvg,
    /// The course sheet as PNG, a picture per page.
    CoursePng,
    /// The course sheet as one PDF.
    CoursePdf,
    /// The course-design report (its window's choices) as one PDF.
    ReportPdf,
    /// The open exercise's task sheet of the student's variant as one PDF (in the
    /// browser: its print dialog).
    TaskSheetPdf,
    /// Write a cam joint (by its index) over its turn as CSV.
    CamCsv(usize),
    /// Write a cam joint's profile sheet as SVG.
    CamSvg(usize),
    /// Write a cam joint's profile as DXF for manufacture (the desktop app).
    CamDxf(usize),
}

impl FileAction {
    /// The dialog's title.
    pub fn title(self) -> String {
        match self {
            Self::Open => crate::i18n::tr!("action.open"),
            Self::SaveScene => crate::i18n::tr!("action.save"),
            Self::ExportCsv => crate::i18n::tr!("action.csv"),
            Self::ExportSheet => crate::i18n::tr!("action.svg"),
            Self::ExportSheetPng => crate::i18n::tr!("action.png"),
            Self::ExportSheetPdf => crate::i18n::tr!("action.pdf"),
            Self::CourseSvg | Self::CoursePng | Self::CoursePdf => {
                crate::i18n::tr!("action.course", format = self.file_type().1)
            }
            Self::ReportPdf => crate::i18n::tr!("action.report"),
            Self::TaskSheetPdf => crate::i18n::tr!("action.task_sheet"),
            Self::CamCsv(_) => crate::i18n::tr!("action.cam_csv"),
            Self::CamSvg(_) => crate::i18n::tr!("action.cam_svg"),
            Self::CamDxf(_) => crate::i18n::tr!("action.cam_dxf"),
        }
    }

    /// The file type read or written, as (name, extension without the dot).
    pub fn file_type(self) -> (&'static str, &'static str) {
        match self {
            Self::Open | Self::SaveScene => ("Linkage scene", "ron"),
            Self::ExportCsv | Self::CamCsv(_) => ("CSV table", "csv"),
            Self::ExportSheet | Self::CamSvg(_) | Self::CourseSvg => ("SVG drawing", "svg"),
            Self::ExportSheetPng | Self::CoursePng => ("PNG picture", "png"),
            Self::ExportSheetPdf | Self::CoursePdf | Self::ReportPdf | Self::TaskSheetPdf => {
                ("PDF document", "pdf")
            }
            Self::CamDxf(_) => ("DXF drawing", "dxf"),
        }
    }
}
