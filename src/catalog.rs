//! The scenes shipped in `assets/scenes`, built into the binary so that the browser
//! demo has them without a file system.

/// One built-in scene: its file name (the key used in URLs) and its RON text.
#[derive(Clone, Copy, Debug)]
pub struct BuiltinScene {
    /// File name without `.ron`, e.g. `die_cutter`.
    pub key: &'static str,
    /// The scene file's text.
    pub text: &'static str,
}

macro_rules! scene {
    ($key:literal) => {
        BuiltinScene {
            key: $key,
            text: include_str!(concat!("../assets/scenes/", $key, ".ron")),
        }
    };
}

/// Every scene in `assets/scenes`: the three source machines first, then the
/// as-printed die cutter and the teaching classics. A test checks that this list and
/// the directory agree.
pub const BUILTIN_SCENES: &[BuiltinScene] = &[
    scene!("paper_cup_feed"),
    scene!("die_cutter"),
    scene!("gravity_flipper"),
    scene!("die_cutter_as_printed"),
    scene!("slider_crank"),
    scene!("quick_return"),
];

/// The built-in scene with this key.
pub fn builtin(key: &str) -> Option<&'static BuiltinScene> {
    BUILTIN_SCENES.iter().find(|s| s.key == key)
}
