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

/// The file `assets/FOLDER/KEY.ron`, built in.
macro_rules! embedded {
    ($folder:literal, $key:literal) => {
        BuiltinScene {
            key: $key,
            text: include_str!(concat!("../../../assets/", $folder, "/", $key, ".ron")),
        }
    };
}

/// Every scene in `assets/scenes`: the three source machines first, then the
/// as-printed die cutter and the teaching classics. A test checks that this list and
/// the directory agree.
pub const BUILTIN_SCENES: &[BuiltinScene] = &[
    embedded!("scenes", "paper_cup_feed"),
    embedded!("scenes", "paper_cup_cam_feed"),
    embedded!("scenes", "die_cutter"),
    embedded!("scenes", "gravity_flipper"),
    embedded!("scenes", "die_cutter_as_printed"),
    embedded!("scenes", "slider_crank"),
    embedded!("scenes", "quick_return"),
];

/// The templates in `assets/templates` a new scene starts from, in the menu's order.
/// A test checks that this list and the directory agree.
pub const TEMPLATES: &[BuiltinScene] = &[
    embedded!("templates", "four_bar"),
    embedded!("templates", "slider_crank"),
    embedded!("templates", "inverted_slider_crank"),
    embedded!("templates", "watt_six_bar"),
    embedded!("templates", "stephenson_six_bar"),
];

/// The gear trains in `assets/trains`, for the gear lab's train view: the source
/// machines' drives first, then the planetary set and the differential. A test
/// checks that this list and the directory agree.
pub const TRAINS: &[BuiltinScene] = &[
    embedded!("trains", "die_cutter_drive"),
    embedded!("trains", "paper_cup_feed_drive"),
    embedded!("trains", "planetary_ring_fixed"),
    embedded!("trains", "differential"),
];

/// The exercises in `assets/exercises` a student opens from *New… → Exercises*. A
/// test checks that this list and the directory agree.
pub const EXERCISES: &[BuiltinScene] = &[
    embedded!("exercises", "die_cutter_slider"),
    embedded!("exercises", "four_bar_instant_centres"),
    embedded!("exercises", "cam_pressure_angle"),
];

impl BuiltinScene {
    /// Its display name (the file's `name` field), or its key if the text does not
    /// parse (a test checks that every built-in one does).
    pub fn name(&self) -> String {
        linkage::SceneFile::parse(self.text).map_or_else(|_| self.key.to_string(), |s| s.name)
    }
}

/// The built-in scene with this key.
pub fn builtin(key: &str) -> Option<&'static BuiltinScene> {
    BUILTIN_SCENES.iter().find(|s| s.key == key)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn keys_on_disk(folder: &str) -> Vec<String> {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../..")
            .join(folder);
        let mut keys: Vec<String> = std::fs::read_dir(&dir)
            .expect("asset folder")
            .filter_map(|e| {
                let name = e.ok()?.file_name().into_string().ok()?;
                name.strip_suffix(".ron").map(str::to_string)
            })
            .collect();
        keys.sort();
        keys
    }

    #[test]
    fn the_catalog_lists_exactly_the_exercise_files_and_each_reads() {
        let mut listed: Vec<String> = EXERCISES.iter().map(|s| s.key.to_string()).collect();
        listed.sort();
        assert_eq!(listed, keys_on_disk("assets/exercises"));
        for e in EXERCISES {
            crate::exercise::Exercise::parse(e.text)
                .unwrap_or_else(|why| panic!("{}: {why}", e.key));
        }
    }

    #[test]
    fn the_catalog_lists_exactly_the_template_files_and_each_opens() {
        let mut listed: Vec<String> = TEMPLATES.iter().map(|s| s.key.to_string()).collect();
        listed.sort();
        assert_eq!(listed, keys_on_disk("assets/templates"));
        for t in TEMPLATES {
            let s = crate::session::Session::open_text(
                crate::session::SceneSource::File(format!("{}.ron", t.key)),
                t.text,
            )
            .unwrap_or_else(|e| panic!("{}: {e}", t.key));
            assert!(s.message().is_none(), "{}", t.key);
        }
    }

    #[test]
    fn the_catalog_lists_exactly_the_scene_files() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes");
        let mut on_disk: Vec<String> = std::fs::read_dir(&dir)
            .expect("assets/scenes")
            .filter_map(|e| {
                let name = e.ok()?.file_name().into_string().ok()?;
                name.strip_suffix(".ron").map(str::to_string)
            })
            .collect();
        let mut listed: Vec<String> = BUILTIN_SCENES.iter().map(|s| s.key.to_string()).collect();
        on_disk.sort();
        listed.sort();
        assert_eq!(listed, on_disk);
    }

    #[test]
    fn the_catalog_lists_exactly_the_train_files_and_each_solves() {
        let mut listed: Vec<String> = TRAINS.iter().map(|s| s.key.to_string()).collect();
        listed.sort();
        assert_eq!(listed, keys_on_disk("assets/trains"));
        for t in TRAINS {
            let file = linkage::gears::train_file::TrainFile::from_ron(t.text)
                .unwrap_or_else(|e| panic!("{}: {e}", t.key));
            let train =
                linkage::gears::Train::new(file).unwrap_or_else(|e| panic!("{}: {e}", t.key));
            assert!(train.solve().is_ok(), "{}", t.key);
        }
    }

    #[test]
    fn every_shipped_scene_opens_in_the_viewer() {
        for s in BUILTIN_SCENES {
            let session = crate::session::Session::open_builtin(s.key);
            assert!(session.is_ok(), "{}: {:?}", s.key, session.err());
        }
        assert!(builtin("no_such_scene").is_none());
    }
}
