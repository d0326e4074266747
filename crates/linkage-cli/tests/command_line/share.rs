//! `linkage share`: every scene file in `assets/scenes` packs into a link fragment and
//! unpacks to the same bytes (from the fragment, from `#…` and from a whole URL); a
//! damaged, foreign, too long or too large link is refused with its cause, never a
//! panic.

use crate::common;

use common::{run_linkage, scene};
use miniz_oxide::deflate::compress_to_vec;

fn share(scene_path: &str) -> String {
    let (code, out, err) = run_linkage(&["share", scene_path]);
    assert_eq!(code, Some(0), "{scene_path}: {err}");
    out.trim_end().to_string()
}

fn decode(link: &str) -> (Option<i32>, String, String) {
    run_linkage(&["share", "--decode", link])
}

#[test]
fn every_scene_round_trips_exactly() {
    let dir = scene("");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("scenes")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "ron"))
        .collect();
    files.sort();
    assert!(files.len() >= 6);
    for path in files {
        let text = std::fs::read_to_string(&path).expect("read");
        let fragment = share(&path.display().to_string());
        assert!(fragment.starts_with("doc=1."), "{fragment}");
        assert!(
            fragment[4..]
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c)),
            "{path:?}: not URL-safe"
        );
        for link in [
            fragment.clone(),
            format!("#scene=x&{fragment}"),
            format!("https://example.org/linkage/#{fragment}&input=30"),
            fragment[4..].to_string(),
        ] {
            let (code, out, err) = decode(&link);
            assert_eq!(code, Some(0), "{path:?}: {err}");
            assert_eq!(out, text, "{path:?} via {}", &link[..20]);
        }
    }
}

#[test]
fn damaged_foreign_and_oversized_links_are_refused_by_cause() {
    let fragment = share(&scene("die_cutter.ron"));
    let payload = &fragment[4..];
    let cut = &payload[..payload.len() / 2];
    let mut flipped = payload.to_string();
    flipped.replace_range(10..11, if &payload[10..11] == "A" { "B" } else { "A" });
    let bomb = {
        use base64::Engine as _;
        let zeros = vec![b' '; 3 * 1024 * 1024];
        format!(
            "1.{}",
            base64::engine::general_purpose::URL_SAFE_NO_PAD.encode(compress_to_vec(&zeros, 9))
        )
    };
    let binary = {
        use base64::Engine as _;
        format!(
            "1.{}",
            base64::engine::general_purpose::URL_SAFE_NO_PAD
                .encode(compress_to_vec(&[0xff, 0xfe, 0x00], 9))
        )
    };
    for (link, says) in [
        ("", "the link carries no scene"),
        ("doc=", "the link carries no scene"),
        ("2.abcdef", "unknown format"),
        ("1.@@@@", "the link is damaged"),
        (cut, "the link is damaged"),
        (flipped.as_str(), "the link is damaged"),
        (bomb.as_str(), "unpacks to more than 1048576 bytes"),
        (binary.as_str(), "not UTF-8 text"),
        (
            &format!("1.{}", "A".repeat(40_000)),
            "more than the 32768 a link may carry",
        ),
    ] {
        let (code, out, err) = decode(link);
        // A flipped character may still unpack: then it must not be the scene.
        if code == Some(0) {
            assert_ne!(
                out,
                std::fs::read_to_string(scene("die_cutter.ron")).expect("read"),
                "{link}"
            );
            continue;
        }
        assert_eq!(code, Some(1), "{link:.20}: {err}");
        assert!(err.contains(says), "{link:.20}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

#[test]
fn an_invalid_scene_is_not_shared() {
    let dir = std::env::temp_dir().join(format!("linkage-share-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    let bad = dir.join("bad.ron");
    std::fs::write(&bad, "(name: \"x\", links: [], relative_angel: 5.0)").expect("write");
    let (code, _, err) = run_linkage(&["share", &bad.display().to_string()]);
    assert_eq!(code, Some(1));
    assert!(err.contains("bad.ron"), "{err}");
    std::fs::remove_dir_all(dir).expect("clean up");
}
