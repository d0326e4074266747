//! Pictures to look at, not a test that passes or fails: every shipped scene at a
//! laptop's 1366×768, a phone's 390×844 and a tablet's 820×1180, rendered through
//! wgpu into `target/screens/` (or `$LINKAGE_SCREENS`), with the plot tab or sheet
//! tab `$LINKAGE_SCREENS_TAB` shown if set (its label in the language shown), in
//! Chinese if `$LINKAGE_SCREENS_LANG` is `zh-CN`. Run with
//! `cargo test --test app screens -- --ignored`.

use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use linkage_lab::catalog::BUILTIN_SCENES;
use linkage_lab::{LinkageApp, StartOptions};

#[test]
#[ignore = "writes pictures to look at; run by hand"]
fn screens() {
    let dir = std::env::var("LINKAGE_SCREENS").unwrap_or_else(|_| "target/screens".into());
    std::fs::create_dir_all(&dir).expect("a folder for the pictures");
    let tab = std::env::var("LINKAGE_SCREENS_TAB").ok();
    let lang = std::env::var("LINKAGE_SCREENS_LANG").unwrap_or_else(|_| "en".into());
    let language = linkage_lab::i18n::Language::from_tag(&lang);
    for (w, h) in [(1366.0, 768.0), (390.0, 844.0), (820.0, 1180.0)] {
        for scene in BUILTIN_SCENES {
            let key = scene.key.to_owned();
            let mut harness: Harness<'static, LinkageApp> = Harness::builder()
                .with_size(egui::vec2(w, h))
                .wgpu()
                .build_eframe(move |cc| {
                    let start = StartOptions {
                        scene: Some(key.clone()),
                        ..StartOptions::default()
                    };
                    LinkageApp::new(cc, start)
                });
            harness.state_mut().state.timing.show = false;
            harness.state_mut().state.language = language;
            for _ in 0..4 {
                harness.state_mut().state.session.wait_for_run();
                harness.run_steps(1);
            }
            if let Some(tab) = &tab
                && harness.query_by_label(tab).is_some()
            {
                harness.get_by_label(tab).click();
                harness.run_steps(3);
            }
            let image = harness.render().expect("rendered");
            let path = format!("{dir}/{}_{w}x{h}_{}.png", scene.key, language.code());
            image.save(&path).expect("saved");
        }
    }
}
