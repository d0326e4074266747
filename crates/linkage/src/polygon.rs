//! Velocity and acceleration polygon data: for every dyad, its vector equations
//! (`v_C = v_B + v_CB`, `a_C^n + a_C^t = a_B^n + a_B^t + a_CB^n + a_CB^t`, with the
//! Coriolis term where a slider rides a moving guide) and, per term, the vector,
//! whether its magnitude and direction are known before solving the group, and the
//! direction in words, as the textbooks tabulate them.

use std::fmt;

use serde::{Serialize, Serializer};

use crate::ids::LinkId;
use crate::model::Mechanism;
use crate::motion::{PointMotion, Solution, Vec2, perp};
use crate::solve::Group;
use crate::solve::Kinematics;

/// Velocity or acceleration.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Quantity {
    /// v.
    Velocity,
    /// a.
    Acceleration,
}

/// Which part of a point's (relative) motion a term is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum Component {
    /// The whole vector.
    Whole,
    /// The normal (centripetal) part, towards the centre of rotation: ^n.
    Normal,
    /// The tangential part, at right angles to the radius: ^t.
    Tangential,
    /// The Coriolis part, 2 ω × v_rel of a point riding a turning guide: ^k.
    Coriolis,
    /// The sliding part along a moving guide: ^r.
    Sliding,
}

/// A term's symbol as data: `v_CB` is the velocity of C relative to B, whole;
/// `a_C^n` the normal acceleration of C (relative to the frame). Text is made where
/// it is shown ([`fmt::Display`] gives the ASCII form `v_CB`, `a_C^n`).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Symbol {
    /// Velocity or acceleration.
    pub quantity: Quantity,
    /// The point (its name; `C'` is the point of a guide under the slider's C).
    pub point: String,
    /// The point it is relative to; `None` relative to the frame.
    pub relative_to: Option<String>,
    /// Which part.
    pub component: Component,
}

impl Symbol {
    fn new(accel: bool, point: &str, relative_to: Option<&str>, component: Component) -> Self {
        Self {
            quantity: if accel {
                Quantity::Acceleration
            } else {
                Quantity::Velocity
            },
            point: point.to_string(),
            relative_to: relative_to.map(str::to_string),
            component,
        }
    }

    /// The subscript: the point, then the one it is relative to (`CB`).
    pub fn subscript(&self) -> String {
        format!(
            "{}{}",
            self.point,
            self.relative_to.as_deref().unwrap_or("")
        )
    }

    /// The superscript letter of the component (`n`, `t`, `k`, `r`), if any.
    pub fn superscript(&self) -> Option<char> {
        match self.component {
            Component::Whole => None,
            Component::Normal => Some('n'),
            Component::Tangential => Some('t'),
            Component::Coriolis => Some('k'),
            Component::Sliding => Some('r'),
        }
    }

    /// The letter of the quantity (`v`, `a`).
    pub fn letter(&self) -> char {
        match self.quantity {
            Quantity::Velocity => 'v',
            Quantity::Acceleration => 'a',
        }
    }
}

impl fmt::Display for Symbol {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}_{}", self.letter(), self.subscript())?;
        match self.superscript() {
            Some(c) => write!(f, "^{c}"),
            None => Ok(()),
        }
    }
}

/// In JSON a symbol is its ASCII text (`v_CB`), as scripts reading `linkage at` expect.
fn symbol_text<S: Serializer>(symbol: &Symbol, out: S) -> Result<S::Ok, S::Error> {
    out.collect_str(symbol)
}

/// One vector of a polygon equation.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Term {
    /// Its symbol (in JSON as text: `v_CB`, `a_C^t`; `^k` Coriolis, `^r` sliding).
    #[serde(serialize_with = "symbol_text")]
    pub symbol: Symbol,
    /// The vector, m/s or m/s².
    pub vector: [f64; 2],
    /// Its length.
    pub magnitude: f64,
    /// Its direction, rad.
    pub direction_rad: f64,
    /// Magnitude known before the group is solved.
    pub magnitude_known: bool,
    /// Direction known before the group is solved.
    pub direction_known: bool,
    /// The direction in words (`perp CD`, `along guide`, `C to D`).
    pub direction: String,
}

