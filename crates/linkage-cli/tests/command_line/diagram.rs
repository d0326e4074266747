//! `linkage diagram`: for every scene file in `assets/scenes` (read from the
//! directory), the sheet parses as SVG (usvg, resvg's parser, with the app's font),
//! keeps its text as text, holds the parts asked for, and the PNG written beside it
//! decodes at the size its resolution gives; bad arguments are refused by name.

use crate::common;

use common::{run_linkage, run_sheet, scene};

fn scene_files() -> Vec<String> {
    let dir = scene("");
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .expect("scene directory")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "ron"))
        .map(|p| p.display().to_string())
        .collect();
    files.sort();
    assert!(files.len() >= 6, "{files:?}");
    files
}

/// Texts of the `<text>` elements with their tspans joined.
fn texts(tree: &resvg::usvg::Tree) -> Vec<String> {
    fn walk(g: &resvg::usvg::Group, out: &mut Vec<String>) {
        for n in g.children() {
            match n {
                resvg::usvg::Node::Group(g) => walk(g, out),
                resvg::usvg::Node::Text(t) => {
                    out.push(t.chunks().iter().map(|c| c.text()).collect())
                }
                _ => {}
            }
        }
    }
    let mut out = Vec::new();
    walk(tree.root(), &mut out);
    out
}

/// The texts of every page.
fn texts_of(pages: &[String]) -> Vec<String> {
    assert!(!pages.is_empty(), "no page written");
    pages.iter().flat_map(|p| texts(&parse(p))).collect()
}

fn parse(svg: &str) -> resvg::usvg::Tree {
    let mut opt = resvg::usvg::Options::default();
    opt.fontdb_mut()
        .load_font_data(epaint_default_fonts::UBUNTU_LIGHT.to_vec());
    resvg::usvg::Tree::from_str(svg, &opt).expect("the sheet parses as SVG")
}

