//! `linkage cam`: the shipped cam files as CSV and JSON, and the DXF read back by the
//! `dxf` crate's parser with every profile point present (to 1e-9 mm); bad files and
//! options refused by name.

use crate::common;

use common::run_linkage;

fn cam(file: &str) -> String {
    format!("{}/../../assets/cams/{file}", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn the_dxf_holds_every_profile_point() {
    let dir = std::env::temp_dir().join(format!("linkage-cam-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch dir");
    for file in ["offset_roller.ron", "oscillating_roller.ron"] {
        let dxf_path = dir.join("cam.dxf");
        let path = dxf_path.to_str().expect("a path");
        let (code, json, err) =
            run_linkage(&["cam", &cam(file), "--format", "json", "--dxf", path]);
        assert_eq!(code, Some(0), "{file}: {err}");
        let v: serde_json::Value = serde_json::from_str(&json).expect("json");
        let rows = v["rows"].as_array().expect("rows");
        assert_eq!(rows.len(), 360);
        let drawing = dxf::Drawing::load_file(&dxf_path).expect("the DXF parses");
        let profile = drawing
            .entities()
            .find_map(|e| match &e.specific {
                dxf::entities::EntityType::LwPolyline(p) if e.common.layer == "PROFILE" => {
                    Some(p.clone())
                }
                _ => None,
            })
            .expect("a profile polyline");
        assert!(profile.is_closed());
        assert_eq!(profile.vertices.len(), rows.len(), "{file}");
        for (vertex, row) in profile.vertices.iter().zip(rows) {
            let x = row["profile_x_m"].as_f64().expect("x") * 1e3;
            let y = row["profile_y_m"].as_f64().expect("y") * 1e3;
            assert!(
                (vertex.x - x).abs() <= 1e-9 && (vertex.y - y).abs() <= 1e-9,
                "{file}: {vertex:?} vs ({x}, {y})"
            );
        }
    }
    std::fs::remove_dir_all(dir).expect("clean up");
}

#[test]
fn the_json_gives_the_joins_the_peaks_and_the_extremes() {
    let (code, json, err) = run_linkage(&["cam", &cam("offset_roller.ron"), "--format", "json"]);
    assert_eq!(code, Some(0), "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).expect("json");
    let joins = v["joins"].as_array().expect("joins");
    assert_eq!(joins.len(), 4);
    assert!(joins.iter().all(|j| j["continuity"] == "C2"), "{joins:?}");
    assert_eq!(v["peak_coefficients"][0]["law"], "Cycloidal");
    assert_eq!(v["peak_coefficients"][0]["coefficients"]["velocity"], 2.0);
    assert_eq!(v["extremes"]["undercut"], false);
    let (code, csv, err) = run_linkage(&["cam", &cam("offset_roller.ron"), "--samples", "36"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(csv.starts_with("angle_deg,s,v,a,jerk,pitch_x_m"), "{csv}");
    assert_eq!(csv.lines().count(), 37);
}

#[test]
fn a_cam_that_is_not_a_turn_or_a_bad_option_is_refused_by_name() {
    let dir = std::env::temp_dir().join(format!("linkage-cam-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch dir");
    let bad = dir.join("bad.ron");
    let text = std::fs::read_to_string(cam("offset_roller.ron"))
        .expect("readable")
        .replace("Dwell(deg: 80.0)", "Dwell(deg: 70.0)");
    std::fs::write(&bad, text).expect("written");
    let (code, _, err) = run_linkage(&["cam", bad.to_str().expect("path")]);
    assert_ne!(code, Some(0));
    assert!(err.contains("sum of the segment angles"), "{err}");
    let (code, _, err) = run_linkage(&["cam", &cam("offset_roller.ron"), "--samples", "2"]);
    assert_ne!(code, Some(0));
    assert!(
        err.contains("--samples 2 is out of range: 4 to 1000000"),
        "{err}"
    );
    std::fs::remove_dir_all(dir).expect("clean up");
}
