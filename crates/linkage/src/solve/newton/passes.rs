//! The passes over the tree that every solve makes: placing the links for the
//! coordinates, their velocities and accelerations for given rates, the cut joints'
//! residuals and acceleration bias, and the Jacobian.

use super::{Cut, Solver, TreeKind};
use crate::ids::LinkId;
use crate::motion::{LinkMotion, PointMotion, Vec2, cross, perp};

impl Solver<'_> {
    /// Keeps joint angles in (-π, π]: they only enter through sin/cos, and a large
    /// angle would cost digits there.
    pub(super) fn wrap_angles(&mut self) {
        for (k, t) in self.model.tree.iter().enumerate().skip(1) {
            if matches!(t.kind, TreeKind::Revolute { .. }) {
                let q = &mut self.state.q[k - 1];
                *q -= (*q / std::f64::consts::TAU).round() * std::f64::consts::TAU;
            }
        }
    }

    /// Places every link for coordinates `q` (driver angle `input`); velocities untouched.
    pub(super) fn position_pass(&mut self, input: f64, links: &mut [LinkMotion]) {
        links[self.model.ground] = LinkMotion::default();
        for k in 0..self.model.tree.len() {
            let q = if k == 0 { input } else { self.state.q[k - 1] };
            let t = &self.model.tree[k];
            let parent = links[t.parent];
            let child = &mut links[t.child];
            match &t.kind {
                TreeKind::Revolute {
                    on_parent,
                    on_child,
                } => {
                    let j = parent.world(on_parent);
                    child.rotation = parent.rotation * self.state.turns[k].to(q, k == 0);
                    child.origin.position = j - child.rotation * on_child;
                    self.work.contacts[k] = j;
                }
                TreeKind::Prismatic {
                    slide,
                    parent_is_guide: true,
                } => {
                    let u = parent.rotation * slide.direction_local;
                    let p = parent.world(&slide.through_local) + u * q;
                    child.rotation = parent.rotation * slide.relative;
                    child.origin.position = p - child.rotation * slide.slider_local;
                    (self.work.contacts[k], self.work.guides[k]) = (p, u);
                }
                TreeKind::Prismatic {
                    slide,
                    parent_is_guide: false,
                } => {
                    child.rotation = parent.rotation * slide.relative.inverse();
                    let u = child.rotation * slide.direction_local;
                    let through = parent.world(&slide.slider_local) - u * q;
                    child.origin.position = through - child.rotation * slide.through_local;
                    (self.work.contacts[k], self.work.guides[k]) = (through, u);
                }
            }
        }
    }

    /// Sets every link's velocity and acceleration for coordinate rates `rate(k)` and
    /// second derivatives `accel(k)` (k = 0 is the driver), positions fixed.
    pub(super) fn motion_pass(
        &self,
        links: &mut [LinkMotion],
        rate: impl Fn(usize) -> f64,
        accel: impl Fn(usize) -> f64,
    ) {
        links[self.model.ground] = LinkMotion::default();
        for (k, t) in self.model.tree.iter().enumerate() {
            let parent = links[t.parent];
            let (qd, qdd) = (rate(k), accel(k));
            let child = &mut links[t.child];
            let (omega, alpha, local, pin) = match &t.kind {
                TreeKind::Revolute { on_child, .. } => (
                    parent.omega_rad_s + qd,
                    parent.alpha_rad_s2 + qdd,
                    *on_child,
                    parent.material_point_at(&self.work.contacts[k]),
                ),
                TreeKind::Prismatic {
                    slide,
                    parent_is_guide,
                } => {
                    let (sign, local) = if *parent_is_guide {
                        (1.0, slide.slider_local)
                    } else {
                        (-1.0, slide.through_local)
                    };
                    let base = parent.material_point_at(&self.work.contacts[k]);
                    let pin = PointMotion {
                        position: self.work.contacts[k],
                        velocity: base.velocity + self.work.guides[k] * (sign * qd),
                        acceleration: base.acceleration
                            + perp(&self.work.guides[k]) * (2.0 * parent.omega_rad_s * sign * qd)
                            + self.work.guides[k] * (sign * qdd),
                    };
                    (parent.omega_rad_s, parent.alpha_rad_s2, local, pin)
                }
            };
            *child = LinkMotion::from_pin(child.rotation, omega, alpha, &local, &pin);
        }
    }

    /// Cut-joint residuals (positions), written to `out`; returns the max-norm.
    pub(super) fn residual(&self, links: &[LinkMotion], out: &mut [f64]) -> f64 {
        let mut worst: f64 = 0.0;
        let per_m = 1.0 / self.model.size_m;
        for (c, cut) in self.model.cuts.iter().enumerate() {
            let (r0, r1) = match cut {
                Cut::Revolute {
                    a,
                    a_local,
                    b,
                    b_local,
                } => {
                    let d = links[*a].world(a_local) - links[*b].world(b_local);
                    (d.x, d.y)
                }
                Cut::Prismatic(s) => {
                    let (sl, g) = (&links[s.slider], &links[s.guide]);
                    let u = g.rotation * s.direction_local;
                    let d = sl.world(&s.slider_local) - g.world(&s.through_local);
                    let turn = ((g.rotation * s.relative).inverse() * sl.rotation).angle();
                    (cross(&u, &d), turn)
                }
            };
            out[2 * c] = r0;
            out[2 * c + 1] = r1;
            let r1_relative = match cut {
                Cut::Revolute { .. } => r1 * per_m,
                Cut::Prismatic(_) => r1,
            };
            worst = worst.max(r0.abs() * per_m).max(r1_relative.abs());
        }
        worst.max(self.cam_residuals(links, out, 2 * self.model.cuts.len()))
    }

    /// Second time derivative of the cut residuals (the acceleration bias `b` when the
    /// coordinates' second derivatives are zero).
    pub(super) fn cut_accelerations(&self, links: &[LinkMotion], out: &mut [f64]) {
        for (c, cut) in self.model.cuts.iter().enumerate() {
            let (r0, r1) = match cut {
                Cut::Revolute {
                    a,
                    a_local,
                    b,
                    b_local,
                } => {
                    let (pa, pb) = (links[*a].point(a_local), links[*b].point(b_local));
                    let d = pa.acceleration - pb.acceleration;
                    (d.x, d.y)
                }
                Cut::Prismatic(s) => {
                    let (sl, g) = (&links[s.slider], &links[s.guide]);
                    let u = g.rotation * s.direction_local;
                    let (p, q) = (sl.point(&s.slider_local), g.point(&s.through_local));
                    let d = p.position - q.position;
                    let dd = p.velocity - q.velocity;
                    let u_dot = perp(&u) * g.omega_rad_s;
                    let u_ddot = perp(&u) * g.alpha_rad_s2 - u * (g.omega_rad_s * g.omega_rad_s);
                    let ddd = p.acceleration - q.acceleration;
                    (
                        cross(&u_ddot, &d) + 2.0 * cross(&u_dot, &dd) + cross(&u, &ddd),
                        sl.alpha_rad_s2 - g.alpha_rad_s2,
                    )
                }
            };
            out[2 * c] = r0;
            out[2 * c + 1] = r1;
        }
        self.cam_accelerations(links, out, 2 * self.model.cuts.len());
    }

    /// Velocity of the material point at `p` of `link`, and the link's angular
    /// velocity, for a unit rate of tree joint `k` with every other coordinate still:
    /// a turn about the joint or a slide along its guide, if `k` carries the link.
    #[inline]
    pub(super) fn unit_rate(&self, k: usize, link: LinkId, p: &Vec2) -> (Vec2, f64) {
        if !self.model.moved_by[link.index() * self.model.tree.len() + k] {
            return (Vec2::zeros(), 0.0);
        }
        let t = &self.model.tree[k];
        match &t.kind {
            TreeKind::Revolute { .. } => (perp(&(p - self.work.contacts[k])), 1.0),
            TreeKind::Prismatic {
                parent_is_guide, ..
            } => (
                self.work.guides[k] * if *parent_is_guide { 1.0 } else { -1.0 },
                0.0,
            ),
        }
    }

    /// Jacobian of the cut residuals at the current positions (columns: unknowns) and,
    /// in `self.work.rates`, the driver's column. Each column is the cut joints' relative
    /// velocity for a unit rate of one tree joint, written directly from the joint
    /// points (what a velocity pass with that one rate would give, without the pass).
    pub(super) fn build_jacobian(&mut self, links: &[LinkMotion]) {
        for (c, cut) in self.model.cuts.iter().enumerate() {
            // The cut's points and guide direction are the same for every column.
            let (first, second, guide_dir) = match cut {
                Cut::Revolute {
                    a,
                    a_local,
                    b,
                    b_local,
                } => (
                    (*a, links[*a].world(a_local)),
                    (*b, links[*b].world(b_local)),
                    None,
                ),
                Cut::Prismatic(s) => (
                    (s.slider, links[s.slider].world(&s.slider_local)),
                    (s.guide, links[s.guide].world(&s.through_local)),
                    Some(links[s.guide].rotation * s.direction_local),
                ),
            };
            for k in 0..self.model.tree.len() {
                let (v_first, w_first) = self.unit_rate(k, first.0, &first.1);
                let (v_second, w_second) = self.unit_rate(k, second.0, &second.1);
                let (r0, r1) = match guide_dir {
                    None => (v_first.x - v_second.x, v_first.y - v_second.y),
                    // Slider point on the guide line: d/dt cross(u, p - q), and the
                    // slider's turn relative to the guide.
                    Some(u) => (
                        cross(&(perp(&u) * w_second), &(first.1 - second.1))
                            + cross(&u, &(v_first - v_second)),
                        w_first - w_second,
                    ),
                };
                if k == 0 {
                    self.work.rates[2 * c] = r0;
                    self.work.rates[2 * c + 1] = r1;
                } else {
                    self.work.jac[(2 * c, k - 1)] = r0;
                    self.work.jac[(2 * c + 1, k - 1)] = r1;
                }
            }
        }
        self.cam_jacobian_rows(links, 2 * self.model.cuts.len());
    }
}
