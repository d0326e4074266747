//! Involute spur gears and pairs against closed forms written here, apart from the
//! module's own: the tooth thickness from the involute's parametric form (the roll
//! angle t, polar angle t − atan t), the contact ratio by the textbooks' tangent
//! formula ε = [z₁(tan α_a1 − tan α') ± z₂(tan α_a2 − tan α')]/2π, the shifts' sum from
//! a centre distance by the textbooks' formula, the 17-tooth limit at 20° and its
//! least shift. Random gears and pairs nobody chose (teeth 6..200, shifts −1..1,
//! modules 0.1..50 mm) give finite numbers or a clean refusal.

use std::f64::consts::{FRAC_PI_2, PI};

use linkage::gears::{
    CentreDistance, Gear, GearError, GearKind, GearPair, GearParam, GearSpec, Member, PairIssue,
    PairSpec, least_teeth_without_undercut,
};
use proptest::prelude::*;

const DEG20: f64 = 20.0 * PI / 180.0;

/// The tooth thickness at `rho` from the involute itself: the flank is the involute
/// of the base circle turned so that it crosses the pitch circle at half the tooth's
/// angle; at radius ρ its roll angle is t = √(ρ²/r_b² − 1) and its polar angle
/// t − atan t. An internal gear's space is shaped as an external tooth.
fn thickness_by_involute(g: &Gear, rho: f64) -> f64 {
    let (r, rb) = (g.pitch_radius_m, g.base_radius_m);
    let polar = |radius: f64| {
        let t = (radius * radius / (rb * rb) - 1.0).sqrt();
        t - t.atan()
    };
    let share = 2.0 * PI * rho / f64::from(g.spec.teeth);
    match g.spec.kind {
        GearKind::External => {
            let half_at_base = g.tooth_thickness_m / (2.0 * r) + polar(r);
            2.0 * rho * (half_at_base - polar(rho))
        }
        GearKind::Internal => {
            let half_space_at_base = g.space_width_m / (2.0 * r) + polar(r);
            share - 2.0 * rho * (half_space_at_base - polar(rho))
        }
    }
}

fn pair(pinion: GearSpec, wheel: GearSpec) -> GearPair {
    let spec = PairSpec {
        pinion,
        wheel,
        centre: CentreDistance::FromShifts,
    };
    GearPair::new(spec).expect("a pair that meshes")
}

/// The textbooks' contact ratio: external ε = [z₁(tan α_a1 − tan α') + z₂(tan α_a2 −
/// tan α')]/2π, internal with the wheel's term subtracted.
fn textbook_contact_ratio(p: &GearPair) -> f64 {
    let aw = p.working_pressure_angle_rad;
    let term = |g: &Gear| {
        let alpha_a = (g.base_radius_m / g.tip_radius_m).acos();
        f64::from(g.spec.teeth) * (alpha_a.tan() - aw.tan())
    };
    let wheel = if p.internal {
        -term(&p.wheel)
    } else {
        term(&p.wheel)
    };
    (term(&p.pinion) + wheel) / (2.0 * PI)
}

#[test]
fn a_standard_pairs_circles_and_contact_ratio_are_the_textbooks() {
    let m = 0.004;
    let p = pair(GearSpec::standard(m, 20), GearSpec::standard(m, 50));
    assert!((p.pinion.pitch_radius_m - 0.040).abs() < 1e-15);
    assert!((p.wheel.tip_radius_m - (0.100 + m)).abs() < 1e-15);
    assert!((p.wheel.root_radius_m - (0.100 - 1.25 * m)).abs() < 1e-15);
    assert!((p.centre_m - 0.140).abs() < 1e-15);
    assert!((p.working_pressure_angle_rad - DEG20).abs() < 1e-14);
    let eps = textbook_contact_ratio(&p);
    assert!(
        (p.contact_ratio - eps).abs() < 1e-12,
        "{} vs {eps}",
        p.contact_ratio
    );
    // z = 20 and 50 at 20°: ε ≈ 1.66 (the textbooks' chart).
    assert!((1.6..1.7).contains(&p.contact_ratio));
    assert!((p.speed_ratio + 0.4).abs() < 1e-15);
    for c in p.clearances_m {
        assert!((c - 0.25 * m).abs() < 1e-15);
    }
    assert!(p.issues.is_empty(), "{:?}", p.issues);
}

