//! The editable dimensions of a scene: pin-to-pin lengths, spring constants and
//! masses, read from and written back to the scene file so that a saved scene keeps
//! the user's edits.

use linkage::SceneFile;

/// One pin-to-pin distance on one link, in the scene's length unit.
#[derive(Clone, Debug, PartialEq)]
pub struct LengthParam {
    /// Index of the link in the scene.
    pub link: usize,
    /// The point that stays put (the link's first joint point).
    pub from: String,
    /// The point that moves along the line from `from` when the length changes.
    pub to: String,
    /// Label shown on the slider, e.g. `AB` or `O4-O2`.
    pub label: String,
    /// Length in the scene file as loaded (slider ranges are relative to it).
    pub original: f64,
}

impl LengthParam {
    /// The length in `scene`, scene units (`None` if the scene lost a point).
    pub fn value(&self, scene: &SceneFile) -> Option<f64> {
        let (a, b) = self.ends(scene)?;
        Some((b.0 - a.0).hypot(b.1 - a.1))
    }

    /// Slider range: a twentieth to four times the length as loaded, wide enough to
    /// reach every assembly limit of the shipped scenes.
    pub fn range(&self) -> std::ops::RangeInclusive<f64> {
        self.original * 0.05..=self.original * 4.0
    }

    /// Writes `length` (scene units) by moving `to` along the line from `from`.
    ///
    /// # Errors
    /// A length that is not finite and positive, named with the valid range.
    pub fn apply(&self, scene: &mut SceneFile, length: f64) -> Result<(), LengthError> {
        let range = self.range();
        if !(length.is_finite() && length > 0.0) {
            return Err(LengthError::NotPositive {
                label: self.label.clone(),
                value: length,
                range: [*range.start(), *range.end()],
            });
        }
        let Some(((ax, ay), (bx, by))) = self.ends(scene) else {
            return Err(LengthError::PointsGone {
                label: self.label.clone(),
            });
        };
        let old = (bx - ax).hypot(by - ay);
        let scale = length / old;
        let link = &mut scene.links[self.link];
        if let Some(p) = link.points.get_mut(&self.to) {
            *p = (ax + (bx - ax) * scale, ay + (by - ay) * scale);
        }
        Ok(())
    }

    fn ends(&self, scene: &SceneFile) -> Option<((f64, f64), (f64, f64))> {
        let link = scene.links.get(self.link)?;
        Some((*link.points.get(&self.from)?, *link.points.get(&self.to)?))
    }
}

/// The pin-to-pin lengths of every link: from each link's first joint point to each
/// of its other joint points. A joint point is one that another link shares (a pin)
/// or a slider's guide passes through; spring anchors, centroids and tool points are
/// not dimensions of the chain and get no slider.
pub fn length_params(scene: &SceneFile) -> Vec<LengthParam> {
    let shared = |name: &str, me: usize| is_joint_point(scene, name, me);
    let mut out = Vec::new();
    for (i, link) in scene.links.iter().enumerate() {
        let joints: Vec<(&String, &(f64, f64))> = link
            .points
            .iter()
            .filter(|(name, _)| shared(name, i))
            .collect();
        let Some(((base, a), rest)) = joints.split_first() else {
            continue;
        };
        for (name, b) in rest {
            let length = (b.0 - a.0).hypot(b.1 - a.1);
            if length > 0.0 && length.is_finite() {
                out.push(LengthParam {
                    link: i,
                    from: (*base).clone(),
                    to: (*name).clone(),
                    label: pair_label(base, name),
                    original: length,
                });
            }
        }
    }
    out
}

/// Whether `name` on link number `link` is a joint point: another link shares it (a
/// pin) or a slider's guide passes through it.
pub fn is_joint_point(scene: &SceneFile, name: &str, link: usize) -> bool {
    let pinned = scene
        .links
        .iter()
        .enumerate()
        .any(|(i, l)| i != link && l.points.contains_key(name));
    pinned || scene.sliders.iter().any(|s| s.through == name)
}

/// `AB` for one-letter names, `O4-O2` otherwise (so that the pair stays readable).
fn pair_label(a: &str, b: &str) -> String {
    if a.chars().count() == 1 && b.chars().count() == 1 {
        format!("{a}{b}")
    } else {
        format!("{a}-{b}")
    }
}

/// Valid range of a spring constant slider, N/m: zero (spring removed) to a hundred
/// times the scene's value (or 1e5 N/m for a scene whose spring starts at zero).
pub fn spring_range(original_n_per_m: f64) -> std::ops::RangeInclusive<f64> {
    let top = if original_n_per_m > 0.0 {
        original_n_per_m * 100.0
    } else {
        1e5
    };
    0.0..=top
}

/// Valid range of a mass slider, kg: a hundredth to ten times the scene's value.
pub fn mass_range(original_kg: f64) -> std::ops::RangeInclusive<f64> {
    original_kg * 0.01..=original_kg * 10.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalog::builtin;

    fn scene(key: &str) -> SceneFile {
        SceneFile::parse(builtin(key).expect("shipped scene").text).expect("parses")
    }

    #[test]
    fn flipper_lengths_are_its_four_bars_and_not_its_spring_anchors() {
        let s = scene("gravity_flipper");
        let labels: Vec<String> = length_params(&s).into_iter().map(|p| p.label).collect();
        assert_eq!(labels, ["AD", "AB", "BC", "DC"]);
    }

    #[test]
    fn applying_a_length_moves_only_the_far_point_along_its_line() {
        let mut s = scene("gravity_flipper");
        let p = length_params(&s)
            .into_iter()
            .find(|p| p.label == "BC")
            .expect("BC");
        p.apply(&mut s, 0.25).expect("valid");
        assert!((p.value(&s).expect("points") - 0.25).abs() < 1e-15);
        let table = &s.links[p.link];
        assert_eq!(table.points["B"], (0.0, 0.0));
        assert!((table.points["C"].0 - 0.25).abs() < 1e-15);
    }

    #[test]
    fn non_positive_or_nan_lengths_are_refused_with_the_range() {
        let mut s = scene("slider_crank");
        let p = &length_params(&s)[0];
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let why = p.apply(&mut s, bad).expect_err("refused");
            assert!(
                matches!(why, LengthError::NotPositive { range, .. } if range[0] < range[1]),
                "{why:?}"
            );
            assert!(why.to_string().contains("positive length"), "{why}");
        }
    }
}

/// Why a length cannot be set.
#[derive(Clone, Debug, PartialEq)]
pub enum LengthError {
    /// Not a positive finite number.
    NotPositive {
        /// The length's slider label.
        label: String,
        /// The value asked for.
        value: f64,
        /// The slider's range.
        range: [f64; 2],
    },
    /// The scene no longer has the length's points.
    PointsGone {
        /// The length's slider label.
        label: String,
    },
}

impl std::fmt::Display for LengthError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.words(linkage_diagram::words::Lang::English))
    }
}
