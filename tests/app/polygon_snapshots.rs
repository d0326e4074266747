//! The polygon pane of each seed scene at three crank angles, drawn through wgpu
//! (Mesa's lavapipe in CI) and compared with the images committed under
//! `docs/polygons/` (shown in docs/journal.md; `UPDATE_SNAPSHOTS=1` rewrites them). The
//! die cutter as printed is shown at the paper's "position 1" (crank at 50°).
//! Each pane is also checked as a user would read it: both polygons drawn, no label
//! without a free place.

use eframe::egui;
use egui_kittest::{Harness, SnapshotOptions};
use linkage_lab::AppState;
use linkage_lab::session::{SceneEdit, SceneSource, Session};
use linkage_lab::ui::polygons::PolygonPane;

/// Scene, crank angles (deg): the paper-cup feed, both die cutters, the flipper.
const SHOTS: [(&str, [f64; 3]); 4] = [
    ("paper_cup_feed", [0.0, 120.0, 240.0]),
    ("die_cutter", [30.0, 150.0, 270.0]),
    ("die_cutter_as_printed", [50.0, 150.0, 270.0]),
    ("gravity_flipper", [40.0, 70.0, 110.0]),
];

/// The pane's state: the app's, and whether its fonts are set yet.
struct Pane {
    st: AppState,
    pane: PolygonPane,
    fonts_set: bool,
}

fn pane(scene: &str, deg: f64) -> Harness<'static, Pane> {
    let mut session = Session::open_builtin(scene).expect("a shipped scene opens");
    session.apply(SceneEdit::Input { deg });
    assert!(
        session.message().is_none(),
        "{scene} at {deg}°: {:?}",
        session.message()
    );
    let mut st = AppState::new(session);
    st.timing.show = false;
    Harness::builder()
        .with_size(egui::vec2(620.0, 980.0))
        .wgpu()
        .build_ui_state(
            |ui, p: &mut Pane| {
                // The app's own fonts (egui's defaults are not built in): set in the
                // first frame, used from the next.
                if !p.fonts_set {
                    ui.ctx().set_fonts(linkage_lab::fonts::definitions());
                    p.fonts_set = true;
                    return;
                }
                egui::ScrollArea::vertical().show(ui, |ui| p.pane.ui(ui, &mut p.st));
            },
            Pane {
                st,
                pane: PolygonPane::default(),
                fonts_set: false,
            },
        )
}

#[test]
fn polygon_panes_of_the_seed_scenes_match_the_committed_images() {
    let options =
        SnapshotOptions::new().output_path(format!("{}/docs/polygons", env!("CARGO_MANIFEST_DIR")));
    let mut failures = Vec::new();
    for (scene, angles) in SHOTS {
        for deg in angles {
            let mut h = pane(scene, deg);
            h.run();
            if let Err(e) = h.try_snapshot_options(format!("{scene}_{deg:.0}deg"), &options) {
                failures.push(e.to_string());
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The force polygons of a scene file at `deg`, as the polygon pane draws them.
fn force_pane(file: &str, deg: f64) -> Harness<'static, (Session, bool)> {
    let path = format!("{}/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("a scene file");
    let name = SceneSource::File(file.to_string());
    let mut session = Session::open_text(name, &text).expect("opens");
    session.apply(SceneEdit::Input { deg });
    assert!(
        session.message().is_none(),
        "{file}: {:?}",
        session.message()
    );
    Harness::builder()
        .with_size(egui::vec2(620.0, 1500.0))
        .wgpu()
        .build_ui_state(
            |ui, (session, fonts_set): &mut (Session, bool)| {
                if !*fonts_set {
                    ui.ctx().set_fonts(linkage_lab::fonts::definitions());
                    *fonts_set = true;
                    return;
                }
                linkage_lab::ui::force_polygons::section(ui, session, f32::INFINITY);
            },
            (session, false),
        )
}

/// The force polygons of the die cutter and of the quick-return shaper cutting, at
/// two positions each (one on the working stroke, one off it).
#[test]
fn force_polygons_of_the_die_cutter_and_the_quick_return_match_the_committed_images() {
    let options =
        SnapshotOptions::new().output_path(format!("{}/docs/polygons", env!("CARGO_MANIFEST_DIR")));
    let shots = [
        ("assets/scenes/die_cutter.ron", "die_cutter", [60.0, 200.0]),
        (
            "docs/examples/quick_return_cutting.ron",
            "quick_return_cutting",
            [60.0, 270.0],
        ),
    ];
    let mut failures = Vec::new();
    for (file, key, angles) in shots {
        for deg in angles {
            let mut h = force_pane(file, deg);
            h.run();
            let stages = h
                .state()
                .0
                .force_polygons()
                .map(|r| r.as_ref().map(|fp| fp.stages.len()));
            assert!(
                matches!(stages, Some(Ok(n)) if n >= 3),
                "{key} at {deg}: {stages:?}"
            );
            if let Err(e) = h.try_snapshot_options(format!("{key}_forces_{deg:.0}deg"), &options) {
                failures.push(e.to_string());
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
