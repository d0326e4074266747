//! The terms of a point's motion as the polygons write them: a point known from its
//! link's pivot, a point relative to another of its link, a point riding a guide.

use super::parts::{Component, Quantity, Symbol, Term, TermDirection, VectorEquation};
use crate::dyad::GroupLabel;
use crate::ids::LinkId;
use crate::model::Mechanism;
use crate::motion::{PointMotion, Solution, Vec2, perp};

pub(super) fn term(
    symbol: Symbol,
    v: Vec2,
    magnitude_known: bool,
    direction_known: bool,
    direction: TermDirection,
) -> Term {
    Term {
        symbol,
        vector: [v.x, v.y],
        magnitude: v.norm(),
        direction_rad: v.y.atan2(v.x),
        magnitude_known,
        direction_known,
        direction,
    }
}

pub(super) fn point_name(m: &Mechanism, link: LinkId, local: &Vec2) -> String {
    m.links[link]
        .points
        .iter()
        .find(|(_, l)| (l - local).norm() <= 1e-12 * (1.0 + local.norm()))
        .map_or_else(
            || format!("{}?", m.links[link].name),
            |(p, _)| m.points[*p].name.clone(),
        )
}

/// The ground pivot of a link pinned to ground: its name and place on the link.
pub(super) fn ground_pivot(m: &Mechanism, link: LinkId) -> Option<(String, Vec2)> {
    m.revolutes.iter().find_map(|r| {
        let local = if r.a == link && r.b == m.ground {
            r.a_local
        } else if r.b == link && r.a == m.ground {
            r.b_local
        } else {
            return None;
        };
        Some((m.points[r.point].name.clone(), local))
    })
}

/// Terms of a known point P on `link`: none on ground; `v_P` (perp OP) and
/// `a_P^n + a_P^t` on a link turning about a ground pivot O; else the whole vector.
pub(super) fn known_point(
    m: &Mechanism,
    s: &Solution,
    link: LinkId,
    name: &str,
    p: &PointMotion,
    accel: bool,
) -> Vec<Term> {
    if link == m.ground {
        return Vec::new();
    }
    let l = &s.links[link];
    match ground_pivot(m, link) {
        Some((o, pivot_local)) => {
            let r = p.position - l.world(&pivot_local);
            if accel {
                vec![
                    term(
                        Symbol::new(true, name, None, Component::Normal),
                        -r * l.omega_rad_s.powi(2),
                        true,
                        true,
                        TermDirection::Towards {
                            from: name.to_string(),
                            to: o.to_string(),
                        },
                    ),
                    term(
                        Symbol::new(true, name, None, Component::Tangential),
                        perp(&r) * l.alpha_rad_s2,
                        true,
                        true,
                        TermDirection::Perpendicular {
                            a: o.to_string(),
                            b: name.to_string(),
                        },
                    ),
                ]
            } else {
                vec![term(
                    Symbol::new(false, name, None, Component::Whole),
                    p.velocity,
                    true,
                    true,
                    TermDirection::Perpendicular {
                        a: o.to_string(),
                        b: name.to_string(),
                    },
                )]
            }
        }
        None => {
            let v = if accel { p.acceleration } else { p.velocity };
            vec![term(
                Symbol::new(accel, name, None, Component::Whole),
                v,
                true,
                true,
                TermDirection::Known,
            )]
        }
    }
}

/// Relative terms of M about A on a link turning at (ω, α): `v_MA` or `a_MA^n + a_MA^t`
/// (named `v_M`, `a_M^n`, `a_M^t` when A is a ground pivot).
pub(super) fn relative(
    m_name: &str,
    a_name: &str,
    r: Vec2,
    omega: f64,
    alpha: f64,
    a_fixed: bool,
    accel: bool,
) -> Vec<Term> {
    let about = (!a_fixed).then_some(a_name);
    if accel {
        vec![
            term(
                Symbol::new(true, m_name, about, Component::Normal),
                -r * omega * omega,
                true,
                true,
                TermDirection::Towards {
                    from: m_name.to_string(),
                    to: a_name.to_string(),
                },
            ),
            term(
                Symbol::new(true, m_name, about, Component::Tangential),
                perp(&r) * alpha,
                false,
                true,
                TermDirection::Perpendicular {
                    a: m_name.to_string(),
                    b: a_name.to_string(),
                },
            ),
        ]
    } else {
        vec![term(
            Symbol::new(false, m_name, about, Component::Whole),
            perp(&r) * omega,
            false,
            true,
            TermDirection::Perpendicular {
                a: m_name.to_string(),
                b: a_name.to_string(),
            },
        )]
    }
}

/// Terms of a point M riding a guide of `guide` link: the guide's coincident point
/// M' (if the guide moves), Coriolis, and the sliding term along the guide.
pub(super) fn riding(
    m: &Mechanism,
    s: &Solution,
    guide: LinkId,
    m_name: &str,
    pm: &PointMotion,
    accel: bool,
) -> Vec<Term> {
    let g = &s.links[guide];
    let on = g.material_point_at(&pm.position);
    let v_rel = pm.velocity - on.velocity;
    let coriolis = perp(&v_rel) * (2.0 * g.omega_rad_s);
    let fixed = guide == m.ground;
    let prime = format!("{m_name}'");
    let about = (!fixed).then_some(prime.as_str());
    let mut t = Vec::new();
    if accel {
        if !fixed {
            t.push(term(
                Symbol::new(true, &prime, None, Component::Whole),
                on.acceleration,
                true,
                true,
                TermDirection::GuidePoint {
                    guide: m.links[guide].name.clone(),
                    point: m_name.to_string(),
                },
            ));
            t.push(term(
                Symbol::new(true, m_name, about, Component::Coriolis),
                coriolis,
                true,
                true,
                TermDirection::Coriolis,
            ));
        }
        let component = if fixed {
            Component::Whole
        } else {
            Component::Sliding
        };
        t.push(term(
            Symbol::new(true, m_name, about, component),
            pm.acceleration - on.acceleration - coriolis,
            false,
            true,
            TermDirection::AlongGuide,
        ));
    } else {
        if !fixed {
            t.push(term(
                Symbol::new(false, &prime, None, Component::Whole),
                on.velocity,
                true,
                true,
                TermDirection::GuidePoint {
                    guide: m.links[guide].name.clone(),
                    point: m_name.to_string(),
                },
            ));
        }
        t.push(term(
            Symbol::new(false, m_name, about, Component::Whole),
            v_rel,
            false,
            true,
            TermDirection::AlongGuide,
        ));
    }
    t
}

pub(super) fn equation(
    kind: Quantity,
    group: GroupLabel,
    lhs: Vec<Term>,
    rhs: Vec<Term>,
) -> VectorEquation {
    let side = |t: &[Term]| {
        if t.is_empty() {
            "0".to_string()
        } else {
            t.iter()
                .map(|x| x.symbol.to_string())
                .collect::<Vec<_>>()
                .join(" + ")
        }
    };
    VectorEquation {
        kind,
        equation: format!("{} = {}", side(&lhs), side(&rhs)),
        group,
        lhs,
        rhs,
    }
}
