//! A chain without a closed form (the triad six-bar of the CLI tests) opened in the
//! app's session: the crank slider spans the traced assembly range, moving it past a
//! fold is refused naming that range, and the pose shown stays the last valid one.

use linkage_diagram::numbers::significant;
use linkage_lab::session::{SceneEdit, SceneSource, Session};

#[test]
fn a_newton_only_scene_offers_its_traced_range_and_refuses_past_its_folds() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/crates/linkage-cli/tests/data/triad_six_bar.ron"
    );
    let text = std::fs::read_to_string(path).expect("the triad fixture");
    let k = linkage::Kinematics::new(linkage::Mechanism::from_ron(&text).expect("valid"))
        .expect("assembles");
    let [tlo, thi] = k.traced_range().expect("the triad locks both ways");
    let (a, width) = (
        tlo.rem_euclid(std::f64::consts::TAU).to_degrees(),
        (thi - tlo).to_degrees(),
    );

    let mut s =
        Session::open_text(SceneSource::File("triad_six_bar.ron".into()), &text).expect("opens");
    let [lo, hi] = s.input_range_deg();
    assert!(
        (lo - a).abs() < 1e-3 && (hi - lo - width).abs() < 1e-3,
        "slider {lo}..{hi}, traced {a} + {width}"
    );
    s.apply(SceneEdit::Input {
        deg: 0.5 * (lo + hi),
    });
    assert!(s.message().is_none(), "{:?}", s.message());
    let kept = s.pose().input_rad;
    s.apply(SceneEdit::Input { deg: a - 60.0 });
    let msg = s.message().expect("refused past the fold");
    let want = format!(
        "the crank reaches {}° to {}°",
        significant(a, 5),
        significant(a + width, 5)
    );
    assert!(msg.contains(&want), "{msg}");
    assert_eq!(s.pose().input_rad, kept, "the last valid pose is kept");
}
