//! The Roberts–Chebyshev cognates of a four-bar: the two other four-bars whose
//! coupler point traces the same curve (Roberts 1875, Chebyshev 1878).
//!
//! With complex numbers for points, let the coupler point be P = B + w (C − B), w the
//! coupler triangle's shape. The third fixed pivot is O = A + w (D − A): the
//! triangle ADO is similar to BCP. Writing u = B − A (the crank), v = C − D (the
//! rocker) and e = C − B (the coupler),
//!
//! P = A + u + w e = D + v − (1 − w) e = O + (1 − w) u + w v,
//!
//! and each form is a four-bar through P: on pivots A and O with links w e (turning
//! with the coupler) and w v (with the rocker), coupler w u; on pivots O and D with
//! links (1 − w) u (with the crank: the same timing) and (1 − w) e... read off below.
//! The construction is exact at every pose, so it is made at one pose and the
//! cognate's pins follow from the original's at every other.

use serde::Serialize;

use super::geometry::CouplerFourBar;
use super::shape::{complex, point};
use crate::motion::{Vec2, cross};

/// Which link of the original four-bar a cognate's input turns with.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum TurnsWith {
    /// The original's crank: the cognate meets the targets at the same crank angles
    /// (relative to each other), so it keeps a timing.
    Crank,
    /// The original's coupler.
    Coupler,
    /// The original's rocker.
    Rocker,
}

/// A cognate as pins at one pose: input pivot and pin, output pin and pivot.
#[derive(Clone, Copy, Debug)]
struct Pose {
    input_pivot: Vec2,
    input_pin: Vec2,
    output_pin: Vec2,
    output_pivot: Vec2,
}

/// The pins of the original at one crank angle: A, B, C, D and P.
struct Original {
    a: Vec2,
    b: Vec2,
    c: Vec2,
    d: Vec2,
    p: Vec2,
}

/// A cognate's pose from the original's, for each choice of input.
fn cognate_poses(o: &Original) -> [(TurnsWith, Pose); 3] {
    let c = |v: Vec2| complex(v);
    let (a, b, cc, d, p) = (c(o.a), c(o.b), c(o.c), c(o.d), c(o.p));
    let w = (p - b) / (cc - b);
    let pivot_o = a + w * (d - a);
    let (u, v, e) = (b - a, cc - d, cc - b);
    let one = nalgebra::Complex::new(1.0, 0.0);
    // On A and O: A–B1 turns with the coupler, O–C1 with the rocker.
    let b1 = a + w * e;
    let c1 = pivot_o + w * v;
    // On O and D: O–C2 turns with the crank, D–B2 with the coupler.
    let c2 = pivot_o + (one - w) * u;
    let b2 = d - (one - w) * e;
    let pose = |ip, ipin, opin, op| Pose {
        input_pivot: point(ip),
        input_pin: point(ipin),
        output_pin: point(opin),
        output_pivot: point(op),
    };
    [
        (TurnsWith::Crank, pose(pivot_o, c2, b2, d)),
        (TurnsWith::Coupler, pose(a, b1, c1, pivot_o)),
        (TurnsWith::Rocker, pose(pivot_o, c1, b1, a)),
    ]
}

/// Whether a pose's output pin lies left of the line from its input pin to its
/// output pivot (the branch, as [`CouplerFourBar::c_left_of_bd`] reads it).
fn side(pose: &Pose) -> bool {
    cross(
        &(pose.output_pivot - pose.input_pin),
        &(pose.output_pin - pose.input_pin),
    ) > 0.0
}

/// The four-bar of a cognate's pose with coupler point `p`, and its input angle.
fn linkage_of(pose: &Pose, p: Vec2) -> (CouplerFourBar, f64) {
    let crank_v = pose.input_pin - pose.input_pivot;
    let coupler_v = pose.output_pin - pose.input_pin;
    let coupler = coupler_v.norm();
    let x = coupler_v / coupler;
    let y = Vec2::new(-x.y, x.x);
    let rel = p - pose.input_pin;
    let m = CouplerFourBar {
        a: pose.input_pivot,
        d: pose.output_pivot,
        crank: crank_v.norm(),
        coupler,
        rocker: (pose.output_pin - pose.output_pivot).norm(),
        point: Vec2::new(rel.dot(&x), rel.dot(&y)),
        c_left_of_bd: side(pose),
    };
    (m, crank_v.y.atan2(crank_v.x))
}

/// A cognate and its input angle at each of the original's crank angles.
#[derive(Clone, Debug, PartialEq)]
pub struct Cognate {
    /// Which link of the original its input turns with.
    pub turns_with: TurnsWith,
    /// The four-bar (its input at `a`), on its branch at the first angle.
    pub linkage: CouplerFourBar,
    /// Its input angle where the original's crank is at each angle asked, rad.
    pub angles: Vec<f64>,
    /// Whether it is on the same branch at every angle: driven by a link that rocks
    /// while the original's crank turns, a cognate passes its dead points between
    /// targets and meets some on its other branch.
    pub one_branch: bool,
}

