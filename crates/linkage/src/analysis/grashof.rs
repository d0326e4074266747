//! The Grashof class of the four-bar loop formed by ground, the crank and the first
//! RRR dyad.

use serde::Serialize;

use crate::solve::Group;
use crate::solve::Kinematics;

/// The Grashof class of a four-bar loop, by which link is shortest (JSON: the words
/// [`std::fmt::Display`] shows).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum GrashofClass {
    /// Grashof, the input shortest: it turns fully, the output rocks.
    #[serde(rename = "crank-rocker")]
    CrankRocker,
    /// Grashof, the ground shortest: both side links turn fully.
    #[serde(rename = "double-crank (drag link)")]
    DoubleCrank,
    /// Grashof, the coupler shortest: both side links rock.
    #[serde(rename = "double-rocker (Grashof, coupler shortest)")]
    DoubleRocker,
    /// Grashof, the output shortest: the output turns fully, the input rocks.
    #[serde(rename = "rocker-crank")]
    RockerCrank,
    /// s + l = p + q: the chain can fold flat and change its assembly mode.
    #[serde(rename = "change-point")]
    ChangePoint,
    /// Not Grashof: no link turns fully.
    #[serde(rename = "triple-rocker (non-Grashof)")]
    TripleRocker,
}

impl GrashofClass {
    /// The class of a four-bar of lengths ground, input, coupler, output (any unit).
    pub fn of_lengths(lengths: [f64; 4]) -> Self {
        Self::with_sums(lengths).0
    }

    /// The class, s + l and p + q.
    fn with_sums(lengths: [f64; 4]) -> (Self, f64, f64) {
        let mut sorted = lengths;
        sorted.sort_by(f64::total_cmp);
        let (sl, pq) = (sorted[0] + sorted[3], sorted[1] + sorted[2]);
        let shortest = (0..4)
            .min_by(|&x, &y| lengths[x].total_cmp(&lengths[y]))
            .unwrap_or(0);
        let class = if (sl - pq).abs() <= 1e-9 * sl {
            Self::ChangePoint
        } else if sl > pq {
            Self::TripleRocker
        } else {
            match shortest {
                0 => Self::DoubleCrank,
                1 => Self::CrankRocker,
                2 => Self::DoubleRocker,
                _ => Self::RockerCrank,
            }
        };
        (class, sl, pq)
    }
}

impl std::fmt::Display for GrashofClass {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::CrankRocker => "crank-rocker",
            Self::DoubleCrank => "double-crank (drag link)",
            Self::DoubleRocker => "double-rocker (Grashof, coupler shortest)",
            Self::RockerCrank => "rocker-crank",
            Self::ChangePoint => "change-point",
            Self::TripleRocker => "triple-rocker (non-Grashof)",
        })
    }
}

/// Grashof classification of a four-bar loop.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Grashof {
    /// The class.
    pub class: GrashofClass,
    /// s + l ≤ p + q.
    pub grashof: bool,
    /// s + l = p + q (within 1e-9 relative).
    pub change_point: bool,
    /// Shortest plus longest, m.
    pub s_plus_l_m: f64,
    /// The other two, m.
    pub p_plus_q_m: f64,
    /// Lengths: ground, input, coupler, output, m.
    pub lengths_m: [f64; 4],
    /// Link names in the same order.
    pub links: [String; 4],
    /// False: the mechanism is this four-bar; true: the four-bar is its driving loop.
    pub embedded: bool,
}

/// Grashof class of the four-bar formed by ground, the crank and the first RRR dyad
/// when that dyad closes on ground.
pub fn grashof(k: &Kinematics) -> Option<Grashof> {
    let m = k.mechanism();
    let cf = k.closed_form()?;
    let Some(Group::Rrr(g)) = cf.groups.first() else {
        return None;
    };
    let crank = m.driver.link;
    let (a_on_crank, ground_pin) = if g.a.link == crank && g.c.link == m.ground {
        (g.a.local, g.c.local)
    } else {
        return None;
    };
    let pivot = &m.revolutes[m.driver.pivot];
    let (crank_pivot_local, ground_pivot) = if pivot.a == m.ground {
        (pivot.b_local, pivot.a_local)
    } else {
        (pivot.a_local, pivot.b_local)
    };
    let lengths = [
        (ground_pin - ground_pivot).norm(),
        (a_on_crank - crank_pivot_local).norm(),
        g.len_i,
        g.len_j,
    ];
    let names = [m.ground, crank, g.i, g.j].map(|l| m.links[l].name.clone());
    let (class, sl, pq) = GrashofClass::with_sums(lengths);
    let change_point = class == GrashofClass::ChangePoint;
    Some(Grashof {
        class,
        grashof: sl <= pq || change_point,
        change_point,
        s_plus_l_m: sl,
        p_plus_q_m: pq,
        lengths_m: lengths,
        links: names,
        embedded: m.links.len() != 4 || !m.sliders.is_empty(),
    })
}
