//! A gear as a rack cutter cuts it ([`linkage::gears::generation`]), drawn whole: the
//! outline of every tooth (its two cut flanks, fillet and undercut included, and the
//! root circle between teeth) as SVG in millimetres, with the pitch, base, tip and
//! root circles, or as DXF for manufacture (the outline on its own layer).

use std::f64::consts::{FRAC_PI_2, TAU};
use std::fmt::Write as _;

use linkage::gears::generation::cut_flank;
use linkage::gears::shaper::shaper_cut_flank;
use linkage::gears::{Gear, GearKind};

use crate::numbers::significant;

/// The closed outline of the cut gear, metres: every tooth's flanks from
/// `per_flank` radii, root arcs between them; empty where the rack cuts nothing
/// (its teeth pointed above their tip line, or an internal gear).
pub fn gear_outline(g: &Gear, per_flank: usize) -> Vec<[f64; 2]> {
    let left: Vec<[f64; 2]> = cut_flank(g, per_flank);
    let z = g.spec.teeth;
    let pitch = TAU / f64::from(z);
    let mut out = Vec::new();
    for k in 0..z {
        let turn = f64::from(k) * pitch;
        let (s, c) = turn.sin_cos();
        let at = |[x, y]: [f64; 2]| [c * x - s * y, s * x + c * y];
        // The right flank (the left one mirrored) root to tip, the left tip to root.
        out.extend(left.iter().map(|&[x, y]| at([-x, y])));
        out.extend(left.iter().rev().map(|&p| at(p)));
        // The root circle to the next tooth's right flank.
        if let Some(&[x, y]) = left.first() {
            let a0 = y.atan2(x) + turn;
            let a1 = y.atan2(-x) + turn + pitch;
            let r = g.root_radius_m;
            for j in 1..8 {
                let a = a0 + (a1 - a0) * f64::from(j) / 8.0;
                out.push([r * a.cos(), r * a.sin()]);
            }
        }
    }
    out
}

/// The closed inner outline of a ring cut by a pinion cutter of `cutter_teeth`,
/// metres: every space's two cut edges from `per_flank` radii, its root arc at the
/// cut root, and the tip circle's arcs (the bore) between spaces; empty where the
/// cutter cannot cut the ring ([`ShaperCut::new`]).
pub fn ring_outline(ring: &Gear, cutter_teeth: u32, per_flank: usize) -> Vec<[f64; 2]> {
    let right: Vec<[f64; 2]> = shaper_cut_flank(ring, cutter_teeth, per_flank);
    let (Some(&first), Some(&last)) = (right.first(), right.last()) else {
        return Vec::new();
    };
    let z = ring.spec.teeth;
    let pitch = TAU / f64::from(z);
    let arc = |out: &mut Vec<[f64; 2]>, r: f64, a0: f64, a1: f64| {
        for j in 1..8 {
            let a = a0 + (a1 - a0) * f64::from(j) / 8.0;
            out.push([r * a.cos(), r * a.sin()]);
        }
    };
    let mut out = Vec::new();
    for k in 0..z {
        let turn = f64::from(k) * pitch;
        let (s, c) = turn.sin_cos();
        let at = |[x, y]: [f64; 2]| [c * x - s * y, s * x + c * y];
        // The right edge bore to root, across the root, the left edge root to bore.
        out.extend(right.iter().map(|&p| at(p)));
        let r_root = last[0].hypot(last[1]);
        let a_right = last[1].atan2(last[0]) + turn;
        arc(
            &mut out,
            r_root,
            a_right,
            a_right + 2.0 * (FRAC_PI_2 - (a_right - turn)),
        );
        out.extend(right.iter().rev().map(|&[x, y]| at([-x, y])));
        // The bore to the next space's right edge.
        let r_tip = first[0].hypot(first[1]);
        let a_left = (first[1]).atan2(-first[0]) + turn;
        arc(
            &mut out,
            r_tip,
            a_left,
            first[1].atan2(first[0]) + turn + pitch,
        );
    }
    out
}

/// The cut gear as an SVG drawing in millimetres: its outline (a ring's body between
/// its rim and its teeth), the pitch circle dash-dotted, the base circle dotted, and
/// a title with its numbers.
pub fn gear_svg(g: &Gear, outline: &[[f64; 2]]) -> String {
    let mm = |v: f64| v * 1e3;
    // A ring's body: its rim 2.5 modules beyond its cut roots.
    let internal = g.spec.kind == GearKind::Internal;
    let outer = outline.iter().map(|p| p[0].hypot(p[1])).fold(0.0, f64::max);
    let rim = internal.then_some(outer + 2.5 * g.spec.module_m);
    let half = mm(rim.unwrap_or(g.tip_radius_m.max(g.root_radius_m))) * 1.15;
    let size = 2.0 * half;
    let mut out = String::new();
    let _ = writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{size:.2}mm\" height=\"{:.2}mm\" viewBox=\"{:.3} {:.3} {size:.3} {:.3}\">",
        size * 1.1,
        -half,
        -half * 1.2,
        size * 1.1
    );
    let stroke = half / 400.0;
    outline_svg(&mut out, outline, rim, stroke);
    let circle = |out: &mut String, r: f64, dash: &str| {
        let _ = writeln!(
            out,
            "<circle cx=\"0\" cy=\"0\" r=\"{:.4}\" fill=\"none\" stroke=\"#555555\" stroke-width=\"{:.4}\" stroke-dasharray=\"{dash}\"/>",
            mm(r),
            stroke * 0.6
        );
    };
    circle(
        &mut out,
        g.pitch_radius_m,
        &format!(
            "{:.3} {:.3} {:.3} {:.3}",
            8.0 * stroke,
            2.0 * stroke,
            1.0 * stroke,
            2.0 * stroke
        ),
    );
    circle(
        &mut out,
        g.base_radius_m,
        &format!("{:.3} {:.3}", 1.0 * stroke, 2.0 * stroke),
    );
    let s = g.spec;
    let undercut = g.undercut_shift_short().map_or(String::new(), |short| {
        format!(", undercut (x short of x_min by {})", significant(short, 3))
    });
    let _ = writeln!(
        out,
        "<text x=\"{:.3}\" y=\"{:.3}\" font-size=\"{:.3}\" font-family=\"sans-serif\">{}z = {}, m = {} mm, x = {}, α = {}°{undercut}</text>",
        -half,
        -half * 1.08,
        half / 18.0,
        if internal { "internal, " } else { "" },
        s.teeth,
        significant(mm(s.module_m), 4),
        significant(s.shift, 4),
        significant(s.pressure_angle_rad.to_degrees(), 4)
    );
    out.push_str("</svg>\n");
    out
}

