//! A scene named in Chinese (its name, links and description: the in-line
//! slider-crank as `docs/examples/slider_crank_zh.ron` writes it) through the command
//! line: the names come back as written in the text report, the CSV and the JSON,
//! and the sheet draws every character of them (the PNG with the Chinese face).

use crate::common;

use common::run_linkage;

fn example() -> String {
    format!(
        "{}/../../docs/examples/slider_crank_zh.ron",
        env!("CARGO_MANIFEST_DIR")
    )
}

fn ok(args: &[&str]) -> String {
    let (code, out, err) = run_linkage(args);
    assert_eq!(code, Some(0), "{args:?}: {err}");
    out
}

#[test]
fn chinese_names_come_back_as_written() {
    let file = example();
    let report = ok(&["report", &file, "--format", "text"]);
    assert!(report.starts_with("对心曲柄滑块机构\n"), "{report}");
    assert!(report.contains("stroke of 滑块: 100 mm"), "{report}");
    let csv = ok(&["sweep", &file, "--step-deg", "90"]);
    let header = csv.lines().next().expect("header");
    assert!(
        header.ends_with("滑块 angle (deg),滑块 omega (rad/s),滑块 alpha (rad/s^2)"),
        "{header}"
    );
    assert!(header.contains(",曲柄 angle (deg),"), "{header}");
    let json: serde_json::Value =
        serde_json::from_str(&ok(&["at", &file, "--input-deg", "30"])).expect("JSON");
    assert_eq!(json["scene"], "对心曲柄滑块机构");
    assert!(
        json["links"]["连杆"]["omega"].is_number(),
        "{}",
        json["links"]
    );
}

/// In both languages: the English sheet with the Chinese names, and the Chinese
/// sheet (`--lang zh-CN`).
#[test]
fn the_sheet_draws_every_chinese_character() {
    for lang in ["en", "zh-CN"] {
        let args = ["diagram", &example(), "--input-deg", "30", "--lang", lang];
        let (code, pages, err) = common::run_sheet(&args);
        assert_eq!(code, Some(0), "{err}");
        assert!(
            pages[0].contains("对心曲柄滑块机构"),
            "the title names the scene"
        );
        for page in &pages {
            let undrawn = linkage_diagram::png::undrawn_characters(
                page,
                epaint_default_fonts::UBUNTU_LIGHT,
                "Ubuntu",
            )
            .expect("parses");
            assert!(undrawn.is_empty(), "{lang}: drawn as boxes: {undrawn:?}");
        }
    }
    let (_, zh, _) = common::run_sheet(&[
        "diagram",
        &example(),
        "--input-deg",
        "30",
        "--lang",
        "zh-CN",
    ]);
    assert!(zh.concat().contains("速度多边形"), "the Chinese sheet");
}
