//! How the app starts: the desktop app's command line (clap), what it asks for, and
//! the one line it prints when there is no display to open a window on.

use std::path::PathBuf;

/// What the app opens with and how it runs.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StartOptions {
    /// Close after this many frames and print the mean CPU time per frame
    /// (headless smoke runs and measurements).
    pub exit_after_frames: Option<u64>,
    /// Start with the animation running.
    pub play: bool,
    /// Open this shipped scene instead of the default.
    pub scene: Option<String>,
    /// Open this scene file.
    pub file: Option<PathBuf>,
    /// The language of the app's words (English unless told: the command line, the
    /// page and the remembered choice tell it).
    pub language: crate::i18n::Language,
    /// Whether a language chosen in the app is kept for the next run (the desktop
    /// app and the web demo; not the tests, which must not write the user's files).
    pub remember_choices: bool,
}

/// Linkage Lab: planar linkages for machine theory and design (the desktop app).
#[cfg(not(target_arch = "wasm32"))]
#[derive(clap::Parser, Debug)]
#[command(name = "linkage-lab", version, about, long_about = None)]
struct Args {
    /// A scene file to open (RON, as saved by the app or written by hand).
    file: Option<PathBuf>,
    /// Open a shipped scene instead of the default.
    #[arg(long, conflicts_with = "file", value_parser = shipped_scene)]
    scene: Option<String>,
    /// Start with the animation running.
    #[arg(long)]
    play: bool,
    /// Close after this many frames and print the mean CPU time per frame.
    #[arg(long, value_name = "N")]
    exit_after_frames: Option<u64>,
    /// The language of the app's words: en or zh (English, 简体中文). Without it,
    /// the one chosen in the app last time, else the system's.
    #[arg(long, value_name = "LANG")]
    lang: Option<String>,
}

/// A shipped scene's key, or why not with the keys there are.
#[cfg(not(target_arch = "wasm32"))]
fn shipped_scene(key: &str) -> Result<String, String> {
    let keys: Vec<&str> = crate::catalog::BUILTIN_SCENES
        .iter()
        .map(|s| s.key)
        .collect();
    if keys.contains(&key) {
        Ok(key.to_string())
    } else {
        Err(format!(
            "no shipped scene `{key}`: one of {}",
            keys.join(", ")
        ))
    }
}

#[cfg(not(target_arch = "wasm32"))]
impl StartOptions {
    /// Reads the command line: `--help` and `--version` print and exit 0; an unknown
    /// argument or a bad value prints why and exits with status 2.
    pub fn from_command_line() -> Self {
        Self::from(<Args as clap::Parser>::parse())
    }

    /// Reads `args` (the program's name first), or the message clap would print.
    ///
    /// # Errors
    /// An unknown argument, a bad value, or `--help`/`--version` (whose text is the
    /// error's, as clap has it).
    pub fn try_from_args<I, T>(args: I) -> Result<Self, clap::Error>
    where
        I: IntoIterator<Item = T>,
        T: Into<std::ffi::OsString> + Clone,
    {
        <Args as clap::Parser>::try_parse_from(args).map(Self::from)
    }
}

#[cfg(not(target_arch = "wasm32"))]
impl From<Args> for StartOptions {
    fn from(a: Args) -> Self {
        Self {
            exit_after_frames: a.exit_after_frames,
            play: a.play,
            scene: a.scene,
            file: a.file,
            language: a.lang.as_deref().map_or_else(
                crate::language_pref::at_start,
                crate::i18n::Language::from_tag,
            ),
            remember_choices: true,
        }
    }
}

/// Why no window can open here, in one line, where that can be known before trying:
/// on Linux and the BSDs a window needs a display server named by `DISPLAY` (X11)
/// or `WAYLAND_DISPLAY` (Wayland). `None` where one is named (or on other systems).
pub fn no_display(display: Option<&str>, wayland: Option<&str>) -> Option<String> {
    let named = |v: Option<&str>| v.is_some_and(|v| !v.trim().is_empty());
    let unix_desktop = cfg!(all(unix, not(target_os = "macos"), not(target_os = "ios")));
    (unix_desktop && !named(display) && !named(wayland)).then(|| {
        "linkage-lab: no display to open a window on: neither DISPLAY (X11) nor WAYLAND_DISPLAY (Wayland) is set; run it in a desktop session, or headless under xvfb-run".to_string()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_display_is_said_in_one_line_naming_both_variables() {
        let why = no_display(None, Some("  ")).expect("none set");
        assert!(!why.contains('\n') && why.contains("DISPLAY") && why.contains("WAYLAND_DISPLAY"));
        assert!(no_display(Some(":0"), None).is_none());
        assert!(no_display(None, Some("wayland-0")).is_none());
    }

    #[cfg(not(target_arch = "wasm32"))]
    #[test]
    fn the_command_line_takes_a_file_or_a_shipped_scene_and_refuses_the_rest() {
        let o = StartOptions::try_from_args(["linkage-lab", "my.ron", "--play"]).expect("valid");
        assert_eq!(o.file, Some(PathBuf::from("my.ron")));
        assert!(o.play);
        let o =
            StartOptions::try_from_args(["linkage-lab", "--scene", "quick_return"]).expect("valid");
        assert_eq!(o.scene.as_deref(), Some("quick_return"));
        for bad in [
            vec!["linkage-lab", "--frobnicate"],
            vec!["linkage-lab", "--scene", "nope"],
            vec!["linkage-lab", "a.ron", "--scene", "quick_return"],
            vec!["linkage-lab", "a.ron", "b.ron"],
        ] {
            let e = StartOptions::try_from_args(&bad).expect_err("refused");
            assert_eq!(e.exit_code(), 2, "{bad:?}: {e}");
        }
        let help = StartOptions::try_from_args(["linkage-lab", "--help"]).expect_err("prints");
        assert_eq!(help.exit_code(), 0);
        assert!(help.to_string().contains("--scene"));
    }
}
