//! A pair in mesh as the app draws it: both cut outlines (`gear_outline`) turned as
//! `MeshPose` says. At every turn over a base pitch, the teeth touch at the contact
//! points the pose gives (each on both outlines) and nowhere reach into each other;
//! the number of teeth in contact, averaged over the turn, is the pair's contact
//! ratio (an independent check of ε: counting against the tangent formula).

use linkage::gears::{CentreDistance, GearPair, GearSpec, MeshPose, PairSpec};
use linkage_diagram::gear_profile::gear_outline;

fn turned(points: &[[f64; 2]], turn: f64, centre: [f64; 2]) -> Vec<[f64; 2]> {
    let (s, c) = turn.sin_cos();
    points
        .iter()
        .map(|&[x, y]| [centre[0] + c * x - s * y, centre[1] + s * x + c * y])
        .collect()
}

/// The distance from `p` to the closed polyline.
fn distance(polyline: &[[f64; 2]], p: [f64; 2]) -> f64 {
    let n = polyline.len();
    (0..n)
        .map(|i| {
            let (a, b) = (polyline[i], polyline[(i + 1) % n]);
            let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
            let len2 = (ex * ex + ey * ey).max(f64::MIN_POSITIVE);
            let t = (((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / len2).clamp(0.0, 1.0);
            (a[0] + t * ex - p[0]).hypot(a[1] + t * ey - p[1])
        })
        .fold(f64::INFINITY, f64::min)
}

/// Whether `p` is inside the closed polygon (winding by crossings).
fn inside(polygon: &[[f64; 2]], p: [f64; 2]) -> bool {
    let n = polygon.len();
    let mut odd = false;
    for i in 0..n {
        let (a, b) = (polygon[i], polygon[(i + 1) % n]);
        if (a[1] > p[1]) != (b[1] > p[1]) {
            let x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if x > p[0] {
                odd = !odd;
            }
        }
    }
    odd
}

#[test]
fn a_pair_drawn_in_mesh_touches_at_its_contacts_and_nowhere_overlaps() {
    let m = 0.01;
    for (z1, z2, x1, x2) in [(12, 40, 0.3, 0.2), (20, 30, 0.0, 0.0), (17, 17, 0.5, -0.2)] {
        let pair = GearPair::new(PairSpec {
            pinion: GearSpec::standard(m, z1).shifted(x1),
            wheel: GearSpec::standard(m, z2).shifted(x2),
            centre: CentreDistance::FromShifts,
        })
        .expect("a pair");
        let (p_out, w_out) = (
            gear_outline(&pair.pinion, 60),
            gear_outline(&pair.wheel, 60),
        );
        let steps = 200;
        let pitch_turn = pair.pinion.base_pitch_m / pair.pinion.base_radius_m;
        let mut touching = 0usize;
        for k in 0..steps {
            let turn = pitch_turn * k as f64 / steps as f64;
            let pose = MeshPose::at(&pair, turn).expect("external");
            touching += pose.contacts.len();
            // The outlines at every tenth turn (a check costs the outlines' size
            // squared near the pitch point).
            if k % 10 != 0 {
                continue;
            }
            let pinion = turned(&p_out, pose.pinion_turn_rad, [0.0, 0.0]);
            let wheel = turned(&w_out, pose.wheel_turn_rad, pose.wheel_centre_m);
            for c in &pose.contacts {
                for (name, outline) in [("pinion", &pinion), ("wheel", &wheel)] {
                    let d = distance(outline, *c);
                    assert!(d <= 2e-3 * m, "{z1}/{z2}: contact {d} m off the {name}");
                }
            }
            // Reaching in deeper than the outlines' chords allow is an overlap; only
            // the teeth within three modules of the pitch point can meet.
            let pitch_point = [0.0, pair.working_pitch_radii_m[0]];
            let near =
                |q: &&[f64; 2]| (q[0] - pitch_point[0]).hypot(q[1] - pitch_point[1]) < 3.0 * m;
            for (a, b) in [(&pinion, &wheel), (&wheel, &pinion)] {
                for &q in a.iter().filter(near) {
                    if inside(b, q) {
                        let depth = distance(b, q);
                        assert!(
                            depth <= 2e-3 * m,
                            "{z1}/{z2}: overlap {depth} m at turn {turn}"
                        );
                    }
                }
            }
        }
        let mean = touching as f64 / steps as f64;
        assert!(
            (mean - pair.contact_ratio).abs() <= 1.5 / steps as f64,
            "{z1}/{z2}: {mean} teeth in contact on average, ε = {}",
            pair.contact_ratio
        );
    }
}
