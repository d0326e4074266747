//! What the figure tests share: every scene file and inputs over its range.
#![allow(dead_code)]

use linkage::force_polygon::force_polygons;
use linkage::instant_centres::instant_centres;
use linkage::kinetostatics::Kinetostatics;
use linkage::polygon::polygons;
use linkage::{Kinematics, Mechanism};
use linkage_diagram::pages::Sheet;
use linkage_diagram::svg::{Parts, Position, sheet};
use linkage_diagram::words::Lang;

/// Every scene file in `assets/scenes` (read from the directory), by file name.
pub fn scenes() -> Vec<(String, Mechanism)> {
    let dir = format!("{}/../../assets/scenes", env!("CARGO_MANIFEST_DIR"));
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("scene directory")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "ron"))
        .collect();
    files.sort();
    assert!(files.len() >= 6, "only {} scenes in {dir}", files.len());
    files
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).expect("readable");
            let m = Mechanism::from_ron(&text).unwrap_or_else(|e| panic!("{p:?}: {e}"));
            (
                p.file_name().expect("name").to_string_lossy().into_owned(),
                m,
            )
        })
        .collect()
}

/// `n` inputs over the scene's sweep range (a full turn or the assembly interval).
pub fn inputs(k: &Kinematics, n: usize) -> Vec<f64> {
    let ([a, b], full) = linkage::sweep::sweep_range(k).expect("assembles");
    let div = if full { n } else { n - 1 };
    (0..n)
        .map(|i| a + (b - a) * i as f64 / div as f64)
        .collect()
}

/// Every scene file and every example in `docs/examples` (each must parse), by path.
pub fn scenes_and_examples() -> Vec<(String, Mechanism)> {
    let mut scenes = scenes();
    let examples = format!("{}/../../docs/examples", env!("CARGO_MANIFEST_DIR"));
    let mut files: Vec<_> = std::fs::read_dir(&examples)
        .expect("examples")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "ron"))
        .collect();
    files.sort();
    for p in files {
        let text = std::fs::read_to_string(&p).expect("readable");
        let m = Mechanism::from_ron(&text).unwrap_or_else(|e| panic!("{p:?}: {e}"));
        scenes.push((p.display().to_string(), m));
    }
    scenes
}

/// The position sheet at input `x` with every part: the pose with its instant
/// centres, the polygons and tables, and the force polygons where the scene has
/// force data; `None` where the position does not solve.
pub fn full_sheet(k: &mut Kinematics, x: f64, lang: Lang) -> Option<Sheet> {
    let forces = Kinetostatics::new(k)
        .and_then(|mut ks| force_polygons(k, &mut ks, x))
        .ok();
    let s = k.solve(x).ok()?;
    let equations = polygons(k, &s);
    let centres = instant_centres(k.mechanism(), &s);
    let position = Position {
        mechanism: k.mechanism(),
        solution: &s,
        equations: &equations,
        centres: Some(&centres),
        forces: forces.as_ref(),
    };
    let parts = Parts {
        centres: true,
        forces: true,
        ..Parts::default()
    };
    Some(sheet(&position, parts, lang))
}
