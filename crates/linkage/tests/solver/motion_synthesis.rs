//! Three-position motion generation, checked against independent references: the
//! coupler of a known four-bar, taken at three crank angles, gives back its fixed
//! pivots when its own joints are chosen as the moving pivots; and any design moves
//! its body through the three positions when its scene is solved by the general
//! solver (1e-9). Four positions put the known fixed pivots on the centre-point
//! curve with their moving pivots as circle points, and five give them back among
//! the Burmester points; the designs move the body through every position (1e-9).

use linkage::synthesis::burmester::{
    Crank, burmester_points, centre_condition, centre_curve, circle_point, four_bar_of,
    four_positions,
};
use linkage::synthesis::motion::{BodyPose, pole, three_positions};
use linkage::{DesignRefusal, LinkageError, Vec2};

/// The known four-bar (A0 at the origin, B0 at (1, 0); crank 0.4, coupler 0.9,
/// rocker 0.7) at crank angle θ: its joints A and B (B above the line A→B0).
fn joints(theta: f64) -> (Vec2, Vec2) {
    let (a, b, c, d) = (0.4, 0.9, 0.7, 1.0);
    let pa = Vec2::new(a * theta.cos(), a * theta.sin());
    let to_b0 = Vec2::new(d, 0.0) - pa;
    let dist = to_b0.norm();
    let along = (b * b - c * c + dist * dist) / (2.0 * dist);
    let up = (b * b - along * along).sqrt();
    let u = to_b0 / dist;
    (pa, pa + along * u + up * Vec2::new(-u.y, u.x))
}

/// The coupler's position at crank angle θ, its reference point at (0.3, 0.2) in a
/// frame at A along A→B.
fn coupler_pose(theta: f64) -> BodyPose {
    let (a, b) = joints(theta);
    let angle = (b - a).y.atan2((b - a).x);
    let (s, c) = angle.sin_cos();
    let at = a + Vec2::new(c * 0.3 - s * 0.2, s * 0.3 + c * 0.2);
    BodyPose {
        at: [at.x, at.y],
        angle_rad: angle,
    }
}

fn close(what: &str, x: f64, y: f64) {
    assert!((x - y).abs() <= 1e-9, "{what}: {x} vs {y}");
}

#[test]
fn a_known_coupler_in_three_positions_gives_back_its_fixed_pivots() {
    let poses = [40.0f64, 65.0, 95.0].map(|t| coupler_pose(t.to_radians()));
    // A and B in the body frame: the same in every position.
    let (a, b) = joints(40f64.to_radians());
    let back = |p: Vec2| {
        let (s, c) = poses[0].angle_rad.sin_cos();
        let d = p - Vec2::new(poses[0].at[0], poses[0].at[1]);
        [c * d.x + s * d.y, -s * d.x + c * d.y]
    };
    let design = three_positions(poses, [back(a), back(b)]).expect("designs");
    close("A0 x", design.fixed[0][0], 0.0);
    close("A0 y", design.fixed[0][1], 0.0);
    close("B0 x", design.fixed[1][0], 1.0);
    close("B0 y", design.fixed[1][1], 0.0);
    let checked = design.check().expect("moves");
    let (miss_m, miss_rad) = (checked.miss_m, checked.miss_rad);
    assert!(
        miss_m < 1e-9 && miss_rad < 1e-9,
        "{miss_m} m, {miss_rad} rad"
    );
}

#[test]
fn any_design_moves_its_body_through_the_three_positions() {
    let poses = [
        BodyPose {
            at: [0.0, 0.0],
            angle_rad: 0.0,
        },
        BodyPose {
            at: [0.2, 0.1],
            angle_rad: 20f64.to_radians(),
        },
        BodyPose {
            at: [0.35, 0.3],
            angle_rad: 45f64.to_radians(),
        },
    ];
    let design = three_positions(poses, [[-0.1, -0.15], [0.15, -0.1]]).expect("designs");
    // Each fixed pivot is as far from its moving pivot in every position.
    for (k, m) in design.moving.iter().enumerate() {
        let f = Vec2::new(design.fixed[k][0], design.fixed[k][1]);
        let r: Vec<f64> = poses
            .iter()
            .map(|p| (p.place(Vec2::new(m[0], m[1])) - f).norm())
            .collect();
        close("radius 2", r[1], r[0]);
        close("radius 3", r[2], r[0]);
    }
    let checked = design.check().expect("moves");
    let (miss_m, miss_rad) = (checked.miss_m, checked.miss_rad);
    assert!(
        miss_m < 1e-9 && miss_rad < 1e-9,
        "{miss_m} m, {miss_rad} rad"
    );
    // The pole of 1→2 stays where it is.
    let p12 = pole(&poses[0], &poses[1]).expect("a rotation");
    let moved = poses[1].place({
        let (s, c) = poses[0].angle_rad.sin_cos();
        let d = p12 - Vec2::new(poses[0].at[0], poses[0].at[1]);
        Vec2::new(c * d.x + s * d.y, -s * d.x + c * d.y)
    });
    close("pole x", moved.x, p12.x);
    close("pole y", moved.y, p12.y);
}