/// One vector equation: sum of `lhs` = sum of `rhs`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct VectorEquation {
    /// Velocity or acceleration (in JSON `velocity`, `acceleration`).
    pub kind: Quantity,
    /// The group it solves.
    pub group: String,
    /// The equation in symbols.
    pub equation: String,
    /// Left side terms.
    pub lhs: Vec<Term>,
    /// Right side terms.
    pub rhs: Vec<Term>,
}

impl VectorEquation {
    /// The largest magnitude among its terms: the scale its round-off is judged by.
    pub fn largest_term(&self) -> f64 {
        self.lhs
            .iter()
            .chain(&self.rhs)
            .map(|t| t.magnitude)
            .fold(0.0, f64::max)
    }

    /// |Σlhs − Σrhs|: zero up to round-off for a solved position.
    pub fn residual(&self) -> f64 {
        let sum = |t: &[Term]| {
            t.iter().fold(Vec2::zeros(), |acc, t| {
                acc + Vec2::new(t.vector[0], t.vector[1])
            })
        };
        (sum(&self.lhs) - sum(&self.rhs)).norm()
    }
}

fn term(
    symbol: Symbol,
    v: Vec2,
    magnitude_known: bool,
    direction_known: bool,
    direction: String,
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

fn point_name(m: &Mechanism, link: LinkId, local: &Vec2) -> String {
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
fn ground_pivot(m: &Mechanism, link: LinkId) -> Option<(String, Vec2)> {
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
fn known_point(
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
                        format!("{name} to {o}"),
                    ),
                    term(
                        Symbol::new(true, name, None, Component::Tangential),
                        perp(&r) * l.alpha_rad_s2,
                        true,
                        true,
                        format!("perp {o}{name}"),
                    ),
                ]
            } else {
                vec![term(
                    Symbol::new(false, name, None, Component::Whole),
                    p.velocity,
                    true,
                    true,
                    format!("perp {o}{name}"),
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
                "known".into(),
            )]
        }
    }
}

/// Relative terms of M about A on a link turning at (ω, α): `v_MA` or `a_MA^n + a_MA^t`
/// (named `v_M`, `a_M^n`, `a_M^t` when A is a ground pivot).
fn relative(
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
                format!("{m_name} to {a_name}"),
            ),
            term(
                Symbol::new(true, m_name, about, Component::Tangential),
                perp(&r) * alpha,
                false,
                true,
                format!("perp {m_name}{a_name}"),
            ),
        ]
    } else {
        vec![term(
            Symbol::new(false, m_name, about, Component::Whole),
            perp(&r) * omega,
            false,
            true,
            format!("perp {m_name}{a_name}"),
        )]
    }
}

/// Terms of a point M riding a guide of `guide` link: the guide's coincident point
/// M' (if the guide moves), Coriolis, and the sliding term along the guide.
fn riding(
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
                format!("known ({} point at {m_name})", m.links[guide].name),
            ));
            t.push(term(
                Symbol::new(true, m_name, about, Component::Coriolis),
                coriolis,
                true,
                true,
                "Coriolis: 2 omega_guide x v_rel".into(),
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
            "along guide".into(),
        ));
    } else {
        if !fixed {
            t.push(term(
                Symbol::new(false, &prime, None, Component::Whole),
                on.velocity,
                true,
                true,
                format!("known ({} point at {m_name})", m.links[guide].name),
            ));
        }
        t.push(term(
            Symbol::new(false, m_name, about, Component::Whole),
            v_rel,
            false,
            true,
            "along guide".into(),
        ));
    }
    t
}

