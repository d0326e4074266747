//! The sheets' words in the reader's language, English or Simplified Chinese, from
//! one catalogue (`locales/sheets.yml`) that rust-i18n compiles in, as the app's
//! own catalogue is; and the solver's data worded for a reader: a group by its
//! links and joint, a force stage by its links' numbers, a term's direction, how a
//! stage treats a force. The app words the same data through these functions, so a
//! sheet says what the app said.

use std::collections::{BTreeMap, BTreeSet};

use linkage::Mechanism;
use linkage::dyad::{DyadKind, DyadLabel, GroupLabel};
use linkage::force_polygon::{Stage, StagePolygon};
use linkage::polygon::{Quantity, TermDirection};

use crate::force_figure::{RowStatus, Sense, stage_numbers};

// The sheets' catalogue (locales/sheets.yml), compiled in here; English where a key
// lacks a language. Its global locale is not used: every call names its language.
rust_i18n::i18n!("locales", fallback = "en");

/// A language a sheet is written in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Lang {
    /// English.
    #[default]
    English,
    /// Simplified Chinese (简体中文).
    Chinese,
}

impl Lang {
    /// Every language.
    pub const ALL: [Self; 2] = [Self::English, Self::Chinese];

    /// The BCP 47 tag: the catalogue's locale and a PDF's language.
    pub fn code(self) -> &'static str {
        match self {
            Self::English => "en",
            Self::Chinese => "zh-CN",
        }
    }

    /// The language of a tag ("zh-CN", "zh", "zh_CN.UTF-8", "en"): Chinese for any
    /// Chinese, English otherwise.
    pub fn from_tag(tag: &str) -> Self {
        let lower = tag.trim().to_ascii_lowercase();
        if lower == "zh" || lower.starts_with("zh-") || lower.starts_with("zh_") {
            Self::Chinese
        } else {
            Self::English
        }
    }
}

/// The catalogue's text for `key` in `lang`.
#[doc(hidden)]
pub fn text(lang: Lang, key: &str) -> String {
    _rust_i18n_translate(lang.code(), key).into_owned()
}

/// [`text`] with each `%{name}` replaced by its value.
#[doc(hidden)]
pub fn text_with(lang: Lang, key: &str, names: &[&str], values: &[String]) -> String {
    rust_i18n::replace_patterns(&text(lang, key), names, values)
}

/// The catalogue's text for `key` in `lang`, with `%{name}` replaced by
/// `name = value` (any `Display`).
macro_rules! sw {
    ($lang:expr, $key:literal) => {
        $crate::words::text($lang, $key)
    };
    ($lang:expr, $key:literal, $($name:ident = $value:expr),+ $(,)?) => {
        $crate::words::text_with(
            $lang,
            $key,
            &[$(stringify!($name)),+],
            &[$(($value).to_string()),+],
        )
    };
}
pub(crate) use sw;

/// A group as the reader knows it: "coupler and rocker, joined at C" (连杆 与 摇杆，
/// 在 C 处铰接), a cam's follower, or its number.
pub fn group(lang: Lang, label: &GroupLabel) -> String {
    match label {
        GroupLabel::Dyad(d) => dyad(lang, d),
        GroupLabel::Numbered(n) => sw!(lang, "group.numbered", n = n),
    }
}

/// A dyad by its links and inner joint.
pub fn dyad(lang: Lang, d: &DyadLabel) -> String {
    let [a, b] = &d.links;
    if d.kind == DyadKind::CamFollower {
        sw!(lang, "group.follower", a = a, joint = d.inner_point)
    } else {
        sw!(lang, "group.dyad", a = a, b = b, joint = d.inner_point)
    }
}

/// A force polygon's stage: its group and its links' numbers, or the crank.
pub fn stage_title(lang: Lang, stage: &StagePolygon, m: &Mechanism) -> String {
    let numbers = stage_numbers(stage, m);
    // A Chinese list takes the enumeration comma: 构件 3、4.
    let numbers = match lang {
        Lang::English => numbers,
        Lang::Chinese => numbers.replace(", ", "、"),
    };
    match &stage.stage {
        Stage::Group { dyad: d, .. } if d.kind != DyadKind::CamFollower => {
            sw!(
                lang,
                "group.stage",
                group = dyad(lang, d),
                numbers = numbers
            )
        }
        // A cam's follower is one link.
        Stage::Group { dyad: d, .. } => {
            sw!(
                lang,
                "group.stage_one",
                group = dyad(lang, d),
                number = numbers
            )
        }
        Stage::Crank { link } => sw!(
            lang,
            "group.stage_one",
            group = m.links[*link].name,
            number = numbers
        ),
    }
}