#[test]
fn a_translation_has_no_pole_and_bad_input_is_refused() {
    let still = BodyPose {
        at: [0.0, 0.0],
        angle_rad: 0.3,
    };
    let moved = BodyPose {
        at: [1.0, 2.0],
        angle_rad: 0.3,
    };
    assert_eq!(pole(&still, &moved), None);
    // Three translations along a line: every moving pivot's places are in a line.
    let line = [0.0, 1.0, 2.0].map(|x| BodyPose {
        at: [x, 0.0],
        angle_rad: 0.0,
    });
    let err = three_positions(line, [[0.0, 0.1], [0.2, 0.0]]).expect_err("at infinity");
    assert!(
        matches!(&err, LinkageError::NoDesign(why)
            if matches!(**why, DesignRefusal::CentreAtInfinity { number: 1, .. })),
        "{err}"
    );
    let nan = [
        still,
        moved,
        BodyPose {
            at: [f64::NAN, 0.0],
            angle_rad: 0.0,
        },
    ];
    assert!(three_positions(nan, [[0.0, 0.1], [0.2, 0.0]]).is_err());
    assert!(three_positions([still, moved, line[2]], [[0.1, 0.1], [0.1, 0.1]]).is_err());
}

/// The known four-bar's moving pivots A and B in the body frame of `poses[0]`.
fn body_pivots(theta0_deg: f64) -> [Vec2; 2] {
    let pose = coupler_pose(theta0_deg.to_radians());
    let (a, b) = joints(theta0_deg.to_radians());
    let back = |p: Vec2| {
        let (s, c) = pose.angle_rad.sin_cos();
        let d = p - Vec2::new(pose.at[0], pose.at[1]);
        Vec2::new(c * d.x + s * d.y, -s * d.x + c * d.y)
    };
    [back(a), back(b)]
}

#[test]
fn four_positions_put_the_known_pivots_on_the_centre_point_curve() {
    let poses: Vec<BodyPose> = [40.0f64, 65.0, 95.0, 130.0]
        .iter()
        .map(|t| coupler_pose(t.to_radians()))
        .collect();
    let typical = centre_condition(&poses, Vec2::new(0.3, -0.4)).abs();
    assert!(typical > 0.0);
    for (fixed, moving) in [Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.0)]
        .into_iter()
        .zip(body_pivots(40.0))
    {
        assert!(centre_condition(&poses, fixed).abs() <= 1e-12 * typical);
        let a = circle_point(&poses, fixed).expect("a circle point");
        close("circle x", a.x, moving.x);
        close("circle y", a.y, moving.y);
    }
    // Fixed pivots taken on the curve near the known ones: the four-bar moves the
    // body through all four positions.
    let design = four_positions(&poses, [[0.05, 0.03], [0.97, -0.04]]).expect("designs");
    for f in design.fixed {
        assert!(centre_condition(&poses, Vec2::from(f)).abs() <= 1e-9 * typical);
    }
    let checked = design.check().expect("moves");
    assert!(
        checked.miss_m < 1e-9 && checked.miss_rad < 1e-9,
        "{} m, {} rad",
        checked.miss_m,
        checked.miss_rad
    );
    assert!(!centre_curve(&poses, 2.0, 100).is_empty());
}

#[test]
fn five_positions_give_back_the_known_pivots_among_the_burmester_points() {
    let poses: Vec<BodyPose> = [40.0f64, 65.0, 95.0, 130.0, 170.0]
        .iter()
        .map(|t| coupler_pose(t.to_radians()))
        .collect();
    let points = burmester_points(&poses).expect("five positions");
    assert!(points.len() <= 4, "{points:?}");
    let [ma, mb] = body_pivots(40.0);
    let a = crank_at(&points, [0.0, 0.0], ma);
    let b = crank_at(&points, [1.0, 0.0], mb);
    let checked = four_bar_of(&poses, [a, b])
        .expect("designs")
        .check()
        .expect("moves");
    assert!(
        checked.miss_m < 1e-9 && checked.miss_rad < 1e-9,
        "{} m, {} rad",
        checked.miss_m,
        checked.miss_rad
    );
    assert!(burmester_points(&poses[..4]).is_err(), "five are needed");
}

/// The crank of `points` at centre `fixed` (1e-9), its circle point checked
/// against `moving` (1e-9).
fn crank_at(points: &[Crank], fixed: [f64; 2], moving: Vec2) -> Crank {
    let c = *points
        .iter()
        .find(|c| (Vec2::from(c.centre) - Vec2::from(fixed)).norm() < 1e-9)
        .unwrap_or_else(|| panic!("{fixed:?} not among {points:?}"));
    close("circle x", c.circle[0], moving.x);
    close("circle y", c.circle[1], moving.y);
    c
}
