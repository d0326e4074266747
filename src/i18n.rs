//! The app's words in the user's language: English or Simplified Chinese, from one
//! catalogue (`locales/app.yml`, both languages side by side under each key), which
//! rust-i18n reads at compile time. [`tr!`] gives a key's text in the language of
//! the frame being drawn.
//!
//! Why rust-i18n: the catalogue is compiled into the binary (the browser demo
//! fetches nothing to speak), its YAML puts each key's languages together where a
//! reviewer compares them, it is small at run time (a map lookup, no parser, unlike
//! Fluent's bundles), and it runs on wasm32. Its one global locale is not used: the
//! language is this thread's (the UI thread's), set each frame from the app's state,
//! so that tests on other threads keep their own.
//!
//! The words follow the textbooks (`../shared/design/glossary_zh.md`); the polygon
//! notation and symbols stay as drawn in both languages. What the solver and the
//! model say (refusals, analyses' words) is still English.

use std::cell::Cell;

// The catalogue of the app's words (locales/app.yml), compiled in here; English
// where a key lacks a language.
rust_i18n::i18n!("locales", fallback = "en");

/// A language the app speaks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Language {
    /// English.
    #[default]
    English,
    /// Simplified Chinese (简体中文).
    Chinese,
}

impl Language {
    /// Every language, in the switch's order.
    pub const ALL: [Self; 2] = [Self::English, Self::Chinese];

    /// The catalogue's locale code (and a share link's `lang=`).
    pub fn code(self) -> &'static str {
        match self {
            Self::English => "en",
            Self::Chinese => "zh-CN",
        }
    }

    /// The language's name in itself, as the switch lists it.
    pub fn own_name(self) -> &'static str {
        match self {
            Self::English => "English",
            Self::Chinese => "中文",
        }
    }

    /// The language of a BCP 47 tag or a POSIX locale ("zh-CN", "zh-Hans",
    /// "zh_CN.UTF-8", "en-US"): Chinese for any Chinese, English otherwise.
    pub fn from_tag(tag: &str) -> Self {
        let lower = tag.trim().to_ascii_lowercase();
        if lower == "zh" || lower.starts_with("zh-") || lower.starts_with("zh_") {
            Self::Chinese
        } else {
            Self::English
        }
    }

    /// The system's language (the desktop app's first start).
    #[cfg(not(target_arch = "wasm32"))]
    pub fn of_system() -> Self {
        sys_locale::get_locale().map_or(Self::English, |tag| Self::from_tag(&tag))
    }

    /// The browser's language (the web demo's first visit).
    #[cfg(target_arch = "wasm32")]
    pub fn of_system() -> Self {
        web_sys::window()
            .and_then(|w| w.navigator().language())
            .map_or(Self::English, |tag| Self::from_tag(&tag))
    }
}

thread_local! {
    static CURRENT: Cell<Language> = const { Cell::new(Language::English) };
}

/// Sets the language [`tr!`] speaks on this thread (the UI's, each frame).
pub fn set_language(language: Language) {
    CURRENT.with(|c| c.set(language));
}

/// The language [`tr!`] speaks on this thread.
pub fn language() -> Language {
    CURRENT.with(Cell::get)
}

/// The catalogue's text for `key` in this thread's language. Not inlined: the
/// app calls it from some 300 places, and the web demo's download carries each.
#[doc(hidden)]
#[inline(never)]
pub fn text(key: &str) -> String {
    _rust_i18n_translate(language().code(), key).into_owned()
}

/// [`text`] with each `%{name}` replaced by its value.
#[doc(hidden)]
#[inline(never)]
pub fn text_with(key: &str, names: &[&str], values: &[String]) -> String {
    rust_i18n::replace_patterns(&text(key), names, values)
}

/// The catalogue's text for `key` in this thread's language, as a `String`, with
/// `%{name}` replaced by `name = value` (any `Display`).
macro_rules! tr {
    ($key:literal) => {
        $crate::i18n::text($key)
    };
    ($key:literal, $($name:ident = $value:expr),+ $(,)?) => {
        $crate::i18n::text_with(
            $key,
            &[$(stringify!($name)),+],
            &[$(($value).to_string()),+],
        )
    };
}
pub(crate) use tr;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tags_name_their_language() {
        for tag in ["zh-CN", "zh-Hans-CN", "zh_CN.UTF-8", "zh", "ZH-tw"] {
            assert_eq!(Language::from_tag(tag), Language::Chinese, "{tag}");
        }
        for tag in ["en-US", "C.UTF-8", "de_DE", "", "zhx"] {
            assert_eq!(Language::from_tag(tag), Language::English, "{tag}");
        }
    }

    #[test]
    fn a_key_speaks_the_threads_language_with_its_values() {
        set_language(Language::Chinese);
        assert_eq!(tr!("controls.play"), "播放");
        assert_eq!(tr!("controls.link_lengths", unit = "mm"), "杆长 (mm)");
        set_language(Language::English);
        assert_eq!(
            tr!("controls.link_lengths", unit = "mm"),
            "Link lengths (mm)"
        );
        // Another thread keeps its own language.
        set_language(Language::Chinese);
        let other = std::thread::spawn(|| tr!("controls.play"))
            .join()
            .expect("runs");
        assert_eq!(other, "Play");
        set_language(Language::English);
    }
}

