//! Where the user's choice of language is kept between runs: the browser's local
//! storage for the web demo, a one-line file in the user's configuration folder
//! (`$XDG_CONFIG_HOME/linkage-lab/language`, else `~/.config/…`) for the desktop
//! app. A preference, not scene data: a scene file never carries it; a share link
//! may (`lang=zh-CN`), which the page follows on opening.

use crate::i18n::Language;

/// The language the app starts in: the remembered choice, else the system's or the
/// browser's.
pub fn at_start() -> Language {
    remembered().unwrap_or_else(Language::of_system)
}

/// The language remembered from an earlier run, if any.
#[cfg(not(target_arch = "wasm32"))]
pub fn remembered() -> Option<Language> {
    let text = std::fs::read_to_string(file()?).ok()?;
    Some(Language::from_tag(&text))
}

/// Keeps `language` for the next run (a failure is logged: the choice then lasts
/// this run only).
#[cfg(not(target_arch = "wasm32"))]
pub fn remember(language: Language) {
    let Some(path) = file() else {
        return;
    };
    let written = path
        .parent()
        .map_or(Ok(()), std::fs::create_dir_all)
        .and_then(|()| std::fs::write(&path, language.code()));
    if let Err(e) = written {
        log::warn!(
            "the language chosen is not remembered ({}): {e}",
            path.display()
        );
    }
}

/// The desktop app's preference file.
#[cfg(not(target_arch = "wasm32"))]
fn file() -> Option<std::path::PathBuf> {
    let config = std::env::var_os("XDG_CONFIG_HOME")
        .filter(|d| !d.is_empty())
        .map(std::path::PathBuf::from)
        .or_else(|| {
            std::env::var_os("HOME").map(|h| std::path::PathBuf::from(h).join(".config"))
        })?;
    Some(config.join("linkage-lab").join("language"))
}

/// The local-storage key of the language chosen.
#[cfg(target_arch = "wasm32")]
const KEY: &str = "linkage-lab.language";

/// The language remembered from an earlier visit, if any.
#[cfg(target_arch = "wasm32")]
pub fn remembered() -> Option<Language> {
    let storage = web_sys::window()?.local_storage().ok().flatten()?;
    storage
        .get_item(KEY)
        .ok()
        .flatten()
        .map(|t| Language::from_tag(&t))
}

/// Keeps `language` for the next visit.
#[cfg(target_arch = "wasm32")]
pub fn remember(language: Language) {
    if let Some(storage) = web_sys::window().and_then(|w| w.local_storage().ok().flatten()) {
        let _ = storage.set_item(KEY, language.code());
    }
}

/// The language a share link asks for (`lang=zh-CN` in its fragment), if any.
pub fn in_fragment(fragment: &str) -> Option<Language> {
    fragment
        .trim_start_matches('#')
        .split('&')
        .find_map(|pair| pair.strip_prefix("lang="))
        .map(Language::from_tag)
}

/// `fragment` without its `lang=` entry: the scene's own part, which the app
/// compares with its state.
pub fn without_language(fragment: &str) -> String {
    fragment
        .trim_start_matches('#')
        .split('&')
        .filter(|pair| !pair.starts_with("lang="))
        .collect::<Vec<_>>()
        .join("&")
}

/// The fragment's language entry for `language` (`&lang=zh-CN`), empty for English,
/// the default.
pub fn fragment_entry(language: Language) -> String {
    match language {
        Language::English => String::new(),
        other => format!("&lang={}", other.code()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_link_carries_the_language_beside_the_scene() {
        let f = format!(
            "#scene=die_cutter&input=42.000{}",
            fragment_entry(Language::Chinese)
        );
        assert_eq!(in_fragment(&f), Some(Language::Chinese));
        assert_eq!(without_language(&f), "scene=die_cutter&input=42.000");
        assert_eq!(in_fragment("#scene=die_cutter"), None);
        assert_eq!(fragment_entry(Language::English), "");
    }
}
