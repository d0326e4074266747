//! A synthesis tab's design as the app shows it: its table (quantity, value in
//! words), its figure and the scene it opens as; and the small helpers every tab's
//! table is written with. A leaf of the synthesis modules.

use linkage::SceneFile;

/// A design: its table (quantity, value in words) and its scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Design {
    /// What the design is, row by row.
    pub table: Vec<(String, String)>,
    /// What to draw beside the table.
    pub figure: Figure,
    /// The scene it opens as.
    pub scene: SceneFile,
}

/// A figure of a design.
#[derive(Clone, Debug, PartialEq)]
pub enum Figure {
    /// None.
    None,
    /// A function generator's structural error: `[crank deg, error deg]`.
    ErrorCurve(Vec<[f64; 2]>),
    /// A motion generator's construction.
    Construction(Construction),
}

/// A motion generator's construction, mm.
#[derive(Clone, Debug, PartialEq)]
pub struct Construction {
    /// Each position: the body's reference point and its angle, rad.
    pub positions: Vec<([f64; 2], f64)>,
    /// The poles of the pairs of positions that turn.
    pub poles: Vec<[f64; 2]>,
    /// Segments of the centre-point curve(s).
    pub curve: Vec<[[f64; 2]; 2]>,
    /// The Burmester points (five positions).
    pub burmester: Vec<[f64; 2]>,
    /// The fixed pivots.
    pub fixed: [[f64; 2]; 2],
    /// The moving pivots in the first position.
    pub moving: [[f64; 2]; 2],
}

/// A length in m as the tables write it: mm to 1 µm.
pub(crate) fn mm(m: f64) -> String {
    format!("{:.3} mm", m * 1e3)
}

/// An angle in rad as the tables write it: degrees to 0.001°.
pub(crate) fn deg(rad: f64) -> String {
    format!("{:.3}°", rad.to_degrees())
}

/// One row of a table: the quantity and its value in words.
pub(crate) fn row(what: &str, value: String) -> (String, String) {
    (what.to_owned(), value)
}

/// Rows of `width` numbers, as the CLI reads its files (a header and `#` comments
/// skipped): a targets file pasted into the app reads as it does there.
pub(crate) fn numbers(text: &str, width: usize) -> Result<Vec<Vec<f64>>, String> {
    linkage::synthesis::rows::read_rows(text, width).map_err(|e| e.to_string())
}