/// Shifted pairs, external and internal: on the working pitch circles the two teeth
/// fill the pitch exactly (no backlash) by the involute's own geometry.
#[test]
fn shifted_pairs_mesh_without_backlash_by_the_involutes_geometry() {
    let m = 0.003;
    let cases = [
        (17, 0.4, 41, 0.3, GearKind::External),
        (12, 0.5, 27, -0.2, GearKind::External),
        (25, -0.3, 40, 0.3, GearKind::External),
        (20, 0.3, 64, 0.1, GearKind::Internal),
        (18, 0.0, 50, 0.0, GearKind::Internal),
        (22, -0.2, 61, 0.4, GearKind::Internal),
    ];
    for (z1, x1, z2, x2, kind) in cases {
        let wheel = GearSpec {
            kind,
            ..GearSpec::standard(m, z2).shifted(x2)
        };
        let p = pair(GearSpec::standard(m, z1).shifted(x1), wheel);
        let [r1, r2] = p.working_pitch_radii_m;
        assert!((r2 - r1 - p.centre_m).abs() < 1e-14 || (r1 + r2 - p.centre_m).abs() < 1e-14);
        let pitch = 2.0 * PI * r1 / f64::from(z1);
        let s1 = thickness_by_involute(&p.pinion, r1);
        let s2 = thickness_by_involute(&p.wheel, r2);
        let gap = pitch - s1 - s2;
        assert!(gap.abs() < 1e-12 * m, "{z1}/{z2} {kind:?}: gap {gap:e}");
        assert!(p.backlash_m.abs() < 1e-12 * m);
        let eps = textbook_contact_ratio(&p);
        assert!(
            (p.contact_ratio - eps).abs() < 1e-11,
            "{} vs {eps}",
            p.contact_ratio
        );
    }
}

/// The module's tooth thickness at any radius is the involute's.
#[test]
fn tooth_thickness_at_any_radius_is_the_involutes() {
    for (z, x, kind) in [
        (9, 0.6, GearKind::External),
        (31, -0.4, GearKind::External),
        (57, 0.2, GearKind::Internal),
    ] {
        let g = Gear::new(GearSpec {
            kind,
            ..GearSpec::standard(0.002, z).shifted(x)
        })
        .expect("a gear");
        let (lo, hi) = (
            g.base_radius_m * 1.0001,
            g.tip_radius_m.max(g.root_radius_m),
        );
        for k in 0..=50 {
            let rho = lo + (hi - lo) * f64::from(k) / 50.0;
            let ours = g.tooth_thickness_at(rho).expect("outside the base circle");
            let theirs = thickness_by_involute(&g, rho);
            assert!(
                (ours - theirs).abs() < 1e-13 * g.pitch_radius_m,
                "z {z} at {rho}: {ours} vs {theirs}"
            );
        }
    }
}

