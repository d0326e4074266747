//! A cam's follower drawn where it stands (a task sheet's cam figure): the stem in
//! its guide or the arm on its pivot, the roller, knife edge or flat face on the cam.
//! The outline is the solver's ([`FollowerOutline`]), so the follower drawn touches
//! the profile drawn.

use linkage::cam::FollowerOutline;

use crate::geometry::Pt;
use crate::svg_draw::{circle, line};

const FOLLOWER: &str = "#2f5f9e";
const FRAME: &str = "#444444";

/// Draws `o` through `px` (metres to the page) at `scale` px per metre.
pub(crate) fn follower(
    out: &mut String,
    o: &FollowerOutline,
    px: &dyn Fn([f64; 2]) -> Pt,
    scale: f64,
) {
    line(out, px(o.stem_m[0]), px(o.stem_m[1]), FOLLOWER, 2.4, false);
    if let Some([a, b]) = o.guide_m {
        // The guide's two walls beside the stem, as the textbooks draw a sliding pair.
        let gap = 5.0;
        for side in [-gap, gap] {
            let shift = |p: Pt| [p[0] + side, p[1]];
            line(out, shift(px(a)), shift(px(b)), FRAME, 1.0, false);
        }
    }
    if let Some([a, b]) = o.flat_face_m {
        line(out, px(a), px(b), FOLLOWER, 2.4, false);
    }
    match o.roller_radius_m {
        Some(r) => circle(out, px(o.tip_m), (r * scale).max(2.0), "#ffffff", FOLLOWER),
        None => circle(out, px(o.tip_m), 1.8, FOLLOWER, "none"),
    }
    if let Some(pivot) = o.pivot_m {
        circle(out, px(pivot), 3.5, "#ffffff", FRAME);
    }
}
