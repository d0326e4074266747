//! Every scene file in `assets/scenes` (read from the directory), at 36 inputs over
//! its range, both polygons, in a small pane and a large one: every label has a free
//! place — no two label boxes overlap, none touches an arrow head or a vertex, all
//! lie inside the pane — and the figure fills at least 60 % of the pane in one
//! direction; no two points share a name. The same for the pose's joint names and
//! instant centres.

use crate::common;

use common::{inputs, scenes};

use linkage::Kinematics;
use linkage::instant_centres::instant_centres;
use linkage::polygon::{Quantity, polygons};
use linkage_diagram::layout::{LaidPolygon, Sizes};
use linkage_diagram::pose_figure::PoseFigure;
use linkage_diagram::pose_layout::layout_pose;
use linkage_diagram::{Label, PolygonFigure, Rect, layout_polygon};

fn measure(l: &Label) -> [f64; 2] {
    l.approximate_size(13.0)
}

const PANES: [[f64; 2]; 2] = [[340.0, 260.0], [720.0, 480.0]];

fn check_polygon(laid: &LaidPolygon, what: &str) {
    for (i, l) in laid.labels.iter().enumerate() {
        assert!(
            !l.collides,
            "{what}: no free place for {:?}",
            l.label.text()
        );
        assert!(
            laid.pane.contains_rect(&l.rect),
            "{what}: {:?} leaves the pane",
            l.label.text()
        );
        for m in &laid.labels[i + 1..] {
            assert!(
                !l.rect.overlaps(&m.rect),
                "{what}: {:?} overlaps {:?}",
                l.label.text(),
                m.label.text()
            );
        }
        for a in &laid.arrows {
            if let Some(h) = a.head.and_then(Rect::around) {
                assert!(
                    !l.rect.overlaps(&h),
                    "{what}: {:?} on an arrow head",
                    l.label.text()
                );
            }
        }
    }
    if laid.px_per_unit > 0.0 {
        let f = laid.figure_box().expect("drawn");
        let fill = (f.width() / laid.pane.width()).max(f.height() / laid.pane.height());
        assert!(fill >= 0.6, "{what}: fills {:.0} %", fill * 100.0);
    }
    let finite = |p: &[f64; 2]| p[0].is_finite() && p[1].is_finite();
    assert!(
        laid.arrows.iter().all(|a| finite(&a.from) && finite(&a.to)),
        "{what}"
    );
}

#[test]
fn polygon_labels_have_free_places_and_figures_fill_their_panes() {
    let mut figures = 0;
    for (file, m) in scenes() {
        let mut k = Kinematics::new(m.clone()).expect("kinematics");
        for input in inputs(&k, 36) {
            let s = k
                .solve(input)
                .unwrap_or_else(|e| panic!("{file} at {input}: {e}"));
            let eqs = polygons(&k, &s);
            for q in [Quantity::Velocity, Quantity::Acceleration] {
                let fig = PolygonFigure::of_position(q, &m, &s, &eqs);
                // Each point of the figure has its own name (the quick-return
                // shaper's pin P was "p" beside the pole p).
                let mut names: Vec<&str> = fig.vertices.iter().map(|v| v.name.as_str()).collect();
                names.sort_unstable();
                let before = names.len();
                names.dedup();
                assert_eq!(
                    names.len(),
                    before,
                    "{file} {q:?}: a name twice in {names:?}"
                );
                for [w, h] in PANES {
                    let pane = Rect::from_min_size([10.0, 20.0], w, h);
                    let laid = layout_polygon(&fig, pane, Sizes::default(), &measure);
                    let what = format!("{file} {q:?} at {:.1}° in {w}x{h}", input.to_degrees());
                    check_polygon(&laid, &what);
                    figures += 1;
                }
            }
        }
    }
    assert!(figures >= 6 * 36 * 4, "{figures}");
}

#[test]
fn pose_labels_and_instant_centres_have_free_places() {
    for (file, m) in scenes() {
        let mut k = Kinematics::new(m.clone()).expect("kinematics");
        for input in inputs(&k, 36) {
            let s = k.solve(input).expect("solves");
            let ic = instant_centres(&m, &s);
            let fig = PoseFigure::new(&m, &s, Some(&ic));
            let pane = Rect::from_min_size([0.0, 0.0], 713.0, 360.0);
            let laid = layout_pose(&fig, pane, Sizes::default(), &measure);
            let what = format!("{file} at {:.1}°", input.to_degrees());
            for (i, l) in laid.labels.iter().enumerate() {
                assert!(
                    !l.placed.collides,
                    "{what}: no free place for {:?}",
                    l.label.text()
                );
                for o in &laid.labels[i + 1..] {
                    assert!(
                        !l.placed.rect.overlaps(&o.placed.rect),
                        "{what}: {:?} on {:?}",
                        l.label.text(),
                        o.label.text()
                    );
                }
            }
            assert_eq!(
                laid.centres.len() + laid.centres_off.len(),
                ic.centres.len(),
                "{what}: every centre drawn or listed"
            );
        }
    }
}
