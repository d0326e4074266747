//! Typeset labels: a symbol as runs of base, subscript and superscript text, so
//! that each place that shows it (egui's text layout, SVG `tspan`s) sets it as a
//! textbook does — v with subscript CB — instead of printing `v_CB`.

use linkage::polygon::{Symbol, VectorEquation};

/// Where a run of text sits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Script {
    /// On the baseline, full size.
    Base,
    /// Lowered and smaller.
    Sub,
    /// Raised and smaller.
    Super,
}

/// One run of a label.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Run {
    /// Its text.
    pub text: String,
    /// Where it sits.
    pub script: Script,
}

/// A typeset label: runs in reading order.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Label {
    /// The runs.
    pub runs: Vec<Run>,
}

/// Size of sub- and superscripts relative to the base text.
pub const SCRIPT_SCALE: f64 = 0.7;

impl Label {
    /// A label of plain text.
    pub fn plain(text: impl Into<String>) -> Self {
        Self {
            runs: vec![Run {
                text: text.into(),
                script: Script::Base,
            }],
        }
    }

    /// Text whose subscripts the catalogue marks `_{…}` (M_{b}, α_{max}, v_{E}):
    /// each one a subscript run. A name typed with an underscore and no brace
    /// (`bell_crank`), or a brace left open, stays as written.
    pub fn marked(text: &str) -> Self {
        let mut runs = Vec::new();
        let mut push = |text: &str, script| {
            if !text.is_empty() {
                runs.push(Run {
                    text: text.to_string(),
                    script,
                });
            }
        };
        let mut rest = text;
        while let Some(at) = rest.find("_{") {
            let Some(len) = rest[at..].find('}') else {
                break;
            };
            push(&rest[..at], Script::Base);
            push(&rest[at + 2..at + len], Script::Sub);
            rest = &rest[at + len + 1..];
        }
        push(rest, Script::Base);
        Self { runs }
    }

    /// A polygon term's symbol: its letter, the points as subscript, the component
    /// (n, t, k, r) as superscript.
    pub fn of_symbol(s: &Symbol) -> Self {
        let mut runs = vec![
            Run {
                text: s.letter().to_string(),
                script: Script::Base,
            },
            Run {
                text: s.subscript(),
                script: Script::Sub,
            },
        ];
        if let Some(c) = s.superscript() {
            runs.push(Run {
                text: c.to_string(),
                script: Script::Super,
            });
        }
        Self { runs }
    }

    /// A vector equation typeset: `v_C = v_B + v_CB` with every symbol set.
    pub fn of_equation(eq: &VectorEquation) -> Self {
        let mut runs = Vec::new();
        let side = |terms: &[linkage::polygon::Term], runs: &mut Vec<Run>| {
            for (i, t) in terms.iter().enumerate() {
                if i > 0 {
                    runs.push(Run {
                        text: " + ".into(),
                        script: Script::Base,
                    });
                }
                runs.extend(Self::of_symbol(&t.symbol).runs);
            }
        };
        side(&eq.lhs, &mut runs);
        runs.push(Run {
            text: " = ".into(),
            script: Script::Base,
        });
        side(&eq.rhs, &mut runs);
        Self { runs }
    }

    /// The text without its setting (for tooltips and tests).
    pub fn text(&self) -> String {
        self.runs.iter().map(|r| r.text.as_str()).collect()
    }

    /// Width and height, in pixels at `font_px`, by an average advance of 0.58 em (a
    /// Chinese character 1 em, [`em_width`]):
    /// for places without a font engine (the SVG sheet, the CLI, the layout tests).
    /// Generous for the narrow letters of labels, so boxes measured this way hold the
    /// text set in a sans-serif face.
    pub fn approximate_size(&self, font_px: f64) -> [f64; 2] {
        let width = self
            .runs
            .iter()
            .map(|r| {
                let scale = if r.script == Script::Base {
                    1.0
                } else {
                    SCRIPT_SCALE
                };
                font_px * scale * r.text.chars().map(em_width).sum::<f64>()
            })
            .sum();
        let scripted = self.runs.iter().any(|r| r.script != Script::Base);
        [width, font_px * if scripted { 1.6 } else { 1.2 }]
    }
}

/// Whether `c` is of the Chinese face's ranges (CJK radicals to the full-width
/// forms): a square character, drawn with [`crate::png::CJK_FONT`].
pub fn is_cjk(c: char) -> bool {
    ('\u{2E80}'..='\u{FFEF}').contains(&c)
}

/// A character's approximate advance in ems: a CJK character (and a full-width
/// form) is a square, a Latin one a little over half of it.
pub fn em_width(c: char) -> f64 {
    if is_cjk(c) { 1.0 } else { 0.58 }
}

#[cfg(test)]
mod tests {
    use super::*;
    use linkage::polygon::{Component, Quantity};

    #[test]
    fn a_symbol_sets_its_points_low_and_its_component_high() {
        let s = Symbol {
            quantity: Quantity::Acceleration,
            point: "C".into(),
            relative_to: Some("B".into()),
            component: Component::Normal,
        };
        let l = Label::of_symbol(&s);
        let scripts: Vec<_> = l.runs.iter().map(|r| (r.text.as_str(), r.script)).collect();
        assert_eq!(
            scripts,
            [
                ("a", Script::Base),
                ("CB", Script::Sub),
                ("n", Script::Super)
            ]
        );
        assert_eq!(l.text(), "aCBn");
    }
}