fn equation(kind: Quantity, group: String, lhs: Vec<Term>, rhs: Vec<Term>) -> VectorEquation {
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

/// Polygon equations of every group at a solved position (empty on the Newton-only path).
pub fn polygons(k: &Kinematics, s: &Solution) -> Vec<VectorEquation> {
    let m = k.mechanism();
    let Some(cf) = k.closed_form() else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for (gi, group) in cf.groups.iter().enumerate() {
        let gname = k.group_name(gi);
        for accel in [false, true] {
            let kind = if accel {
                Quantity::Acceleration
            } else {
                Quantity::Velocity
            };
            let (lhs, rhs) = match group {
                Group::Rrr(d) => {
                    let (a, c) = (d.a.link, d.c.link);
                    let (an, cn) = (point_name(m, a, &d.a.local), point_name(m, c, &d.c.local));
                    let mn = m.points[cf.group_points[gi]].name.clone();
                    let (pa, pc) = (s.links[a].point(&d.a.local), s.links[c].point(&d.c.local));
                    let pm = s.links[d.i].point(&d.mid_on_i);
                    let (li, lj) = (&s.links[d.i], &s.links[d.j]);
                    let mut lhs = known_point(m, s, c, &cn, &pc, accel);
                    lhs.extend(relative(
                        &mn,
                        &cn,
                        pm.position - pc.position,
                        lj.omega_rad_s,
                        lj.alpha_rad_s2,
                        c == m.ground,
                        accel,
                    ));
                    let mut rhs = known_point(m, s, a, &an, &pa, accel);
                    rhs.extend(relative(
                        &mn,
                        &an,
                        pm.position - pa.position,
                        li.omega_rad_s,
                        li.alpha_rad_s2,
                        a == m.ground,
                        accel,
                    ));
                    (lhs, rhs)
                }
                Group::Rrp(d) => {
                    let an = point_name(m, d.a.link, &d.a.local);
                    let mn = m.points[cf.group_points[gi]].name.clone();
                    let pa = s.links[d.a.link].point(&d.a.local);
                    let pm = s.links[d.j].point(&d.mid_on_j);
                    let li = &s.links[d.i];
                    let lhs = riding(m, s, d.slide.guide, &mn, &pm, accel);
                    let mut rhs = known_point(m, s, d.a.link, &an, &pa, accel);
                    rhs.extend(relative(
                        &mn,
                        &an,
                        pm.position - pa.position,
                        li.omega_rad_s,
                        li.alpha_rad_s2,
                        d.a.link == m.ground,
                        accel,
                    ));
                    (lhs, rhs)
                }
                Group::Rpr(d) => {
                    let sn = point_name(m, d.s.link, &d.s.local);
                    let gn = point_name(m, d.g.link, &d.g.local);
                    let ps = s.links[d.s.link].point(&d.s.local);
                    let pg = s.links[d.g.link].point(&d.g.local);
                    let guide = &s.links[d.guide];
                    let lhs = known_point(m, s, d.s.link, &sn, &ps, accel);
                    let mut rhs = known_point(m, s, d.g.link, &gn, &pg, accel);
                    let prime = format!("{sn}'");
                    rhs.extend(relative(
                        &prime,
                        &gn,
                        ps.position - pg.position,
                        guide.omega_rad_s,
                        guide.alpha_rad_s2,
                        d.g.link == m.ground,
                        accel,
                    ));
                    let slide = riding(m, s, d.guide, &sn, &ps, accel);
                    // The coincident point's own motion is already on this side: keep only
                    // the Coriolis and sliding terms.
                    rhs.extend(
                        slide
                            .into_iter()
                            .filter(|t| t.symbol.point != prime || t.symbol.relative_to.is_some()),
                    );
                    (lhs, rhs)
                }
                Group::Prp(d) => {
                    let mn = m.points[cf.group_points[gi]].name.clone();
                    let pm = s.links[d.i].point(&d.mid_on_i);
                    let lhs = riding(m, s, d.slide_j.guide, &mn, &pm, accel);
                    let rhs = riding(m, s, d.slide_i.guide, &mn, &pm, accel);
                    (lhs, rhs)
                }
            };
            out.push(equation(kind, gname.clone(), lhs, rhs));
        }
    }
    out
}
