//! Moving the current pose without changing the scene: the crank angle, playback of
//! the crank or of the dynamic run, and the run's time.

use super::Session;
use super::notice::Notice;

/// How long playback holds a dynamic run's last state before it starts again, s.
const HOLD_S: f64 = 0.5;

impl Session {
    /// The input slider's range, deg: a full turn (wrapping) or the assembly interval.
    pub fn input_range_deg(&self) -> [f64; 2] {
        let curves = self.curves();
        if curves.full_rotation {
            [0.0, 360.0]
        } else {
            let [a, b] = curves.range_rad;
            [a.to_degrees(), b.to_degrees()]
        }
    }

    /// Moves the crank to `input_deg` (wrapped for a full turn); on failure the pose
    /// stays and the notice says why, with the reachable range.
    pub(super) fn move_to_deg(&mut self, input_deg: f64) {
        if !input_deg.is_finite() {
            self.message = Some(Notice::InvalidValue {
                what: super::notice::ValueKind::InputAngle,
                value: input_deg,
                valid: linkage::error::Valid::Finite,
            });
            return;
        }
        let x = if self.curves().full_rotation {
            input_deg.rem_euclid(360.0)
        } else {
            input_deg
        }
        .to_radians();
        match self.pose.solve(x) {
            Ok(()) => {
                self.message = None;
                self.moved_by_hand = true;
            }
            Err(e) => self.message = Some(Notice::InputRefused(e)),
        }
    }

    /// Advances the animation by `dt_s` of real time at `speed` times real speed: the
    /// dynamic run plays in its own time; kinematic scenes turn at the crank speed.
    pub fn advance(&mut self, dt_s: f64, speed: f64) {
        let dt = dt_s * speed;
        if !(dt.is_finite() && dt > 0.0) {
            return;
        }
        if let Some(Ok(run)) = self.analyses.dynamics_mut() {
            // To the run's end, held there half a second (the time shown stays the
            // end's), then from the start again.
            let end = run.duration_s();
            if self.time_s >= end {
                self.held_s += dt;
                if self.held_s > HOLD_S {
                    self.time_s = 0.0;
                    self.held_s = 0.0;
                }
            } else {
                self.time_s = (self.time_s + dt).min(end);
            }
            if let Some(shown) = run.pose_at(self.time_s) {
                self.show_run_pose(shown);
            }
            return;
        }
        let speed_rad_s = self.mechanism().driver.speed_rad_s;
        // A scene without a crank speed still turns, at one turn per 4 s, for viewing.
        let w = if speed_rad_s != 0.0 {
            speed_rad_s
        } else {
            std::f64::consts::FRAC_PI_2
        };
        let mut next = self.input_rad().to_degrees() + (w * dt * self.play_direction).to_degrees();
        if !self.curves().full_rotation {
            let [a, b] = self.input_range_deg();
            if next > b || next < a {
                self.play_direction = -self.play_direction;
                next = next.clamp(a, b);
            }
        }
        self.move_to_deg(next);
    }

    /// Shows the dynamic run's pose at time `t`, s (clamped to the run).
    pub(super) fn show_time(&mut self, t: f64) {
        if let Some(Ok(run)) = self.analyses.dynamics_mut() {
            let t = t.clamp(0.0, run.duration_s());
            if let Some(shown) = run.pose_at(t) {
                self.time_s = t;
                self.show_run_pose(shown);
            }
        }
    }

    /// Shows a pose of the dynamic run as a pose of the scene's crank. Near the
    /// crank's dead point the run integrates another link's angle (its coordinate
    /// switches), and the pose it solves carries that link's angle as its input;
    /// the crank's own angle and rate, the sample's `q` and `q̇`, go in its place, so
    /// that the crank field, the view's legend, the plots' cursors and the force
    /// polygons all show the one state the run is in.
    fn show_run_pose(
        &mut self,
        (sample, mut pose): (linkage::dynamics::Sample, linkage::Solution),
    ) {
        pose.input_rad = sample.q;
        pose.input_speed_rad_s = sample.q_dot;
        self.pose.show(pose);
        self.moved_by_hand = false;
    }
}
