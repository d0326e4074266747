//! A scene named in Chinese (`docs/examples/slider_crank_zh.ron`: 对心曲柄滑块机构,
//! links 机架, 曲柄, 连杆, 滑块) in the app: every character is drawn with a face
//! that has it (egui is told to panic on a missing glyph instead of drawing a box),
//! in the scene menu, the plots' axis titles and the status line. The pictures are written to `target/screens/` to look at.

use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use linkage_lab::LinkageApp;
use linkage_lab::session::{SceneSource, Session};
use linkage_lab::ui::control_map::ControlKind;

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

/// The app in Chinese: its own words from the catalogue (the top bar, the panels'
/// headings, the controls, the plot tabs, the overlay, the status line), every
/// character drawn, the laptop's and the phone's screens written to
/// `target/screens/` to look at; switched back to English from the top bar's menu.
#[test]
fn the_app_speaks_chinese_when_chosen_and_english_again() {
    use linkage_lab::i18n::Language;
    let dir = "target/screens";
    std::fs::create_dir_all(dir).expect("a folder for the pictures");
    for (w, h_px) in [(1366.0, 768.0), (390.0, 844.0)] {
        let mut h = common::sized_harness(w, h_px);
        h.ctx
            .set_missing_glyph_policy(egui::MissingGlyphPolicy::Panic);
        h.state_mut().state.language = Language::Chinese;
        common::settle(&mut h);
        for words in ["播放", "曲柄转角 (°)"] {
            assert!(
                h.query_all_by_label(words).next().is_some(),
                "{w}×{h_px}: no \"{words}\""
            );
        }
        assert!(
            h.query_by_label("Play").is_none(),
            "{w}×{h_px}: English left"
        );
        let image = h.render().expect("rendered");
        image
            .save(format!("{dir}/chinese_ui_{w}x{h_px}.png"))
            .expect("saved");
    }
    let mut h = common::sized_harness(1366.0, 768.0);
    h.state_mut().state.language = Language::Chinese;
    common::settle(&mut h);
    // The switch, where the control map says it is drawn; then its English item.
    let [x0, y0, x1, y1] = h
        .state()
        .state
        .controls
        .of_kind(ControlKind::Language)
        .next()
        .expect("the language switch is on the top bar")
        .rect;
    common::click(&mut h, egui::pos2(0.5 * (x0 + x1), 0.5 * (y0 + y1)));
    common::settle(&mut h);
    h.get_by_label("English").click();
    common::settle(&mut h);
    assert_eq!(h.state().state.language, Language::English);
    assert!(h.query_by_label("Play").is_some(), "English again");
}

/// A refusal in Chinese, as drawn: the die cutter's crank made a hundred times
/// longer is refused in the user's words and language, with the limit and the
/// distances, and no English (the solver's inner words nor the English catalogue)
/// reaches the screen; the same refusal in English once the language is switched.
#[test]
fn a_refused_edit_is_worded_in_the_users_language() {
    use linkage_lab::i18n::Language;
    use linkage_lab::session::SceneEdit;
    let mut h = common::sized_harness(1366.0, 768.0);
    h.ctx
        .set_missing_glyph_policy(egui::MissingGlyphPolicy::Panic);
    h.state_mut().state.language = Language::Chinese;
    common::settle(&mut h);
    let crank = h.state().state.session.lengths()[1].clone();
    let value = 100.0
        * crank
            .value(h.state().state.session.scene())
            .expect("a length");
    h.state_mut()
        .state
        .edit(SceneEdit::Length { index: 1, value });
    common::settle(&mut h);
    // A label's text is its node's value.
    let shown = |h: &Harness<'static, LinkageApp>, words: &str| -> Option<String> {
        h.query_all_by(|n| n.value().is_some_and(|v| v.contains(words)))
            .next()
            .and_then(|n| n.value())
    };
    let refused = shown(&h, "无法装配").expect("the refusal is drawn in Chinese");
    assert!(
        refused.contains("极限值为") && refused.contains(&crank.label),
        "{refused}"
    );
    for english in ["does not fit", "cannot meet", "dyad", "margin"] {
        assert!(
            shown(&h, english).is_none(),
            "English on the screen: {english}"
        );
    }
    h.state_mut().state.language = Language::English;
    common::settle(&mut h);
    assert!(shown(&h, "does not fit at crank").is_some());
}
