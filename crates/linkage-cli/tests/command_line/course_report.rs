//! `linkage course-report`: for every shipped scene, the report's PDF read back by
//! pdftotext holds the numbers `linkage report` gives as JSON (the time ratio K, the
//! strokes and swings, the least transmission angle) written as the report writes
//! them, its degrees of freedom, and every font embedded (pdffonts); in Chinese for
//! the three papers' mechanisms. The examples committed under docs/examples/reports
//! are read back the same way. Needs poppler-utils (`scripts/install_deps.sh`).

use crate::common;

use std::path::{Path, PathBuf};
use std::process::Command;

use common::{run_linkage, scene};
use linkage_diagram::numbers::{degrees, si, significant};

/// `tool ARGS` (pdftotext, pdffonts); its standard output.
fn poppler(tool: &str, args: &[&str]) -> String {
    let out = Command::new(tool)
        .args(args)
        .output()
        .unwrap_or_else(|e| panic!("{tool} (poppler-utils, scripts/install_deps.sh): {e}"));
    assert!(out.status.success(), "{tool} {args:?}");
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The PDF's text, in reading order.
fn text_of(pdf: &Path) -> String {
    poppler("pdftotext", &[&pdf.display().to_string(), "-"])
}

/// Every font is embedded (pdffonts' `emb` column says yes).
fn assert_fonts_embedded(pdf: &Path) {
    let list = poppler("pdffonts", &[&pdf.display().to_string()]);
    let fonts: Vec<&str> = list.lines().skip(2).collect();
    assert!(!fonts.is_empty(), "{pdf:?}: no font");
    for f in fonts {
        let cols: Vec<&str> = f.split_whitespace().collect();
        let emb = cols[cols.len() - 5];
        assert_eq!(emb, "yes", "{pdf:?}: not embedded: {f}");
    }
}

fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("linkage-report-{test}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}

fn scene_files() -> Vec<String> {
    let mut files: Vec<String> = std::fs::read_dir(scene(""))
        .expect("scenes")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "ron"))
        .map(|p| p.display().to_string())
        .collect();
    files.sort();
    files
}

/// The numbers of `linkage report`'s JSON the report must hold, as it writes them.
fn expected(report: &serde_json::Value) -> Vec<String> {
    let mut want = Vec::new();
    if let Some(k) = report["time_ratio"].as_f64() {
        want.push(significant(k, 4));
    }
    for (_, s) in report["strokes_m"].as_object().into_iter().flatten() {
        want.push(si(s.as_f64().expect("a stroke"), "m"));
    }
    for (_, s) in report["swings_rad"].as_object().into_iter().flatten() {
        want.push(degrees(s.as_f64().expect("a swing").to_degrees()));
    }
    if let Some(mu) = report["transmission_angle_rad"]["min"].as_f64() {
        want.push(degrees(mu.to_degrees()));
    }
    want
}

#[test]
fn every_scenes_report_holds_the_clis_numbers_with_its_fonts_embedded() {
    let dir = scratch("en");
    for file in scene_files() {
        let pdf = dir.join("report.pdf");
        let path = pdf.display().to_string();
        let (code, _, err) = run_linkage(&["course-report", &file, "--pdf", &path]);
        assert_eq!(code, Some(0), "{file}: {err}");
        let text = text_of(&pdf);
        assert!(text.contains("Course design report"), "{file}");
        // P_L and P_H set with their subscripts, read back in line.
        assert!(text.contains("F = 3n − 2PL − PH"), "{file}: {text}");
        let (code, json, err) = run_linkage(&["report", &file]);
        assert_eq!(code, Some(0), "{file}: {err}");
        let report: serde_json::Value = serde_json::from_str(&json).expect("JSON");
        for number in expected(&report) {
            assert!(text.contains(&number), "{file}: {number} missing");
        }
        assert_fonts_embedded(&pdf);
    }
    std::fs::remove_dir_all(dir).expect("clean up");
}

#[test]
fn the_papers_mechanisms_report_in_chinese() {
    let dir = scratch("zh");
    for key in ["die_cutter", "paper_cup_cam_feed", "gravity_flipper"] {
        let pdf = dir.join(format!("{key}.pdf"));
        let path = pdf.display().to_string();
        let file = scene(&format!("{key}.ron"));
        let args = ["course-report", &file, "--lang", "zh-CN", "--pdf", &path];
        let (code, _, err) = run_linkage(&args);
        assert_eq!(code, Some(0), "{key}: {err}");
        let text = text_of(&pdf);
        for word in [
            "课程设计说明书",
            "自由度",
            "基本杆组",
            "机构位置图",
            "设计结果汇总",
        ] {
            assert!(text.contains(word), "{key}: no {word}");
        }
        assert_fonts_embedded(&pdf);
    }
    std::fs::remove_dir_all(dir).expect("clean up");
}

/// The examples under docs/examples/reports: text that reads back, fonts embedded.
#[test]
fn the_committed_example_reports_read_back() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/examples/reports");
    let mut seen = 0;
    for entry in std::fs::read_dir(&dir).expect("docs/examples/reports") {
        let pdf = entry.expect("entry").path();
        if pdf.extension().is_none_or(|x| x != "pdf") {
            continue;
        }
        let text = text_of(&pdf);
        let zh = pdf.to_string_lossy().ends_with("_zh.pdf");
        let title = if zh {
            "课程设计说明书"
        } else {
            "Course design report"
        };
        assert!(text.contains(title), "{pdf:?}");
        assert_fonts_embedded(&pdf);
        seen += 1;
    }
    assert_eq!(seen, 6, "three mechanisms in two languages");
}