/// A centre distance given: the working pressure angle from cos α' = a cos α / a', the
/// shifts' sum from x₁ + x₂ = (z₁ + z₂)(inv α' − inv α)/(2 tan α); with that sum the
/// pair has no backlash, with less it has some, with more it jams.
#[test]
fn a_centre_distance_given_asks_the_textbooks_shift_sum() {
    let (m, z1, z2) = (0.002, 14, 31);
    let a = 0.5 * m * f64::from(z1 + z2);
    let given = a + 0.4 * m;
    let alpha_w = (a * DEG20.cos() / given).acos();
    let inv = |x: f64| x.tan() - x;
    let sum = f64::from(z1 + z2) * (inv(alpha_w) - inv(DEG20)) / (2.0 * DEG20.tan());
    let at = |x1: f64, x2: f64| {
        GearPair::new(PairSpec {
            pinion: GearSpec::standard(m, z1).shifted(x1),
            wheel: GearSpec::standard(m, z2).shifted(x2),
            centre: CentreDistance::Given { centre_m: given },
        })
    };
    let p = at(0.3, sum - 0.3).expect("the shifts fit");
    assert!((p.working_pressure_angle_rad - alpha_w).abs() < 1e-14);
    assert!((p.shift_sum_without_backlash - sum).abs() < 1e-12);
    assert!(p.backlash_m < 1e-12 * m);
    assert!((p.centre_modification - 0.4).abs() < 1e-12);
    let loose = at(0.3, sum - 0.4).expect("thinner teeth fit");
    assert!(loose.backlash_m > 0.05 * m);
    let jam = at(0.3, sum - 0.2).expect_err("thicker teeth jam");
    assert!(matches!(jam, GearError::TeethJam { .. }), "{jam}");
    // Standard gears at the larger distance: they mesh, with backlash.
    let standard = at(0.0, 0.0).expect("standard gears fit a larger distance");
    assert!(standard.backlash_m > 0.1 * m);
    let below = GearPair::new(PairSpec {
        pinion: GearSpec::standard(m, z1),
        wheel: GearSpec::standard(m, z2),
        centre: CentreDistance::Given { centre_m: 0.9 * a },
    })
    .expect_err("inside the base circles' distance");
    assert!(matches!(below, GearError::CentreDistance { .. }));
    assert!(below.to_string().contains("outside the range"), "{below}");
}

/// z_min = 2 h_a*/sin²α: 17 at 20° as the textbooks round it, 32 at 14.5°; below it
/// a rack cutter undercuts, and the least shift x_min = h_a* − z sin²α/2 cures it.
#[test]
fn seventeen_teeth_at_twenty_degrees_and_the_least_shift() {
    let z_min = least_teeth_without_undercut(1.0, DEG20);
    assert_eq!(z_min.round(), 17.0);
    assert!((z_min - 2.0 / DEG20.sin().powi(2)).abs() < 1e-12);
    assert_eq!(
        least_teeth_without_undercut(1.0, 14.5f64.to_radians()).round(),
        32.0
    );
    let g = Gear::new(GearSpec::standard(0.001, 12)).expect("a gear");
    let x_min = g.least_shift_without_undercut();
    assert!((x_min - (1.0 - 6.0 * DEG20.sin().powi(2))).abs() < 1e-15);
    // The textbooks' rounded form (17 − z)/17 within its rounding.
    assert!((x_min - 5.0 / 17.0).abs() < 0.01);
    assert!(
        g.undercut_shift_short()
            .is_some_and(|s| (s - x_min).abs() < 1e-15)
    );
    let cured = Gear::new(GearSpec::standard(0.001, 12).shifted(x_min)).expect("a gear");
    assert_eq!(cured.undercut_shift_short(), None);
    let p = pair(GearSpec::standard(0.001, 12), GearSpec::standard(0.001, 40));
    assert!(p.issues.iter().any(|i| matches!(
        i,
        PairIssue::Undercut {
            member: Member::Pinion,
            ..
        }
    )));
}

/// A small gear shifted far comes to a point: its tip thickness (the involute's)
/// is negative, and the pair says so.
#[test]
fn a_pointed_tip_is_found() {
    let g = Gear::new(GearSpec::standard(0.001, 8).shifted(0.9)).expect("a gear");
    let tip = thickness_by_involute(&g, g.tip_radius_m);
    assert!(tip < 0.0, "{tip}");
    assert!(g.is_pointed());
    let fine = Gear::new(GearSpec::standard(0.001, 30).shifted(0.2)).expect("a gear");
    assert!(!fine.is_pointed());
    assert!(fine.tip_thickness_m().is_some_and(|s| s > 0.4 * 0.001));
}