/// A term's direction as a table states it: "perp CD" (⊥CD), "C to D" (C→D).
pub fn direction(lang: Lang, d: &TermDirection) -> String {
    match d {
        TermDirection::Towards { from, to } => {
            sw!(lang, "direction.towards", from = from, to = to)
        }
        TermDirection::Perpendicular { a, b } => {
            sw!(lang, "direction.perpendicular", a = a, b = b)
        }
        TermDirection::Known => sw!(lang, "direction.known"),
        TermDirection::GuidePoint { guide, point } => {
            sw!(lang, "direction.guide_point", guide = guide, point = point)
        }
        TermDirection::Coriolis => sw!(lang, "direction.coriolis"),
        TermDirection::AlongGuide => sw!(lang, "direction.along_guide"),
    }
}

/// How a force polygon's stage treats a force: known, direction known, solved.
pub fn row_status(lang: Lang, status: RowStatus) -> String {
    match status {
        RowStatus::Known => sw!(lang, "forces.known"),
        RowStatus::DirectionKnown => sw!(lang, "forces.direction_known"),
        RowStatus::Solved => sw!(lang, "forces.solved"),
    }
}

/// A couple's sense of turning.
pub fn sense(lang: Lang, sense: Sense) -> String {
    match sense {
        Sense::None => sw!(lang, "forces.no_sense"),
        Sense::CounterClockwise => sw!(lang, "forces.counter_clockwise"),
        Sense::Clockwise => sw!(lang, "forces.clockwise"),
    }
}

/// A polygon's title: "Velocity polygon" (速度多边形).
pub fn polygon_title(lang: Lang, q: Quantity) -> String {
    match q {
        Quantity::Velocity => sw!(lang, "sheet.velocity_polygon"),
        Quantity::Acceleration => sw!(lang, "sheet.acceleration_polygon"),
    }
}

/// A cam joint's sheet title: "Die cutter: cam on crank, follower bell crank".
pub fn cam_joint_title(lang: Lang, scene: &str, cam: &str, follower: &str) -> String {
    sw!(
        lang,
        "cam.joint_title",
        scene = scene,
        cam = cam,
        follower = follower
    )
}

/// Whether a term's magnitude or direction was known: "known" or "solved".
pub fn known(lang: Lang, k: bool) -> String {
    if k {
        sw!(lang, "table.is_known")
    } else {
        sw!(lang, "table.is_solved")
    }
}

/// `key -> {locale -> text}` of a catalogue file in rust-i18n's `_version: 2`
/// layout (a key at the margin, its languages indented under it): what the
/// catalogue tests of this crate and of the app read.
#[doc(hidden)]
pub fn catalogue_entries(text: &str) -> BTreeMap<String, BTreeMap<String, String>> {
    let mut out: BTreeMap<String, BTreeMap<String, String>> = BTreeMap::new();
    let mut key = None;
    for line in text.lines() {
        if line.trim_start().starts_with('#') || line.trim().is_empty() {
            continue;
        }
        if !line.starts_with(' ') {
            let k = line.trim_end_matches(':').to_string();
            key = (k != "_version: 2").then_some(k);
            continue;
        }
        let (Some(k), Some((locale, value))) = (&key, line.trim().split_once(": ")) else {
            continue;
        };
        out.entry(k.clone())
            .or_default()
            .insert(locale.to_string(), value.trim_matches('"').to_string());
    }
    out
}

/// The keys a catalogue macro (`call`: "sw!(", "mw!(") is called with in every file
/// under `src`, each the first literal after the call: what the catalogue tests of
/// this crate and of the model check their catalogues against.
#[doc(hidden)]
pub fn catalogue_keys_used(src: &std::path::Path, call: &str) -> BTreeSet<String> {
    let mut used = BTreeSet::new();
    let mut dirs = vec![src.to_path_buf()];
    while let Some(dir) = dirs.pop() {
        let Ok(entries) = std::fs::read_dir(dir) else {
            continue;
        };
        for path in entries.filter_map(|e| e.ok().map(|e| e.path())) {
            if path.is_dir() {
                dirs.push(path);
                continue;
            }
            let text = std::fs::read_to_string(&path).unwrap_or_default();
            for (at, m) in text.match_indices(call) {
                // Not the pattern's own text in a test.
                if text[..at].ends_with('"') {
                    continue;
                }
                let rest = &text[at + m.len()..];
                let Some(start) = rest.find('"') else {
                    continue;
                };
                let rest = &rest[start + 1..];
                if let Some(end) = rest.find('"') {
                    used.insert(rest[..end].to_string());
                }
            }
        }
    }
    used
}