/// The outline as an SVG polygon, or for a ring (`rim`, m) a path of its body
/// between the rim and its teeth, filled even-odd.
fn outline_svg(out: &mut String, outline: &[[f64; 2]], rim: Option<f64>, stroke: f64) {
    let mm = |v: f64| v * 1e3;
    let points: Vec<String> = outline
        .iter()
        .map(|&[x, y]| format!("{:.4},{:.4}", mm(x), -mm(y)))
        .collect();
    match rim {
        // The ring's body between its rim and its teeth: one path, even-odd.
        Some(rim) => {
            let r = mm(rim);
            let _ = writeln!(
                out,
                "<path fill-rule=\"evenodd\" d=\"M {} Z M {r:.4},0 A {r:.4},{r:.4} 0 1,0 {:.4},0 A {r:.4},{r:.4} 0 1,0 {r:.4},0 Z\" fill=\"#e8eef7\" stroke=\"#1e5aaa\" stroke-width=\"{stroke:.4}\"/>",
                points.join(" L "),
                -r
            );
        }
        None => {
            let _ = writeln!(
                out,
                "<polygon points=\"{}\" fill=\"#e8eef7\" stroke=\"#1e5aaa\" stroke-width=\"{stroke:.4}\"/>",
                points.join(" ")
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use linkage::gears::GearSpec;
    use std::f64::consts::FRAC_PI_2;

    /// The angle of a point, from the +y axis (the first tooth's middle).
    fn from_top(p: [f64; 2]) -> f64 {
        p[1].atan2(p[0]) - FRAC_PI_2
    }

    /// The outline goes round once: every tooth's points within its pitch, all of
    /// them between the root and the tip circles.
    #[test]
    fn the_outline_is_every_tooth_between_root_and_tip() {
        let g = Gear::new(GearSpec::standard(0.002, 12)).expect("a gear");
        let outline = gear_outline(&g, 40);
        assert!(outline.len() > 12 * 80);
        for p in &outline {
            let r = p[0].hypot(p[1]);
            assert!(
                r >= g.root_radius_m * (1.0 - 1e-12) && r <= g.tip_radius_m * (1.0 + 1e-12),
                "{r}"
            );
        }
        // The first tooth is centred on the y axis: its flanks' angles mirror.
        let first = from_top(outline[0]);
        let last_of_tooth = from_top(outline[79]);
        assert!(
            (first + last_of_tooth).abs() < 1e-12,
            "{first} {last_of_tooth}"
        );
        let svg = gear_svg(&g, &outline);
        assert!(
            svg.contains("z = 12, m = 2 mm, x = 0, α = 20°, undercut"),
            "{}",
            &svg[..400]
        );
    }

    /// A ring cut by a pinion cutter: its outline goes round once, every point
    /// between its tip circle (the bore) and the cut root, each space's edges mirror
    /// images about its middle.
    #[test]
    fn a_rings_outline_is_every_space_between_bore_and_cut_root() {
        use linkage::gears::shaper::ShaperCut;
        let ring = Gear::new(GearSpec::standard(0.002, 60).internal()).expect("a ring");
        let cut = ShaperCut::new(&ring, 25).expect("a cut");
        let outline = ring_outline(&ring, 25, 20);
        let per_space = outline.len() / 60;
        assert_eq!(outline.len(), 60 * per_space);
        for p in &outline {
            let r = p[0].hypot(p[1]);
            assert!(
                r >= ring.tip_radius_m * (1.0 - 1e-12)
                    && r <= cut.cut_root_radius_m * (1.0 + 1e-12),
                "{r}"
            );
        }
        // The first space centred on the y axis: its first and last edge points mirror.
        let (a, b) = (outline[0], outline[2 * 20 + 7 - 1]);
        assert!(
            (a[0] + b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12,
            "{a:?} {b:?}"
        );
        // The angle only grows round the ring.
        let mut turned = 0.0;
        for w in outline.windows(2) {
            let step = (w[1][1].atan2(w[1][0]) - w[0][1].atan2(w[0][0])
                + 3.0 * std::f64::consts::PI)
                .rem_euclid(TAU)
                - std::f64::consts::PI;
            assert!(step > -1e-9, "{w:?}");
            turned += step;
        }
        assert!((turned - TAU).abs() < 0.2, "{turned}");
        assert!(gear_svg(&ring, &outline).contains("fill-rule=\"evenodd\""));
    }
}
