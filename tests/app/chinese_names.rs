//! A scene named in Chinese (`docs/examples/slider_crank_zh.ron`: 对心曲柄滑块机构,
//! links 机架, 曲柄, 连杆, 滑块) in the app: every character is drawn with a face
//! that has it (egui is told to panic on a missing glyph instead of drawing a box),
//! in the scene menu, the plots' axis titles and the status line. The pictures are written to `target/screens/` to look at.

use eframe::egui;
use egui_kittest::kittest::Queryable as _;
use linkage_lab::session::{SceneSource, Session};

use crate::common;

const EXAMPLE: &str = include_str!("../../docs/examples/slider_crank_zh.ron");

#[test]
fn a_scene_named_in_chinese_draws_every_character() {
    let mut h = common::sized_harness(1366.0, 768.0);
    h.ctx
        .set_missing_glyph_policy(egui::MissingGlyphPolicy::Panic);
    let zh = Session::open_text(SceneSource::File("曲柄滑块.ron".into()), EXAMPLE).expect("opens");
    common::open_dropping_edits(&mut h.state_mut().state, zh);
    common::settle(&mut h);
    assert_eq!(h.state().state.session.scene().name, "对心曲柄滑块机构");
    let dir = "target/screens";
    std::fs::create_dir_all(dir).expect("a folder for the pictures");
    for tab in ["Output", "Transmission"] {
        if h.query_by_label(tab).is_some() {
            h.get_by_label(tab).click();
            common::settle(&mut h);
        }
        let image = h.render().expect("rendered");
        image
            .save(format!("{dir}/chinese_names_{}.png", tab.to_lowercase()))
            .expect("saved");
    }
}