#[test]
fn every_scene_gives_a_sheet_that_parses_with_its_text_and_a_png() {
    let dir = std::env::temp_dir().join(format!("linkage-diagram-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch dir");
    for file in scene_files() {
        // A reachable input: the middle of the first range `report` gives.
        let (code, report, err) = run_linkage(&["report", &file]);
        assert_eq!(code, Some(0), "{file}: {err}");
        let report: serde_json::Value = serde_json::from_str(&report).expect("json");
        let input = if report["full_rotation"] == serde_json::Value::Bool(true) {
            30.0
        } else {
            let r = &report["assembly_range_rad"][0];
            let mid = 0.5 * (r[0].as_f64().expect("start") + r[1].as_f64().expect("end"));
            mid.to_degrees()
        };
        let png = dir.join("sheet.png");
        let (code, svg, err) = run_sheet(&[
            "diagram",
            &file,
            "--input-deg",
            &input.to_string(),
            "--what",
            "pose,velocity,acceleration,centres,table",
        ]);
        assert_eq!(code, Some(0), "{file}: {err}");
        let texts = texts_of(&svg);
        for part in ["Velocity polygon", "Acceleration polygon", " m/s"] {
            assert!(
                texts.iter().any(|t| t.contains(part)),
                "{file}: no {part:?} in {texts:?}"
            );
        }
        // Typeset symbols: v, then the subscript in its own span (vCB, not v_CB).
        assert!(
            texts.iter().any(|t| t.starts_with("v") && !t.contains('_')),
            "{file}"
        );
        let markup = texts
            .iter()
            .find(|t| t.starts_with("v_") || t.starts_with("a_") || t.contains('^'));
        assert!(
            markup.is_none(),
            "{file}: ASCII markup {markup:?} in the sheet"
        );
        // Instant centres: I with subscript.
        assert!(
            texts.iter().any(|t| t.starts_with("I1")),
            "{file}: no instant centre named"
        );
        let (code, _, err) = run_linkage(&[
            "diagram",
            &file,
            "--input-deg",
            &input.to_string(),
            "--png",
            &png.display().to_string(),
            "--dpi",
            "48",
        ]);
        assert_eq!(code, Some(0), "{file}: {err}");
        let bytes = std::fs::read(&png).expect("png written");
        assert_eq!(&bytes[1..4], b"PNG", "{file}");
        let width = u32::from_be_bytes([bytes[16], bytes[17], bytes[18], bytes[19]]);
        // A4 is 210 mm wide: 397 px at 48 dpi.
        assert!((396..=398).contains(&width), "{file}: {width} px wide");
    }
    std::fs::remove_dir_all(dir).expect("clean up");
}

#[test]
fn a_sheet_holds_only_the_parts_asked_for() {
    let file = scene("slider_crank.ron");
    let (code, svg, err) =
        run_sheet(&["diagram", &file, "--input-deg", "30", "--what", "velocity"]);
    assert_eq!(code, Some(0), "{err}");
    let texts = texts_of(&svg);
    assert!(texts.iter().any(|t| t == "Velocity polygon"));
    assert!(
        !texts
            .iter()
            .any(|t| t.contains("Acceleration") || t.contains("magnitude")),
        "{texts:?}"
    );
}

#[test]
fn bad_arguments_are_refused_by_name() {
    let file = scene("slider_crank.ron");
    for (args, says) in [
        (vec!["--input-deg", "NaN"], "--input-deg NaN is invalid"),
        (
            vec!["--input-deg", "30", "--dpi", "0"],
            "--dpi 0 is out of range: 10 to 1200",
        ),
        (
            vec!["--input-deg", "30", "--what", "polygons"],
            "invalid value 'polygons'",
        ),
    ] {
        let mut all = vec!["diagram", file.as_str()];
        all.extend(args);
        let (code, _, err) = run_linkage(&all);
        assert_ne!(code, Some(0));
        assert!(err.contains(says), "{err}");
    }
    // A position the chain does not reach names the reachable range.
    let (code, _, err) =
        run_linkage(&["diagram", &scene("gravity_flipper.ron"), "--input-deg", "0"]);
    assert_ne!(code, Some(0));
    assert!(err.contains("reachable input range"), "{err}");
}

#[test]
fn the_default_sheet_draws_force_polygons_where_the_scene_has_forces() {
    let (code, svg, err) = run_sheet(&["diagram", &scene("die_cutter.ron"), "--input-deg", "60"]);
    assert_eq!(code, Some(0), "{err}");
    let drawn = texts_of(&svg);
    assert!(drawn.iter().any(|t| t == "Force polygons"), "{drawn:?}");
    assert!(
        drawn
            .iter()
            .any(|t| t.starts_with("Balancing torque on the crank")),
        "{drawn:?}"
    );
    // A kinematics-only scene: the default sheet leaves them out; asked for by name,
    // they are refused with the cause.
    let file = scene("slider_crank.ron");
    let (code, svg, err) = run_sheet(&["diagram", &file, "--input-deg", "30"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(!texts_of(&svg).iter().any(|t| t == "Force polygons"));
    let (code, _, err) = run_linkage(&["diagram", &file, "--input-deg", "30", "--what", "forces"]);
    assert_ne!(code, Some(0));
    assert!(err.contains("kinematics only"), "{err}");
}

/// The course sheet of the quick-return shaper cutting: it parses, holds the plan
/// with every position numbered, the three diagrams, the polygons at the chosen
/// positions and the force polygons at the first; the PNG decodes.
#[test]
fn the_course_sheet_of_the_quick_return_holds_what_a_course_asks_for() {
    let file = format!(
        "{}/../../docs/examples/quick_return_cutting.ron",
        env!("CARGO_MANIFEST_DIR")
    );
    let (code, svg, err) = run_sheet(&["course-sheet", &file, "--chosen", "2", "8"]);
    assert_eq!(code, Some(0), "{err}");
    let drawn = texts_of(&svg);
    for want in [
        "Plan of positions",
        "ram displacement (m)",
        "ram velocity (m/s)",
        "ram acceleration (m/s²)",
        "Position 2 (crank at 60°): polygons",
        "Position 8 (crank at 240°): polygons",
        "Force polygons",
    ] {
        assert!(drawn.iter().any(|t| t == want), "{want} missing: {drawn:?}");
    }
    for n in 0..12 {
        assert!(
            drawn.iter().any(|t| *t == n.to_string()),
            "position {n} unnumbered"
        );
    }
    let (code, _, err) = run_linkage(&["course-sheet", &file, "--positions", "6", "--chosen", "6"]);
    assert_ne!(code, Some(0));
    assert!(
        err.contains("chosen position = 6 is invalid: 0 to 5"),
        "{err}"
    );
    let dir = std::env::temp_dir().join(format!("linkage-course-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch dir");
    let png = dir.join("course.png");
    let (code, _, err) =
        run_linkage(&["course-sheet", &file, "--png", png.to_str().expect("path")]);
    assert_eq!(code, Some(0), "{err}");
    let bytes = std::fs::read(&png).expect("png written");
    assert_eq!(&bytes[1..4], b"PNG");
    let width = u32::from_be_bytes([bytes[16], bytes[17], bytes[18], bytes[19]]);
    // A4 is 210 mm wide: 1240 px at 150 dpi.
    assert!((1239..=1241).contains(&width), "{width} px wide");
    std::fs::remove_dir_all(dir).expect("clean up");
}