/// The catalogue against the sources: every key in both languages, every key used
/// and every key used there; and the literals the UI shows without the catalogue,
/// file by file, held to a ratchet that only goes down.
#[cfg(test)]
mod catalogue {
    use std::collections::{BTreeMap, BTreeSet};
    use std::path::Path;

    const ROOT: &str = env!("CARGO_MANIFEST_DIR");

    /// `key -> {locale -> text}` of `locales/app.yml`.
    fn catalogue() -> BTreeMap<String, BTreeMap<String, String>> {
        let text = std::fs::read_to_string(Path::new(ROOT).join("locales/app.yml"))
            .expect("the catalogue");
        linkage_diagram::words::catalogue_entries(&text)
    }

    /// Every `.rs` file under `src/`, with its text.
    fn sources() -> Vec<(String, String)> {
        crate::test_sources::rust_sources(&["src"])
    }

    /// The keys `tr!` is called with in `text` (the key may start the next line).
    fn keys_used(text: &str) -> Vec<String> {
        text.match_indices("tr!(")
            // `tr!`, not the end of another macro's name.
            .filter(|(at, _)| {
                !text[..*at]
                    .chars()
                    .next_back()
                    .is_some_and(|c| c.is_alphanumeric() || c == '_')
            })
            .filter_map(|(at, m)| {
                let rest = text[at + m.len()..].trim_start().strip_prefix('"')?;
                rest.find('"').map(|end| rest[..end].to_string())
            })
            .collect()
    }

    #[test]
    fn every_key_is_in_both_languages_and_used_and_every_key_used_is_there() {
        let cat = catalogue();
        assert!(cat.len() > 100, "{} keys", cat.len());
        for (key, texts) in &cat {
            for locale in ["en", "zh-CN"] {
                assert!(
                    texts.get(locale).is_some_and(|t| !t.is_empty()),
                    "{key} has no {locale} text"
                );
            }
        }
        let used: BTreeSet<String> = sources()
            .iter()
            .filter(|(name, _)| !name.ends_with("i18n.rs"))
            .flat_map(|(_, text)| keys_used(text))
            .collect();
        for key in &used {
            assert!(
                cat.contains_key(key),
                "tr!(\"{key}\") is not in locales/app.yml"
            );
        }
        for key in cat.keys() {
            assert!(
                used.contains(key),
                "{key} is in the catalogue but never used"
            );
        }
    }

    /// Calls that put their string argument on screen: a literal with a word in it
    /// there bypasses the catalogue.
    const SHOWN: [&str; 27] = [
        ".button(\"",
        ".label(\"",
        ".heading(\"",
        ".strong(\"",
        ".weak(\"",
        ".small(\"",
        ".on_hover_text(\"",
        ".menu_button(\"",
        "Window::new(\"",
        "CollapsingHeader::new(\"",
        "ComboBox::from_label(\"",
        "Button::new(\"",
        ".label(format!(\"",
        ".strong(format!(\"",
        ".weak(format!(\"",
        ".heading(format!(\"",
        ".on_hover_text(format!(\"",
        "CollapsingHeader::new(format!(\"",
        "RichText::new(format!(\"",
        "status = Some(format!(\"",
        "status = Some(\"",
        // A plot's series: its name shows where the pointer hovers it.
        "Line::new(\"",
        "Points::new(\"",
        "HLine::new(\"",
        "VLine::new(\"",
        "Polygon::new(format!(\"",
        // A plot's axis title.
        "plot(key, height, \"",
    ];

    /// What is left to move into the catalogue, file by file: the UI's literals
    /// that [`SHOWN`] finds. The count may only go down (a file at 0 stays at 0);
    /// a new literal shown to the user fails here.
    const LEFT: [(&str, usize); 0] = [];

    /// Whether the literal that `rest` starts (up to its closing quote) holds a
    /// word: two letters outside `{…}` placeholders.
    fn words_in(rest: &str) -> bool {
        let mut depth = 0;
        let mut letters = 0;
        for c in rest.chars().take_while(|c| *c != '"') {
            match c {
                '{' => depth += 1,
                '}' => depth -= 1,
                c if depth == 0 && c.is_ascii_alphabetic() => letters += 1,
                _ => {}
            }
        }
        letters >= 2
    }

    fn shown_literals(text: &str) -> usize {
        let code = text.split("#[cfg(test)]").next().unwrap_or(text);
        SHOWN
            .iter()
            .map(|call| {
                code.match_indices(call)
                    .filter(|(at, m)| words_in(&code[at + m.len()..]))
                    .count()
            })
            .sum()
    }

    #[test]
    fn the_ui_shows_no_literal_beyond_what_is_left_to_translate() {
        let left: BTreeMap<&str, usize> = LEFT.into_iter().collect();
        let mut report = Vec::new();
        for (name, text) in sources() {
            let found = shown_literals(&text);
            let allowed = left.get(name.as_str()).copied().unwrap_or(0);
            if found != allowed {
                report.push(format!("(\"{name}\", {found}), // allowed {allowed}"));
            }
        }
        assert!(
            report.is_empty(),
            "literals shown without the catalogue (lower LEFT where fewer):\n{}",
            report.join("\n")
        );
    }
}
