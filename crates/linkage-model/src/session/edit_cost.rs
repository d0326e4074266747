//! The CPU an edit takes, measured where the app runs (in the browser: in the page,
//! WebAssembly on the page's clock). A copy of the scene is opened apart from the
//! user's session and edited as a slider edits it: its first length set a
//! hundredth larger and back, and set to a value the chain cannot take (refused,
//! with its limit found), each many times; the median of each is the figure, so that
//! a frame the browser or the other processes took from the page does not stand for
//! the edit. The browser test reads it (`linkage_lab_edit_cpu`) and reports it per
//! scene and build; `cargo bench -p linkage-model --bench edit` is the same natively.

use serde::Serialize;

use super::{SceneEdit, SceneSource, Session};

/// How many times each edit is made.
const REPEATS: usize = 15;

/// An edit's CPU, ms.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct EditCpu {
    /// A valid length edit, median.
    pub valid_ms: f64,
    /// The length set to its slider's upper end where the chain cannot take it
    /// (refused, with its limit found), median; `None` where it is taken.
    pub refused_long_ms: Option<f64>,
    /// The same at the slider's lower end: a link too short to reach is found by
    /// another search than one too long (the scene may not build at all there).
    pub refused_short_ms: Option<f64>,
}

fn median(mut ms: Vec<f64>) -> f64 {
    ms.sort_by(f64::total_cmp);
    ms.get(ms.len() / 2).copied().unwrap_or(f64::NAN)
}

/// The time of `edit` applied to `s`, ms.
fn timed(s: &mut Session, edit: SceneEdit) -> f64 {
    let started = web_time::Instant::now();
    s.apply(edit);
    started.elapsed().as_secs_f64() * 1e3
}

/// The median time of setting the first length to `bad`, from its value `good`
/// each time (as a slider dragged to its end does), where the chain refuses it.
fn refused_at(s: &mut Session, good: f64, bad: f64) -> Option<f64> {
    let set = |s: &mut Session, value| s.apply(SceneEdit::Length { index: 0, value });
    set(s, bad);
    let refused = s.message().is_some();
    set(s, good);
    refused.then(|| {
        median(
            (0..REPEATS)
                .map(|_| {
                    timed(
                        s,
                        SceneEdit::Length {
                            index: 0,
                            value: bad,
                        },
                    )
                })
                .collect(),
        )
    })
}

/// The CPU of a length edit of `scene` (what the edit's frame computes before it
/// draws), measured here; `None` for a scene with no length to edit or that does not
/// open. Every edit is first made [`REPEATS`] times untimed: a browser runs a
/// WebAssembly function's first calls in its baseline compiler's code while its
/// optimising compiler works on the function on another core (V8's dynamic tiering),
/// and a slider dragged runs the optimised code after its first frames. Measured in
/// the page, the cam feed's first round took 2.5 to 3.6 ms and the rounds after it
/// 1.7 to 1.8 ms.
pub fn edit_cpu(scene: &linkage::SceneFile) -> Option<EditCpu> {
    let mut s = Session::open_scene(SceneSource::File("measured".into()), scene.clone()).ok()?;
    let param = s.lengths().first()?.clone();
    let v = param.value(s.scene())?;
    let range = param.range();
    let mut round = || EditCpu {
        valid_ms: median(
            (0..REPEATS)
                .map(|i| {
                    let value = if i % 2 == 0 { 1.01 * v } else { v };
                    timed(&mut s, SceneEdit::Length { index: 0, value })
                })
                .collect(),
        ),
        refused_long_ms: refused_at(&mut s, v, *range.end()),
        refused_short_ms: refused_at(&mut s, v, *range.start()),
    };
    round();
    Some(round())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every shipped scene is measured; the die cutter's first length (AD) is
    /// refused at its slider's end. No time is asserted: the figures are the
    /// browser test's to report.
    #[test]
    fn every_shipped_scene_is_measured() {
        for b in crate::catalog::BUILTIN_SCENES {
            let scene = linkage::SceneFile::parse(b.text).expect("parses");
            let cpu = edit_cpu(&scene).expect("measured");
            assert!(cpu.valid_ms.is_finite() && cpu.valid_ms >= 0.0, "{}", b.key);
            if std::env::var_os("LINKAGE_PRINT_EDIT_CPU").is_some() {
                println!("{}: {cpu:?}", b.key);
            }
            if b.key == "die_cutter" {
                assert!(
                    cpu.refused_long_ms.is_some(),
                    "the die cutter's AD is refused at 4x"
                );
            }
        }
    }
}