/// The scene files' own keys and the notations a Chinese text keeps as written
/// (units, a value that is no number).
const KEPT_IN_CHINESE: [&str; 23] = [
    "NaN",
    "inf",
    "rad",
    "ground",
    "true",
    "branches",
    "models",
    "Kinetostatics",
    "guess",
    "angle",
    "Left",
    "Right",
    "Along",
    "Against",
    "rtol",
    "atol",
    "UTF",
    "RRR",
    "RRP",
    "RPR",
    "PRP",
    "max",
    "min",
];

/// The English words of a Chinese `text` (runs of three or more ASCII letters)
/// outside `%{…}` placeholders, the scene files' keys and notations, and the
/// user's `names` (a link or point as named in the scene): what the tests of the
/// Chinese words look for.
#[doc(hidden)]
pub fn english_words(text: &str, names: &[&str]) -> Vec<String> {
    let named = |w: &str| {
        names.iter().any(|n| {
            n.split(|c: char| !c.is_ascii_alphabetic())
                .any(|part| part == w)
        })
    };
    let mut out = Vec::new();
    let mut word = String::new();
    let mut depth = 0;
    for c in text.chars().chain([' ']) {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            c if depth == 0 && c.is_ascii_alphabetic() => {
                word.push(c);
                continue;
            }
            _ => {}
        }
        if word.len() >= 3 && !KEPT_IN_CHINESE.contains(&word.as_str()) && !named(&word) {
            out.push(word.clone());
        }
        word.clear();
    }
    out
}

#[cfg(test)]
mod tests {
    use std::collections::{BTreeMap, BTreeSet};

    use super::*;

    const ROOT: &str = env!("CARGO_MANIFEST_DIR");

    /// `key -> {locale -> text}` of every catalogue file (the sheets' and the
    /// refusals').
    fn catalogue() -> BTreeMap<String, BTreeMap<String, String>> {
        let mut out = BTreeMap::new();
        for file in ["sheets.yml", "refusals.yml"] {
            let text =
                std::fs::read_to_string(format!("{ROOT}/locales/{file}")).expect("the catalogue");
            out.extend(catalogue_entries(&text));
        }
        out
    }

    /// The keys `sw!` is called with in the crate's sources.
    fn keys_used() -> BTreeSet<String> {
        catalogue_keys_used(std::path::Path::new(&format!("{ROOT}/src")), "sw!(")
    }

    #[test]
    fn every_key_is_in_both_languages_and_used_and_every_key_used_is_there() {
        let cat = catalogue();
        for (key, texts) in &cat {
            for lang in Lang::ALL {
                assert!(
                    texts.get(lang.code()).is_some_and(|t| !t.is_empty()),
                    "{key} has no {} text",
                    lang.code()
                );
            }
        }
        let used = keys_used();
        let keys: BTreeSet<String> = cat.keys().cloned().collect();
        let missing: Vec<_> = used.difference(&keys).collect();
        let unused: Vec<_> = keys.difference(&used).collect();
        assert!(
            missing.is_empty(),
            "used but not in the catalogue: {missing:?}"
        );
        assert!(
            unused.is_empty(),
            "in the catalogue but not used: {unused:?}"
        );
    }

    #[test]
    fn a_key_speaks_its_language_with_its_values() {
        let d = TermDirection::Perpendicular {
            a: "C".into(),
            b: "D".into(),
        };
        assert_eq!(direction(Lang::English, &d), "perp CD");
        assert_eq!(direction(Lang::Chinese, &d), "⊥CD");
        assert_eq!(Lang::from_tag("zh_CN.UTF-8"), Lang::Chinese);
        assert_eq!(Lang::from_tag("en-GB"), Lang::English);
    }

    /// Every character of the catalogue is drawn by the sheets' faces (the app's
    /// Latin face and the Chinese subset): none falls to a missing glyph's box.
    #[cfg(feature = "png")]
    #[test]
    fn every_character_of_the_catalogue_has_a_face() {
        let texts: String = catalogue()
            .values()
            .flat_map(|t| t.values())
            .enumerate()
            .map(|(i, t)| {
                let y = 20 * (i + 1);
                let t = crate::svg_draw::escape(t);
                format!("<text x=\"5\" y=\"{y}\" font-size=\"12\">{t}</text>")
            })
            .collect();
        let svg = format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100\" height=\"40\">{texts}</svg>"
        );
        let undrawn =
            crate::png::undrawn_characters(&svg, epaint_default_fonts::UBUNTU_LIGHT, "Ubuntu")
                .expect("parses");
        assert!(undrawn.is_empty(), "no face draws {undrawn:?}");
    }
}
