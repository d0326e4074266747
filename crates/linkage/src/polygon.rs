//! Velocity and acceleration polygon data: for every dyad, its vector equations
//! (`v_C = v_B + v_CB`, `a_C^n + a_C^t = a_B^n + a_B^t + a_CB^n + a_CB^t`, with the
//! Coriolis term where a slider rides a moving guide) and, per term, the vector,
//! whether its magnitude and direction are known before solving the group, and the
//! direction in words, as the textbooks tabulate them.

mod cam;
mod parts;
mod terms;

pub use parts::{Component, Quantity, Symbol, Term, TermDirection, VectorEquation};

use crate::model::Mechanism;
use crate::motion::Solution;
use crate::solve::Kinematics;
use crate::solve::{Group, Prp, Rpr, Rrp, Rrr};
use terms::{equation, known_point, point_name, relative, riding};

/// Polygon equations of every group at a solved position (empty on the Newton-only path).
pub fn polygons(k: &Kinematics, s: &Solution) -> Vec<VectorEquation> {
    let m = k.mechanism();
    let Some(cf) = k.closed_form() else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for (gi, group) in cf.groups.iter().enumerate() {
        let gname = k.group_name(gi);
        let mid = &m.points[cf.group_points[gi]].name;
        for accel in [false, true] {
            let kind = if accel {
                Quantity::Acceleration
            } else {
                Quantity::Velocity
            };
            let at = At { m, s, accel };
            let (lhs, rhs) = match group {
                Group::Rrr(d) => at.rrr(d, mid),
                Group::Rrp(d) => at.rrp(d, mid),
                Group::Rpr(d) => at.rpr(d),
                Group::Prp(d) => at.prp(d, mid),
                Group::Cam(c) => match cam::cam_sides(m, s, &c.cam, accel) {
                    Some(sides) => sides,
                    None => continue,
                },
            };
            out.push(equation(kind, gname.clone(), lhs, rhs));
        }
    }
    out
}

/// The two sides of one group's equation.
type Sides = (Vec<Term>, Vec<Term>);

/// A solved position, and whether its accelerations are asked for (else its
/// velocities).
struct At<'a> {
    m: &'a Mechanism,
    s: &'a Solution,
    accel: bool,
}

impl At<'_> {
    /// RRR: the inner joint `mid` from each side's outer joint.
    fn rrr(&self, d: &Rrr, mid: &str) -> Sides {
        let (m, s, accel) = (self.m, self.s, self.accel);
        let (a, c) = (d.a.link, d.c.link);
        let (an, cn) = (point_name(m, a, &d.a.local), point_name(m, c, &d.c.local));
        let (pa, pc) = (s.links[a].point(&d.a.local), s.links[c].point(&d.c.local));
        let pm = s.links[d.i].point(&d.mid_on_i);
        let (li, lj) = (&s.links[d.i], &s.links[d.j]);
        let mut lhs = known_point(m, s, c, &cn, &pc, accel);
        lhs.extend(relative(
            mid,
            &cn,
            pm.position - pc.position,
            lj.omega_rad_s,
            lj.alpha_rad_s2,
            c == m.ground,
            accel,
        ));
        let mut rhs = known_point(m, s, a, &an, &pa, accel);
        rhs.extend(relative(
            mid,
            &an,
            pm.position - pa.position,
            li.omega_rad_s,
            li.alpha_rad_s2,
            a == m.ground,
            accel,
        ));
        (lhs, rhs)
    }

    /// RRP: the slider `mid` along its guide, and from the outer joint.
    fn rrp(&self, d: &Rrp, mid: &str) -> Sides {
        let (m, s, accel) = (self.m, self.s, self.accel);
        let an = point_name(m, d.a.link, &d.a.local);
        let pa = s.links[d.a.link].point(&d.a.local);
        let pm = s.links[d.j].point(&d.mid_on_j);
        let li = &s.links[d.i];
        let lhs = riding(m, s, d.slide.guide, mid, &pm, accel);
        let mut rhs = known_point(m, s, d.a.link, &an, &pa, accel);
        rhs.extend(relative(
            mid,
            &an,
            pm.position - pa.position,
            li.omega_rad_s,
            li.alpha_rad_s2,
            d.a.link == m.ground,
            accel,
        ));
        (lhs, rhs)
    }

    /// RPR: the slider's point, and the coincident point on the guide with the
    /// Coriolis and sliding terms.
    fn rpr(&self, d: &Rpr) -> Sides {
        let (m, s, accel) = (self.m, self.s, self.accel);
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

    /// PRP: the block `mid` riding each of its two guides.
    fn prp(&self, d: &Prp, mid: &str) -> Sides {
        let (m, s, accel) = (self.m, self.s, self.accel);
        let pm = s.links[d.i].point(&d.mid_on_i);
        let lhs = riding(m, s, d.slide_j.guide, mid, &pm, accel);
        let rhs = riding(m, s, d.slide_i.guide, mid, &pm, accel);
        (lhs, rhs)
    }
}