/// The cognates of `m` with their input angles where `m`'s crank is at each of
/// `thetas` (rad, where `m` closes): the one turning with the crank, and the other on
/// A and the third pivot, driven by the link turning with the coupler or the rocker,
/// whichever turns fully (else the one whose travel through `thetas` stays on its
/// branch, else the coupler's). `None` where `m` does not close at `thetas` or the
/// coupler point lies on the line BC's degenerate end (B = C).
pub fn cognates(m: &CouplerFourBar, thetas: &[f64]) -> Option<[Cognate; 2]> {
    let mut poses: Vec<[(TurnsWith, Pose); 3]> = Vec::with_capacity(thetas.len());
    for &t in thetas {
        let pins = m.pins_at(t)?;
        if (pins.c - pins.b).norm() == 0.0 {
            return None;
        }
        poses.push(cognate_poses(&Original {
            a: m.a,
            b: pins.b,
            c: pins.c,
            d: m.d,
            p: pins.p,
        }));
    }
    let first = poses.first()?;
    let p0 = m.pins_at(thetas[0])?.p;
    let build = |choice: usize| -> Cognate {
        let (turns_with, pose) = first[choice];
        let (linkage, _) = linkage_of(&pose, p0);
        let angles = poses
            .iter()
            .map(|ps| {
                let v = ps[choice].1.input_pin - ps[choice].1.input_pivot;
                v.y.atan2(v.x)
            })
            .collect();
        let one_branch = poses
            .iter()
            .all(|ps| side(&ps[choice].1) == linkage.c_left_of_bd);
        Cognate {
            turns_with,
            linkage,
            angles,
            one_branch,
        }
    };
    let with_crank = build(0);
    let (coupler, rocker) = (build(1), build(2));
    let stays = |c: &Cognate| c.one_branch && c.linkage.travel(&c.angles).is_some();
    let other = if coupler.linkage.crank_turns()
        || (!rocker.linkage.crank_turns() && (stays(&coupler) || !stays(&rocker)))
    {
        coupler
    } else {
        rocker
    };
    Some([with_crank, other])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A crank-rocker with its coupler point off the coupler line.
    fn crank_rocker() -> CouplerFourBar {
        CouplerFourBar::from_params(&[0.0, 0.0, 4.0, 0.5, 1.2, 3.6, 3.0, 1.5, 1.1], true)
    }

    /// Against the original's own coupler point: each cognate, at its own input angle,
    /// puts its coupler point where the original's is, at 72 crank angles over a turn
    /// (1e-12 of the size). The one turning with the crank stays on its branch; the
    /// other, driven by a link that rocks while the crank turns, passes its dead
    /// points, so some positions are on its other branch.
    #[test]
    fn the_cognates_trace_the_same_curve() {
        let m = crank_rocker();
        let thetas: Vec<f64> = (0..72).map(|k| f64::from(k) * 5f64.to_radians()).collect();
        let cognates = cognates(&m, &thetas).expect("closes everywhere");
        assert_eq!(cognates[0].turns_with, TurnsWith::Crank);
        for (n, c) in cognates.iter().enumerate() {
            for (t, a) in thetas.iter().zip(&c.angles) {
                let want = m.point_at(*t).expect("closes");
                let on = |left: bool| {
                    let branch = CouplerFourBar {
                        c_left_of_bd: left,
                        ..c.linkage
                    };
                    branch
                        .point_at(*a)
                        .is_some_and(|p| (p - want).norm() < 4e-12)
                };
                let own = on(c.linkage.c_left_of_bd);
                assert!(
                    own || (n == 1 && on(!c.linkage.c_left_of_bd)),
                    "{:?} at {t}",
                    c.turns_with
                );
            }
        }
        // The cognate turning with the crank turns as much as the crank: the same timing.
        let c = &cognates[0];
        for w in c.angles.windows(2).zip(thetas.windows(2)) {
            let (da, dt) = (
                (w.0[1] - w.0[0]).rem_euclid(std::f64::consts::TAU),
                (w.1[1] - w.1[0]).rem_euclid(std::f64::consts::TAU),
            );
            assert!((da - dt).abs() < 1e-12, "{da} vs {dt}");
        }
    }

    /// The three four-bars share their three fixed pivots between them (Roberts'
    /// triangle ADO, similar to the coupler triangle BCP).
    #[test]
    fn the_family_has_three_pivots_and_the_pivot_triangle_is_the_coupler_triangle() {
        let m = crank_rocker();
        let [c1, c2] = cognates(&m, &[0.3]).expect("closes");
        let o = c1.linkage.a;
        assert!((c1.linkage.d - m.d).norm() < 1e-12);
        assert!((c2.linkage.a - o).norm() < 1e-12 || (c2.linkage.d - o).norm() < 1e-12);
        let pins = m.pins_at(0.3).expect("closes");
        let ratio = |a: Vec2, b: Vec2, c: Vec2| {
            let (ab, ac) = (complex(b - a), complex(c - a));
            ac / ab
        };
        let coupler = ratio(pins.b, pins.c, pins.p);
        let ground = ratio(m.a, m.d, o);
        assert!((coupler - ground).norm() < 1e-12, "{coupler} vs {ground}");
    }
}