#[test]
fn refusals_name_the_gear_the_number_and_its_range() {
    let bad = GearPair::new(PairSpec {
        pinion: GearSpec::standard(0.002, 20),
        wheel: GearSpec::standard(0.002, 40).shifted(f64::NAN),
        centre: CentreDistance::FromShifts,
    })
    .expect_err("a NaN shift");
    assert!(matches!(
        bad,
        GearError::OutOfRange {
            member: Some(Member::Wheel),
            param: GearParam::Shift,
            ..
        }
    ));
    assert!(
        bad.to_string()
            .starts_with("wheel: profile shift coefficient x NaN is outside the range -3 … 3"),
        "{bad}"
    );
    let zero = Gear::new(GearSpec::standard(0.0, 20)).expect_err("no module");
    assert!(
        zero.to_string()
            .contains("module (m) 0 is outside the range"),
        "{zero}"
    );
    let ring = GearPair::new(PairSpec {
        pinion: GearSpec::standard(0.002, 30),
        wheel: GearSpec::standard(0.002, 30).internal(),
        centre: CentreDistance::FromShifts,
    })
    .expect_err("a ring no larger than its pinion");
    assert_eq!(
        ring,
        GearError::RingTooSmall {
            pinion: 30,
            wheel: 30,
            least: 31
        }
    );
    let mixed = GearPair::new(PairSpec {
        pinion: GearSpec::standard(0.002, 30),
        wheel: GearSpec::standard(0.0025, 40),
        centre: CentreDistance::FromShifts,
    })
    .expect_err("two modules");
    assert!(matches!(mixed, GearError::Mismatched { .. }));
    let rimless = Gear::new(GearSpec::standard(0.002, 6).shifted(-2.5)).expect_err("no rim");
    assert!(matches!(rimless, GearError::NoRim { .. }), "{rimless}");
}

