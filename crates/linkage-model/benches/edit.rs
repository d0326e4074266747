//! The time of one edit per shipped scene, as a slider makes it: a length set to a
//! valid value, and to one the chain cannot assemble with (refused, with its limit
//! found); a joint dragged in the editor; for scenes with springs or masses, those
//! too. Measured is what the frame
//! of the edit has to do before it can draw: the edit itself (pose, polygons, the
//! curves on screen). The report follows in the first frame without an edit
//! (`report`, measured apart); the dynamic run follows off the frame.
//!
//! A drawn four-bar's point dragged with the drawing tools is measured too: each move
//! remakes the scene from the drawing and opens it.
//!
//! `cargo bench -p linkage-model --bench edit`; the target is 4 ms per edit (a 60 Hz frame with room
//! for drawing).

use std::hint::black_box;
use std::path::PathBuf;

use criterion::{Criterion, criterion_group, criterion_main};
use linkage::analysis::report;
use linkage_model::session::{SceneEdit, SceneSource, Session};

/// Every scene file in `assets/scenes`, read from the directory.
fn scene_files() -> Vec<PathBuf> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../assets/scenes");
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .expect("the scene directory")
        .map(|e| e.expect("an entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "ron"))
        .collect();
    files.sort();
    files
}

fn open(path: &PathBuf) -> Session {
    let text = std::fs::read_to_string(path).expect("a scene file");
    let name = path.display().to_string();
    Session::open_text(SceneSource::File(name), &text).expect("a shipped scene opens")
}

/// What the frame of an edit computes: the edit and the polygons it shows.
fn edit(s: &mut Session, f: impl Fn(&mut Session)) {
    f(s);
    black_box(s.polygons());
}

/// A length index and a value of it the chain cannot assemble with, if any has one.
fn refusable_length(path: &PathBuf) -> Option<(usize, f64)> {
    let mut s = open(path);
    for i in 0..s.lengths().len() {
        let v = s.lengths()[i].value(s.scene())?;
        for factor in [100.0, 0.01] {
            s.apply(SceneEdit::Length {
                index: i,
                value: v * factor,
            });
            if s.message().is_some() {
                return Some((i, v * factor));
            }
        }
    }
    None
}

fn edits(c: &mut Criterion) {
    let mut group = c.benchmark_group("edit");
    for path in scene_files() {
        let key = path
            .file_stem()
            .expect("a name")
            .to_string_lossy()
            .to_string();
        let mut s = open(&path);
        let v = s.lengths()[0].value(s.scene()).expect("a length");
        let mut flip = false;
        group.bench_function(format!("{key}/length valid"), |b| {
            b.iter(|| {
                flip = !flip;
                let x = if flip { 1.01 * v } else { v };
                edit(&mut s, |s| {
                    s.apply(SceneEdit::Length { index: 0, value: x })
                });
            });
        });
        assert!(s.message().is_none(), "{key}: {:?}", s.message());
        // An editor drag: a joint moved back and forth by 1 % of the mechanism's size.
        let mut dragged = open(&path);
        let (name, at) = {
            let m = dragged.mechanism();
            // The last pin joint (a slider's point moves only along its guide).
            let p = *dragged
                .topology()
                .joint_points
                .iter()
                .rev()
                .find(|&&p| m.sliders.iter().all(|sl| sl.point != p))
                .expect("a pin joint");
            let q = dragged.pose().points[p].position;
            (m.points[p].name.clone(), [q.x, q.y])
        };
        let step = 0.01 * dragged.mechanism().size_m;
        edit(&mut dragged, |s| {
            s.apply(SceneEdit::MovePoint {
                name: String::from(&name),
                to_m: [at[0] + step, at[1]],
            })
        });
        assert!(
            dragged.message().is_none(),
            "{key}: {:?}",
            dragged.message()
        );
        group.bench_function(format!("{key}/point dragged"), |b| {
            b.iter(|| {
                flip = !flip;
                let to = if flip { [at[0] + step, at[1]] } else { at };
                edit(&mut dragged, |s| {
                    s.apply(SceneEdit::MovePoint {
                        name: String::from(&name),
                        to_m: to,
                    })
                });
            });
        });
        group.bench_function(format!("{key}/report"), |b| {
            b.iter(|| black_box(report(&mut s.kinematics().clone())));
        });
        if let Some((i, bad)) = refusable_length(&path) {
            let mut s = open(&path);
            // Checked before, not after: a filtered run (`-- NAME`) skips the bench.
            edit(&mut s, |s| {
                s.apply(SceneEdit::Length {
                    index: i,
                    value: bad,
                })
            });
            assert!(s.message().is_some(), "{key}: refused");
            group.bench_function(format!("{key}/length refused"), |b| {
                b.iter(|| {
                    edit(&mut s, |s| {
                        s.apply(SceneEdit::Length {
                            index: i,
                            value: bad,
                        })
                    })
                });
            });
        }
        if let Some(k) = s.scene().forces.springs.first().map(|sp| sp.k_n_per_m) {
            let mut flip = false;
            group.bench_function(format!("{key}/spring k"), |b| {
                b.iter(|| {
                    flip = !flip;
                    edit(&mut s, |s| {
                        s.apply(SceneEdit::SpringK {
                            index: 0,
                            n_per_m: if flip { 1.1 * k } else { k },
                        })
                    });
                });
            });
        }
        if let Some((i, m)) = s
            .scene()
            .links
            .iter()
            .enumerate()
            .find_map(|(i, l)| Some((i, l.mass?)))
        {
            let mut flip = false;
            group.bench_function(format!("{key}/mass"), |b| {
                b.iter(|| {
                    flip = !flip;
                    edit(&mut s, |s| {
                        s.apply(SceneEdit::Mass {
                            index: i,
                            kg: if flip { 1.1 * m } else { m },
                        })
                    });
                });
            });
        }
    }
    group.finish();
}

/// A drawn four-bar with its coupler pin dragged (the drawing tools' Move): the
/// drawing's edit, and the scene it makes opened as the session, every frame (what
/// the app's `ui::drawing::edit` does).
fn drawing_drag(c: &mut Criterion) {
    use linkage::Vec2;
    use linkage::drawing::Drawing;
    use linkage_model::drawing::DrawingEditor;
    use linkage_model::drawing::edit::{DrawingEdit, End};

    let at = |x: f64, y: f64| Vec2::new(x, y);
    let mut drawing = DrawingEditor::new(Drawing::new("drawn"));
    for e in [
        DrawingEdit::AddPivot(at(0.0, 0.0)),
        DrawingEdit::AddPivot(at(0.3, 0.0)),
        DrawingEdit::AddLink(End::Point(0), End::New(at(0.0, 0.05))),
        DrawingEdit::AddLink(End::Point(2), End::New(at(0.2, 0.2))),
        DrawingEdit::AddLink(End::Point(3), End::Point(1)),
        DrawingEdit::SetDriver(0),
    ] {
        drawing.apply(e);
    }
    let open = |drawing: &mut DrawingEditor| {
        let scene = drawing.refresh().expect("the drawing is a four-bar");
        Session::open_scene(SceneSource::File("my_mechanism.ron".into()), scene)
            .expect("the four-bar solves")
    };
    open(&mut drawing);
    // One gesture: the drag's moves are one undo step, so the history does not grow.
    drawing.dragged = Some(3);
    let mut flip = false;
    c.bench_function("edit/drawing/point dragged", |b| {
        b.iter(|| {
            flip = !flip;
            let to = if flip { at(0.21, 0.2) } else { at(0.2, 0.2) };
            drawing.apply(DrawingEdit::MovePoint { point: 3, to });
            let session = open(&mut drawing);
            black_box(session.polygons());
        });
    });
    assert!(drawing.problem.is_none());
}

criterion_group!(benches, edits, drawing_drag);
criterion_main!(benches);
