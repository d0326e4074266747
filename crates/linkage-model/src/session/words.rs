//! Refusals in the user's words and language: the links by their points, lengths in
//! the scene's unit, the crank's angle in degrees. The solver's refusals are worded
//! by [`linkage_diagram::refusal`] (one wording for the app, its model and the
//! sheets); the model's own notices from this crate's catalogue
//! (`locales/notices.yml`) through [`mw!`]. What the solver keeps as data (a dyad's
//! kind, its assembly margin, link indices) stays out of what the user reads.

use linkage::LinkageError;
use linkage::error::RunWarning;
use linkage::scene::LengthUnit;
pub use linkage_diagram::numbers::significant;
use linkage_diagram::refusal;
pub use linkage_diagram::refusal::length;
use linkage_diagram::words::Lang;

// The notices' catalogue (locales/notices.yml), compiled in here; English where a
// key lacks a language. Its global locale is not used: every call names its language.
rust_i18n::i18n!("locales", fallback = "en");

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

/// The notices' catalogue text for `key` in `lang`, with `%{name}` replaced by
/// `name = value` (any `Display`).
macro_rules! mw {
    ($lang:expr, $key:literal) => {
        $crate::session::words::text($lang, $key)
    };
    ($lang:expr, $key:literal, $($name:ident = $value:expr),+ $(,)?) => {
        $crate::session::words::text_with(
            $lang,
            $key,
            &[$(stringify!($name)),+],
            &[$(($value).to_string()),+],
        )
    };
}
pub(crate) use mw;

/// A length unit as shown.
pub fn unit_label_of(unit: LengthUnit) -> &'static str {
    linkage_diagram::numbers::unit_symbol(unit)
}

/// A solver's error as the user reads it, in `lang`: an assembly failure with the
/// distances that do not fit at the crank's angle and where the crank can go; a
/// run refused with the app's controls to change.
pub fn error(e: &LinkageError, unit: LengthUnit, lang: Lang) -> String {
    refusal::error(lang, e, unit)
}

/// A warning about a finished run, in the app's words.
pub fn run_warning(w: &RunWarning, lang: Lang) -> String {
    refusal::run_warning(lang, w)
}

#[cfg(test)]
mod tests {
    use linkage::dynamics::{Method, Settings, simulate};
    use linkage::{Kinematics, Mechanism};

    use super::*;

    /// The gravity flipper with its spring a thousand times stiffer than shipped.
    fn stiff_flipper() -> Kinematics {
        let b = crate::catalog::BUILTIN_SCENES
            .iter()
            .find(|b| b.key == "gravity_flipper")
            .expect("shipped");
        let text = b.text.replace("k_n_per_m: 1500.0", "k_n_per_m: 1e7");
        Kinematics::new(Mechanism::from_ron(&text).expect("parses")).expect("builds")
    }

    /// A fixed RK4 step beyond the stiff spring's stability limit, and an adaptive
    /// run whose cost the stiffness sets: the user reads the app's integrator menu,
    /// never a command-line option.
    #[test]
    fn a_run_refused_or_warned_for_its_stiffness_names_the_apps_controls() {
        let k = stiff_flipper();
        let mut fixed = Settings::new(Method::Rk4);
        (fixed.step, fixed.t_end) = (5e-3, 0.5);
        let refused = simulate(&k, &fixed).expect_err("beyond the limit");
        let words = error(&refused, LengthUnit::Millimetre, Lang::English);
        assert!(
            words.contains("“implicit” in the integrator menu") && !words.contains("--"),
            "{words}"
        );
        let mut loose = Settings::new(Method::Dop853);
        (loose.rtol, loose.atol) = (1e-3, 1e-3);
        let run = simulate(&k, &loose).expect("runs");
        let warned: Vec<String> = run
            .stats
            .warnings
            .iter()
            .map(|w| run_warning(w, Lang::English))
            .collect();
        assert!(!warned.is_empty(), "no warning");
        for w in warned {
            assert!(w.contains("integrator menu") && !w.contains("--"), "{w}");
        }
    }

    /// The `mw!` keys of every source under `src/`.
    fn keys_used() -> std::collections::BTreeSet<String> {
        let src = concat!(env!("CARGO_MANIFEST_DIR"), "/src");
        linkage_diagram::words::catalogue_keys_used(std::path::Path::new(src), "mw!(")
    }

    #[test]
    fn every_notice_key_is_in_both_languages_and_used_and_every_key_used_is_there() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/locales/notices.yml");
        let text = std::fs::read_to_string(path).expect("the catalogue");
        let cat = linkage_diagram::words::catalogue_entries(&text);
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
        let keys: std::collections::BTreeSet<String> = cat.keys().cloned().collect();
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
}