fn cases() -> u32 {
    std::env::var("LINKAGE_PROPERTY_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(512)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    /// Gears and pairs nobody chose: a pair is made with finite numbers everywhere,
    /// or refused with words.
    #[test]
    fn random_pairs_are_finite_or_refused(
        module_mm in 0.1f64..50.0,
        z1 in 6u32..200,
        z2 in 6u32..200,
        x1 in -1.0f64..1.0,
        x2 in -1.0f64..1.0,
        internal in any::<bool>(),
        angle_deg in prop::sample::select(vec![14.5, 20.0, 25.0]),
    ) {
        let spec = |z: u32, x: f64| GearSpec {
            pressure_angle_rad: f64::to_radians(angle_deg),
            ..GearSpec::standard(module_mm * 1e-3, z).shifted(x)
        };
        let wheel = if internal { spec(z2, x2).internal() } else { spec(z2, x2) };
        match GearPair::new(PairSpec { pinion: spec(z1, x1), wheel, centre: CentreDistance::FromShifts }) {
            Ok(p) => {
                let numbers = [
                    p.centre_m, p.working_pressure_angle_rad, p.contact_ratio,
                    p.path_of_contact_m, p.backlash_m, p.clearances_m[0], p.clearances_m[1],
                    p.working_pitch_radii_m[0], p.working_pitch_radii_m[1], p.speed_ratio,
                ];
                prop_assert!(numbers.iter().all(|v| v.is_finite()), "{p:?}");
                prop_assert!(p.centre_m > 0.0);
                prop_assert!(p.backlash_m.abs() < 1e-9 * module_mm * 1e-3);
            }
            Err(e) => prop_assert!(!e.to_string().is_empty()),
        }
    }
}

/// The tooth as a rack cutter cuts it, from the cutter's lines alone: from the form
/// circle up it is the involute to round-off where the shift is at least x_min (20
/// teeth, 40 teeth shifted −0.5, 12 teeth with the least shift); where it is not (12
/// and 8 teeth unshifted) the cutter's tip undercuts it just above the base circle.
/// The form circle is where the cutter's straight flank ends, h_a*·m below its datum
/// line: its contact on the line of action is (h_a* − x)·m / sin α from the pitch
/// point, r sin α − that from the base circle's tangent point N.
#[test]
fn the_cut_tooth_is_the_involute_unless_undercut() {
    use linkage::gears::generation::cut_tooth_thickness_at;
    let m = 0.002;
    let twelve = Gear::new(GearSpec::standard(m, 12)).expect("a gear");
    // (teeth, shift, undercut)
    let cases = [
        (20, 0.0, false),
        (40, -0.5, false),
        (12, twelve.least_shift_without_undercut(), false),
        (12, 0.0, true),
        (8, 0.0, true),
    ];
    for (z, x, undercut) in cases {
        let g = Gear::new(GearSpec::standard(m, z).shifted(x)).expect("a gear");
        let from_n = g.pitch_radius_m * DEG20.sin() - (1.0 - x) * m / DEG20.sin();
        assert_eq!(from_n < -1e-12, undercut, "z {z} x {x}: {from_n}");
        let lo = if undercut {
            g.base_radius_m
        } else {
            g.base_radius_m.hypot(from_n)
        };
        let hi = g.tip_radius_m;
        let mut thinnest = 0.0_f64;
        for k in 1..=40 {
            // Closer together near the base circle, where an undercut is (a few
            // hundredths of a millimetre deep for 12 teeth of 2 mm).
            let rho = lo + (hi - lo) * (f64::from(k) / 40.0).powi(2);
            let cut = cut_tooth_thickness_at(&g, rho).expect("a radius on the tooth");
            let involute = thickness_by_involute(&g, rho);
            let short = (involute - cut) / m;
            thinnest = thinnest.max(short);
            if !undercut {
                assert!(
                    short.abs() < 1e-10,
                    "z {z} x {x} at {rho}: cut {cut} vs involute {involute}"
                );
            }
        }
        if undercut {
            assert!(thinnest > 1e-3, "z {z}: no undercut found ({thinnest:e})");
        }
    }
}

/// Cut profiles of gears nobody chose (teeth 6..200, shifts −1..1, pressure angles
/// 14.5° to 30°, where the rack's tip fillets are narrowed to fit above 22.4°): every
/// point finite and between the root and the tip circles; above 32.1° the rack is
/// pointed and there is no profile.
#[test]
fn cut_profiles_of_random_gears_are_finite() {
    use linkage::gears::generation::cut_flank;
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..60 {
        let z = 6 + (next() * 194.0) as u32;
        let x = -1.0 + 2.0 * next();
        let angle = [14.5, 20.0, 25.0, 30.0][(next() * 4.0) as usize % 4];
        let spec = GearSpec {
            pressure_angle_rad: f64::to_radians(angle),
            ..GearSpec::standard(0.002, z).shifted(x)
        };
        let Ok(g) = Gear::new(spec) else { continue };
        for p in cut_flank(&g, 30) {
            let r = p[0].hypot(p[1]);
            assert!(
                p.iter().all(|v| v.is_finite()),
                "z {z} x {x} α {angle}: {p:?}"
            );
            assert!(
                r > g.root_radius_m && r <= g.tip_radius_m * (1.0 + 1e-12),
                "z {z} x {x} α {angle}: {r}"
            );
        }
    }
    let steep = Gear::new(GearSpec {
        pressure_angle_rad: 34f64.to_radians(),
        ..GearSpec::standard(0.002, 30)
    })
    .expect("a gear");
    assert!(cut_flank(&steep, 10).is_empty());
}

/// The rack cutter as drawn is the cutter that cuts: at no position does it reach
/// into the cut tooth (its fillets drawn by chords, inside the arcs), and every point
/// of the cut flank is touched by some position, to a fine grid's step: the tooth is
/// the envelope of the cutter drawn, at 12 teeth with and without undercut and at 40.
#[test]
fn the_cutter_drawn_envelopes_the_cut_tooth() {
    let m = 0.01;
    for (z, x) in [(12u32, 0.0), (12, 0.3), (40, 0.0)] {
        let g = Gear::new(GearSpec::standard(m, z).shifted(x)).expect("gear");
        // The flank as cut_flank gives it, its tooth's middle on the y axis, turned
        // back by 180°/z to where the cutter's middle tooth cut it.
        let (sin, cos) = (-std::f64::consts::PI / f64::from(z)).sin_cos();
        let flank: Vec<[f64; 2]> = linkage::gears::generation::cut_flank(&g, 40)
            .into_iter()
            .map(|[x, y]| [x * cos - y * sin, x * sin + y * cos])
            .collect();
        let steps = 1500;
        let reach = 3.0 * std::f64::consts::PI / f64::from(z);
        let mut nearest = vec![f64::INFINITY; flank.len()];
        for k in 0..=steps {
            let phi = -reach + 2.0 * reach * k as f64 / steps as f64;
            let parts = linkage::gears::generation::cutter_outline(&g, phi, 2, 32).expect("a rack");
            for tooth in &parts {
                for (i, p) in flank.iter().enumerate() {
                    let depth = inside_depth(tooth, *p);
                    assert!(
                        depth <= 1e-9 * m,
                        "z {z} x {x}: {depth} inside at {p:?}, phi {phi}"
                    );
                    nearest[i] = nearest[i].min(-depth);
                }
            }
        }
        let worst = nearest.iter().fold(0.0_f64, |a, &b| a.max(b));
        assert!(
            worst <= 2e-3 * m,
            "z {z} x {x}: a flank point {worst} m from every position"
        );
    }
}

/// How far `p` is inside the counter-clockwise convex polygon (negative: its
/// distance outside, to the nearest edge's line where that is the nearest).
fn inside_depth(polygon: &[[f64; 2]], p: [f64; 2]) -> f64 {
    let n = polygon.len();
    let mut depth = f64::INFINITY;
    let mut outside = 0.0_f64;
    for i in 0..n {
        let (a, b) = (polygon[i], polygon[(i + 1) % n]);
        let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
        let len = ex.hypot(ey);
        if len == 0.0 {
            continue;
        }
        // Signed distance to the edge's line, positive inside.
        let d = (ex * (p[1] - a[1]) - ey * (p[0] - a[0])) / len;
        depth = depth.min(d);
        if d < 0.0 {
            // Outside this edge: the distance to the segment.
            let t = (((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / (len * len)).clamp(0.0, 1.0);
            let q = [a[0] + t * ex - p[0], a[1] + t * ey - p[1]];
            outside = outside.max(q[0].hypot(q[1]));
        }
    }
    if depth >= 0.0 { depth } else { -outside }
}

/// An internal gear cut by a pinion cutter (a gear shaper) is the involute ring
/// from its tip circle to where the cutter's tip corner takes over: its tooth
/// thickness at every radius there equals the involute's, written out in
/// `thickness_by_involute` from the ring's space width, for unshifted and shifted
/// rings and cutters of several sizes; the cut root is the cutting centre distance
/// plus the cutter's tip radius, with a₀ from inv α₀' = inv α − 2 tan α x₂/(z₂ − z_c)
/// (ISO 21771's signs: a positive x₂ thickens the ring's teeth) written here (a₀ = r₂ − r_c unshifted); where the ring's tip lies inside the circle
/// through the cutter's tangent point N_c, its tips are trimmed.
#[test]
fn a_ring_cut_by_a_pinion_cutter_is_the_involute() {
    use linkage::gears::shaper::{ShaperCut, shaper_cut_tooth_thickness_at};
    let m = 0.002;
    // The last: a small cutter in a ring shifted inwards, whose tip then lies inside
    // the circle through N_c: its tips are trimmed.
    let mut trimmed = 0;
    for (z2, x2, zc) in [
        (60, 0.0, 25),
        (80, 0.0, 20),
        (60, 0.4, 25),
        (72, -0.3, 30),
        (45, 0.2, 16),
        (60, -0.4, 12),
    ] {
        let ring = Gear::new(GearSpec::standard(m, z2).shifted(x2).internal()).expect("a ring");
        let cut = ShaperCut::new(&ring, zc).expect("a cut");
        let alpha = DEG20;
        let inv = |a: f64| a.tan() - a;
        let target = inv(alpha) - 2.0 * alpha.tan() * x2 / f64::from(z2 - zc);
        // inv⁻¹ by Newton from α (inv' = tan²).
        let mut working = alpha;
        for _ in 0..50 {
            working -= (inv(working) - target) / working.tan().powi(2);
        }
        let a0 = 0.5 * f64::from(z2 - zc) * m * alpha.cos() / working.cos();
        assert!(
            (cut.centre_m - a0).abs() < 1e-14,
            "{z2}/{zc}: {} vs {a0}",
            cut.centre_m
        );
        if x2 == 0.0 {
            assert!((a0 - 0.5 * m * f64::from(z2 - zc)).abs() < 1e-15);
        }
        let r_ac = 0.5 * m * f64::from(zc) + 1.25 * m;
        assert!((cut.cut_root_radius_m - (a0 + r_ac)).abs() < 1e-15);
        // The involute part: from the tip circle to the point the cutter's tip
        // corner generates, on the line of action |N₂K| = √(r_ac² − r_bc²) from the
        // cutter's tangent point N_c, whose ring radius is √(r_b2² + (N₂N_c + that)²).
        let (rb2, rbc) = (ring.base_radius_m, cut.cutter_base_radius_m);
        let nn = (a0 * a0 - (rb2 - rbc).powi(2)).sqrt();
        let form = rb2.hypot(nn + (r_ac * r_ac - rbc * rbc).sqrt());
        // Below the circle through the cutter's tangent point N_c the ring's involute
        // cannot be generated (its contact would lie past N_c): there the cutter's
        // flank below its base circle trims the ring's tips (a shifted ring's tip moves
        // inside it), thinner than the involute.
        let n_c = rb2.hypot(nn);
        if ring.tip_radius_m < n_c {
            let rho = 0.5 * (ring.tip_radius_m + n_c);
            let cut_s = shaper_cut_tooth_thickness_at(&ring, zc, rho).expect("a radius");
            let short = (thickness_by_involute(&ring, rho) - cut_s) / m;
            assert!(
                short > 1e-3,
                "{z2} x {x2} by {zc}: tips not trimmed ({short:e})"
            );
            trimmed += 1;
        }
        let (lo, hi) = (ring.tip_radius_m.max(n_c), form);
        assert!(lo < hi, "{z2}/{zc}: {lo} {hi}");
        for k in 0..=30 {
            let rho = lo + (hi - lo) * (0.002 + 0.996 * f64::from(k) / 30.0);
            let cut_s =
                shaper_cut_tooth_thickness_at(&ring, zc, rho).expect("a radius on the ring");
            let involute = thickness_by_involute(&ring, rho);
            assert!(
                ((cut_s - involute) / m).abs() < 1e-10,
                "{z2} x {x2} by {zc} at {rho}: cut {cut_s} vs involute {involute}"
            );
        }
    }
    assert!(trimmed >= 1, "a trimmed ring was checked");
}

/// Rings and pinion cutters nobody chose (ring teeth 20..200, cutters 3 to the
/// ring's, shifts −1..1, modules 0.1..50 mm): no panic, every edge finite and right
/// of the space's middle, or no cut at all (a cutter as large as the
/// ring, a shift with no working angle), never a non-finite number.
#[test]
fn shaper_cuts_of_random_rings_are_finite() {
    use linkage::gears::shaper::{ShaperCut, shaper_cut_edge_angle};
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut cut_some = 0;
    for _ in 0..60 {
        let z2 = 20 + (next() * 180.0) as u32;
        let zc = 3 + (next() * f64::from(z2)) as u32;
        let x2 = -1.0 + 2.0 * next();
        let m = 1e-4 * 500f64.powf(next());
        let Ok(ring) = Gear::new(GearSpec::standard(m, z2).shifted(x2).internal()) else {
            continue;
        };
        let Some(cut) = ShaperCut::new(&ring, zc) else {
            continue;
        };
        assert!(cut.centre_m.is_finite() && cut.cut_root_radius_m > ring.tip_radius_m);
        for k in 0..6 {
            let rho = ring.tip_radius_m
                + (cut.cut_root_radius_m - ring.tip_radius_m) * (0.05 + 0.9 * f64::from(k) / 5.0);
            if let Some(edge) = shaper_cut_edge_angle(&ring, zc, rho) {
                // Never past the space's middle (the cutter's tooth is there); past
                // the tooth's middle, 90° − 180°/z₂ − 180°/z₂, where a cutter nearly as
                // large as the ring cuts its teeth away.
                assert!(
                    edge.is_finite() && edge <= FRAC_PI_2 + 1e-12,
                    "{z2}/{zc} x {x2} m {m} at {rho}: {edge}"
                );
                cut_some += 1;
            }
        }
    }
    assert!(cut_some > 100, "{cut_some} edges found");
}

/// The tip thickness, s_a = r_a (s/r + 2(inv α − inv α_a)) written out, against the
/// textbooks' least 0.25·m: a gear shifted out step by step is said to have thin tips
/// exactly where s_a falls below it and is still positive, and pointed past that;
/// a pair says so of the gear it concerns.
#[test]
fn thin_tips_are_said_where_the_tip_is_under_a_quarter_module() {
    let m = 0.002;
    let inv = |a: f64| a.tan() - a;
    let mut seen_thin = 0;
    for z in [10, 12, 17, 30] {
        for k in 0..=30 {
            let x = -0.2 + 0.05 * f64::from(k);
            let g = Gear::new(GearSpec::standard(m, z).shifted(x)).expect("a gear");
            let (r, ra) = (g.pitch_radius_m, g.tip_radius_m);
            let s = m * (PI / 2.0 + 2.0 * x * DEG20.tan());
            let alpha_a = (r * DEG20.cos() / ra).acos();
            let sa = ra * (s / r + 2.0 * (inv(DEG20) - inv(alpha_a)));
            let thin = sa > 0.0 && sa < 0.25 * m;
            assert_eq!(g.thin_tip_m().is_some(), thin, "z {z} x {x}: s_a {sa}");
            assert_eq!(g.is_pointed(), sa <= 0.0, "z {z} x {x}: s_a {sa}");
            if let Some(t) = g.thin_tip_m() {
                assert!((t - sa).abs() < 1e-12 * m, "{t} vs {sa}");
                seen_thin += 1;
            }
        }
    }
    assert!(seen_thin >= 3, "{seen_thin} thin tips seen");
    // A 12-tooth pinion shifted 0.75 with a 40-tooth wheel: the pinion's tip, cut
    // short by Δy·m, is thin; the pair says so of the pinion.
    let p = pair(
        GearSpec::standard(m, 12).shifted(0.75),
        GearSpec::standard(m, 40),
    );
    let thin: Vec<_> = p
        .issues
        .iter()
        .filter(|i| matches!(i, PairIssue::ThinTip { .. }))
        .collect();
    let sa = p.pinion.tip_thickness_m().expect("a tip");
    assert!(sa > 0.0 && sa < 0.25 * m, "the cut tip {sa}");
    assert!(
        matches!(thin.as_slice(), [PairIssue::ThinTip { member: Member::Pinion, thickness_m, .. }] if (thickness_m - sa).abs() < 1e-15),
        "{:?}",
        p.issues
    );
}
