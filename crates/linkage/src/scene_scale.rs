//! A scene made larger or smaller as a whole: the same machine at another scale, of
//! the same material and under the same gravity (geometric similarity).
//!
//! With lengths times `s`, masses go with the volume (s³) and inertias with s⁵. Under
//! unchanged gravity the motion keeps its angles but runs √s times slower, so the
//! driver's speed is divided by √s, and every force element is scaled so that its
//! torque keeps the same share of the gravity torque (s⁴): springs s², linear dampers
//! s^2.5, point forces s³, torques s⁴, rotational dampers s^4.5. Every analysis of
//! the scaled scene is then the original's in the units' scaling: positions ×s,
//! velocities ×√s, accelerations ×1, angular speeds ÷√s, forces ×s³, torques and
//! energies ×s⁴, times ×√s. The scale property tests rely on exactly that.

use crate::scene::{DamperSpec, DriveSpec, FreeLength, MotorSpec, SceneFile, Speed};

/// How each quantity of a scene scales when its lengths are multiplied by `s`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Similarity {
    /// Lengths.
    pub length: f64,
    /// Times (√s): the motion under unchanged gravity runs this much slower.
    pub time: f64,
}

impl Similarity {
    /// The similarity of a length factor `s` (> 0).
    pub fn of_length(s: f64) -> Self {
        Self {
            length: s,
            time: s.sqrt(),
        }
    }

    /// Linear velocities (m/s).
    pub fn velocity(&self) -> f64 {
        self.length / self.time
    }

    /// Linear accelerations (m/s²): 1, since gravity is kept.
    pub fn acceleration(&self) -> f64 {
        self.length / (self.time * self.time)
    }

    /// Angular speeds (rad/s).
    pub fn angular_speed(&self) -> f64 {
        1.0 / self.time
    }

    /// Angular accelerations (rad/s²).
    pub fn angular_acceleration(&self) -> f64 {
        1.0 / (self.time * self.time)
    }

    /// Masses (kg).
    pub fn mass(&self) -> f64 {
        self.length.powi(3)
    }

    /// Moments of inertia (kg·m²).
    pub fn inertia(&self) -> f64 {
        self.length.powi(5)
    }

    /// Forces (N).
    pub fn force(&self) -> f64 {
        self.length.powi(3)
    }

    /// Torques and energies (N·m, J).
    pub fn torque(&self) -> f64 {
        self.length.powi(4)
    }
}

impl SceneFile {
    /// The same machine `s` times larger (see the module's documentation for how
    /// each quantity follows). Angles, the branches and the names are unchanged.
    pub fn scaled(&self, s: f64) -> SceneFile {
        let k = Similarity::of_length(s);
        let mut out = self.clone();
        let xy = |(x, y): (f64, f64)| (x * s, y * s);
        for link in &mut out.links {
            for p in link.points.values_mut() {
                *p = xy(*p);
            }
            link.centroid = link.centroid.map(xy);
            link.mass = link.mass.map(|m| m * k.mass());
            link.inertia = link.inertia.map(|i| i * k.inertia());
        }
        for (x, y, _) in out.guess.values_mut() {
            (*x, *y) = (*x * s, *y * s);
        }
        out.driver.speed = match out.driver.speed {
            Speed::Rpm(n) => Speed::Rpm(n * k.angular_speed()),
            Speed::RadPerSecond(w) => Speed::RadPerSecond(w * k.angular_speed()),
        };
        scale_forces(&mut out, &k);
        if let Some(drive) = &mut out.drive {
            scale_drive(drive, &k);
        }
        scale_cams(&mut out, s);
        out
    }
}

/// The cam joints: the roller's radius is a length, and so are a translating
/// follower's rest and lifts; an arm's are angles.
fn scale_cams(out: &mut SceneFile, s: f64) {
    use crate::cam::SegmentSpec;
    let ground_points: Vec<&String> = out
        .links
        .iter()
        .filter(|l| l.ground)
        .flat_map(|l| l.points.keys())
        .collect();
    let arms: Vec<bool> = out
        .cams
        .iter()
        .map(|cam| {
            out.links
                .iter()
                .filter(|l| l.name == cam.follower)
                .flat_map(|l| l.points.keys())
                .any(|p| ground_points.contains(&p))
        })
        .collect();
    for (cam, arm) in out.cams.iter_mut().zip(arms) {
        cam.roller_radius *= s;
        if arm {
            continue;
        }
        cam.rest *= s;
        for lift in cam.segments.iter_mut().filter_map(SegmentSpec::lift_mut) {
            *lift *= s;
        }
    }
}

/// The force elements, each so that its torque scales as gravity's does.
fn scale_forces(out: &mut SceneFile, k: &Similarity) {
    let f = &mut out.forces;
    // A spring's force k·Δx goes with s³ when Δx goes with s.
    let stiffness = k.force() / k.length;
    for spring in &mut f.springs {
        spring.k_n_per_m *= stiffness;
        if let FreeLength::Length(l) = &mut spring.free_length {
            *l *= k.length;
        }
    }
    for damper in &mut f.dampers {
        match damper {
            DamperSpec::Linear { c_n_s_per_m, .. } => *c_n_s_per_m *= k.force() / k.velocity(),
            DamperSpec::Rotational { c_n_m_s, .. } => *c_n_m_s *= k.torque() / k.angular_speed(),
        }
    }
    for force in &mut f.point_forces {
        force.force_n = (force.force_n.0 * k.force(), force.force_n.1 * k.force());
    }
    for torque in &mut f.torques {
        torque.torque_n_m *= k.torque();
    }
}

/// The drive: its torques as every torque, its speeds as the crank's, its inertias as
/// the links'. The gear ratio is a pure number.
fn scale_drive(drive: &mut DriveSpec, k: &Similarity) {
    let (torque, speed) = (k.torque(), k.angular_speed());
    match &mut drive.motor {
        MotorSpec::Constant { torque_n_m } => *torque_n_m *= torque,
        MotorSpec::Linear {
            no_load_rpm,
            rated_torque_n_m,
            rated_rpm,
        } => {
            *no_load_rpm *= speed;
            *rated_torque_n_m *= torque;
            *rated_rpm *= speed;
        }
        MotorSpec::Table { points } => {
            for (rpm, t) in points {
                (*rpm, *t) = (*rpm * speed, *t * torque);
            }
        }
    }
    drive.motor_inertia_kg_m2 *= k.inertia();
    drive.flywheel_kg_m2 *= k.inertia();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_units_follow_from_lengths_and_times() {
        let k = Similarity::of_length(100.0);
        assert_eq!(k.time, 10.0);
        assert_eq!(k.velocity(), 10.0);
        assert_eq!(k.acceleration(), 1.0);
        // Torque of gravity m g L and of inertia I α agree: s⁴ both.
        assert_eq!(k.mass() * k.acceleration() * k.length, k.torque());
        assert_eq!(k.inertia() * k.angular_acceleration(), k.torque());
    }
}
