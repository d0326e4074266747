//! Force polygon figures of every scene with masses or forces (the shipped scenes
//! and the examples in `docs/examples`), at 36 inputs over the range: the figure's
//! forces run head to tail and come back to its start (to 1e-9 of its size), a
//! group's diagonal ends where its first link's forces end, every force has a label,
//! and laid out in a pane every label lies inside it.

use crate::common;

use common::inputs;

use linkage::force_polygon::{StagePolygon, force_polygons};
use linkage::kinetostatics::Kinetostatics;
use linkage::scene::Models;
use linkage::{Kinematics, Mechanism};
use linkage_diagram::force_figure::ForceFigure;
use linkage_diagram::layout::Sizes;
use linkage_diagram::polygon_figure::ArrowStyle;
use linkage_diagram::{Label, Rect, layout_polygon};

/// Every scene with force data: the shipped ones and the examples.
fn loaded_scenes() -> Vec<(String, Mechanism)> {
    let examples = format!("{}/../../docs/examples", env!("CARGO_MANIFEST_DIR"));
    let mut out: Vec<(String, Mechanism)> = common::scenes();
    for e in std::fs::read_dir(&examples).expect("examples") {
        let p = e.expect("entry").path();
        if p.extension().is_some_and(|x| x == "ron") {
            let text = std::fs::read_to_string(&p).expect("readable");
            let m = Mechanism::from_ron(&text).unwrap_or_else(|e| panic!("{p:?}: {e}"));
            out.push((p.display().to_string(), m));
        }
    }
    out.retain(|(_, m)| m.models != Models::Kinematics);
    out
}

fn check_figure(fig: &ForceFigure, stage: &StagePolygon, what: &str) {
    let size = stage.largest();
    let chain: Vec<_> = fig
        .arrows
        .iter()
        .filter(|a| a.style != ArrowStyle::Inner)
        .collect();
    for pair in chain.windows(2) {
        let gap = (pair[0].to[0] - pair[1].from[0]).hypot(pair[0].to[1] - pair[1].from[1]);
        assert!(gap <= 1e-9 * size, "{what}: not head to tail");
    }
    if let (Some(first), Some(last)) = (chain.first(), chain.last()) {
        assert_eq!(first.from, [0.0, 0.0], "{what}");
        assert!(
            last.to[0].hypot(last.to[1]) <= 1e-9 * size,
            "{what}: open by {:?}",
            last.to
        );
    }
    if let Some(d) = fig.arrows.iter().find(|a| a.style == ArrowStyle::Inner) {
        assert!(
            chain
                .iter()
                .any(|a| (a.to[0] - d.to[0]).hypot(a.to[1] - d.to[1]) <= 1e-9 * size),
            "{what}: the diagonal ends off the polygon"
        );
    }
    assert!(
        fig.arrows.iter().all(|a| !a.label.text().is_empty()),
        "{what}"
    );
}

#[test]
fn every_force_polygon_closes_head_to_tail_with_its_labels_in_the_pane() {
    let mut figures = 0;
    for (file, m) in loaded_scenes() {
        let mut k = Kinematics::new(m.clone()).expect("kinematics");
        if !k.has_closed_form() {
            continue;
        }
        let mut ks = Kinetostatics::new(&mut k).expect("kinetostatics");
        for input in inputs(&k, 36) {
            let Ok(fp) = force_polygons(&mut k, &mut ks, input) else {
                continue;
            };
            for stage in &fp.stages {
                let what = format!("{file} at {input:.3}, {:?}", stage.stage);
                let fig = ForceFigure::new(stage, &m);
                check_figure(&fig, stage, &what);
                let pane = Rect::from_min_size([10.0, 20.0], 340.0, 260.0);
                let measure = |l: &Label| l.approximate_size(13.0);
                let laid = layout_polygon(&fig, pane, Sizes::default(), &measure);
                for l in &laid.labels {
                    assert!(pane.contains_rect(&l.rect), "{what}: {}", l.label.text());
                }
                figures += 1;
            }
        }
    }
    assert!(figures >= 300, "only {figures} figures");
}
