//! The drive, validated and in SI: the motor's torque against its speed, reflected to
//! the crank through the gear or the train, and the inertia the train, rotor and
//! flywheel add there.

use super::drive_train::DriveTrain;
use crate::error::{DriveTrainProblem, LinkageError, Result};
use crate::error::{Param, SceneProblem, Valid};
use crate::scene::{DriveSpec, MotorSpec, Shaft};

const RPM: f64 = std::f64::consts::TAU / 60.0;

/// The motor's characteristic on its own shaft, SI.
#[derive(Clone, Debug, PartialEq)]
pub enum Motor {
    /// The same torque at every speed, N·m.
    Constant(f64),
    /// `T = rated · (no_load − ω) / (no_load − rated_speed)`, rad/s and N·m.
    Linear {
        /// No-load speed, rad/s.
        no_load_rad_s: f64,
        /// Torque at the rated speed, N·m.
        rated_torque_n_m: f64,
        /// Rated speed, rad/s.
        rated_rad_s: f64,
    },
    /// `(rad/s, N·m)` in rising speed, joined by straight lines, ends held.
    Table(Vec<(f64, f64)>),
}

impl Motor {
    /// Torque at motor speed `w`, N·m.
    pub fn torque(&self, w: f64) -> f64 {
        match self {
            Self::Constant(t) => *t,
            Self::Linear {
                no_load_rad_s,
                rated_torque_n_m,
                rated_rad_s,
            } => rated_torque_n_m * (no_load_rad_s - w) / (no_load_rad_s - rated_rad_s),
            Self::Table(points) => table(points, w),
        }
    }
}

/// Straight lines between the points, the end values beyond them.
fn table(points: &[(f64, f64)], w: f64) -> f64 {
    let i = points.partition_point(|&(x, _)| x <= w);
    match (i, points.len()) {
        (0, _) => points[0].1,
        (i, n) if i == n => points[n - 1].1,
        (i, _) => {
            let ((x0, y0), (x1, y1)) = (points[i - 1], points[i]);
            y0 + (y1 - y0) * (w - x0) / (x1 - x0)
        }
    }
}

/// A motor driving the crank through a gear, with the inertia it adds at the crank.
#[derive(Clone, Debug, PartialEq)]
pub struct Drive {
    /// The motor.
    pub motor: Motor,
    /// Motor turns per crank turn (the train's, unsigned, where there is one).
    pub gear_ratio: f64,
    /// Rotor, train and flywheel inertia reduced to the crank, kg·m².
    pub inertia_at_crank_kg_m2: f64,
    /// The flywheel's share of it, kg·m².
    pub flywheel_at_crank_kg_m2: f64,
    /// The motor rotor's share of it (given beside the train), kg·m².
    pub rotor_at_crank_kg_m2: f64,
    /// The train between motor and crank, where the scene gives one.
    pub train: Option<DriveTrain>,
}

impl Drive {
    /// The torque the motor gives the crank turning at `crank_rad_s` (an ideal gear:
    /// the motor turns `gear_ratio` times faster with `gear_ratio` times less torque).
    pub fn torque_at_crank(&self, crank_rad_s: f64) -> f64 {
        self.gear_ratio * self.motor.torque(self.gear_ratio * crank_rad_s)
    }

    /// Validates a scene's drive and puts it in SI.
    ///
    /// # Errors
    /// A gear ratio that is not finite and > 0, an inertia < 0, a linear motor whose
    /// rated speed is not below its no-load speed, a table not in rising speed, a
    /// train that cannot drive the crank ([`DriveTrain::from_spec`]) or whose ratio
    /// is not the `gear_ratio` given.
    pub fn from_spec(spec: &DriveSpec) -> Result<Self> {
        let invalid = |name: &str, value: f64, valid: Valid| {
            LinkageError::invalid(Param::Scene(format!("drive.{name}")), value, valid)
        };
        let train = spec.train.as_deref().map(DriveTrain::from_spec).transpose();
        let train = train.map_err(train_refused)?;
        let n = match &train {
            Some(t) => train_ratio(spec.gear_ratio, t.ratio)?,
            None => spec.gear_ratio,
        };
        if !(n.is_finite() && n > 0.0) {
            return Err(invalid("gear_ratio", n, Valid::GearRatio));
        }
        for (name, j) in [
            ("motor_inertia_kg_m2", spec.motor_inertia_kg_m2),
            ("flywheel_kg_m2", spec.flywheel_kg_m2),
        ] {
            if !(j.is_finite() && j >= 0.0) {
                return Err(invalid(name, j, Valid::NonNegative));
            }
        }
        let flywheel = match spec.flywheel_on {
            Shaft::Crank => spec.flywheel_kg_m2,
            Shaft::Motor => spec.flywheel_kg_m2 * n * n,
        };
        let train_inertia = train.as_ref().map_or(0.0, |t| t.inertia_at_crank_kg_m2);
        let rotor = spec.motor_inertia_kg_m2 * n * n;
        Ok(Self {
            motor: motor(&spec.motor, &invalid)?,
            gear_ratio: n,
            inertia_at_crank_kg_m2: flywheel + rotor + train_inertia,
            flywheel_at_crank_kg_m2: flywheel,
            rotor_at_crank_kg_m2: rotor,
            train,
        })
    }

    /// The rotor's and the train's inertia at the crank, the flywheel's left out
    /// (what turns with the crank beside a flywheel being sized), kg·m².
    pub fn inertia_beside_flywheel_kg_m2(&self) -> f64 {
        self.rotor_at_crank_kg_m2
            + self
                .train
                .as_ref()
                .map_or(0.0, |t| t.inertia_at_crank_kg_m2)
    }
}

fn train_refused(p: DriveTrainProblem) -> LinkageError {
    LinkageError::SceneInvalid(Box::new(SceneProblem::DriveTrain(p)))
}

/// The train's ratio, unsigned (the motor may turn either way); a `gear_ratio` given
/// beside it (other than the default 1) must be the same to 1e-9.
fn train_ratio(given: f64, train: f64) -> Result<f64> {
    let n = train.abs();
    if given != 1.0 && (given - n).abs() > 1e-9 * n {
        return Err(train_refused(DriveTrainProblem::RatioContradicts {
            given,
            train: n,
        }));
    }
    Ok(n)
}

/// The motor in SI, each number checked.
fn motor(spec: &MotorSpec, invalid: &dyn Fn(&str, f64, Valid) -> LinkageError) -> Result<Motor> {
    let finite = |name: &str, v: f64| {
        if v.is_finite() {
            Ok(v)
        } else {
            Err(invalid(name, v, Valid::Finite))
        }
    };
    match spec {
        MotorSpec::Constant { torque_n_m } => {
            Ok(Motor::Constant(finite("torque_n_m", *torque_n_m)?))
        }
        MotorSpec::Linear {
            no_load_rpm,
            rated_torque_n_m,
            rated_rpm,
        } => {
            let (w0, t, w) = (
                finite("no_load_rpm", *no_load_rpm)?,
                finite("rated_torque_n_m", *rated_torque_n_m)?,
                finite("rated_rpm", *rated_rpm)?,
            );
            if w >= w0 {
                return Err(invalid(
                    "rated_rpm",
                    w,
                    Valid::BelowNoLoad { no_load_rpm: w0 },
                ));
            }
            Ok(Motor::Linear {
                no_load_rad_s: w0 * RPM,
                rated_torque_n_m: t,
                rated_rad_s: w * RPM,
            })
        }
        MotorSpec::Table { points } => {
            if points.len() < 2 {
                return Err(invalid("points", points.len() as f64, Valid::TableOfTwo));
            }
            for (i, pair) in points.windows(2).enumerate() {
                if pair[1].0.partial_cmp(&pair[0].0) != Some(std::cmp::Ordering::Greater) {
                    return Err(invalid(
                        &format!("points[{}] speed", i + 1),
                        pair[1].0,
                        Valid::RisingSpeeds,
                    ));
                }
            }
            points
                .iter()
                .map(|&(rpm, t)| {
                    Ok((
                        finite("points speed", rpm)? * RPM,
                        finite("points torque", t)?,
                    ))
                })
                .collect::<Result<Vec<_>>>()
                .map(Motor::Table)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn drive(motor: MotorSpec, ratio: f64, flywheel_on: Shaft) -> Result<Drive> {
        Drive::from_spec(&DriveSpec {
            motor,
            gear_ratio: ratio,
            train: None,
            motor_inertia_kg_m2: 0.5,
            flywheel_kg_m2: 2.0,
            flywheel_on,
        })
    }

    #[test]
    fn a_linear_motor_gives_its_rated_torque_at_its_rated_speed_and_none_at_no_load() {
        let linear = MotorSpec::Linear {
            no_load_rpm: 1500.0,
            rated_torque_n_m: 100.0,
            rated_rpm: 1450.0,
        };
        let d = drive(linear, 10.0, Shaft::Motor).expect("valid");
        // Crank at 145 rpm: the motor at its rated 1450 rpm, ten times the torque.
        assert!((d.torque_at_crank(145.0 * RPM) - 1000.0).abs() < 1e-9);
        assert!(d.torque_at_crank(150.0 * RPM).abs() < 1e-9);
        // Rotor 0.5 and flywheel 2 on the motor shaft: both times 10².
        assert!((d.inertia_at_crank_kg_m2 - 250.0).abs() < 1e-12);
        let on_crank =
            drive(MotorSpec::Constant { torque_n_m: 3.0 }, 10.0, Shaft::Crank).expect("valid");
        assert!((on_crank.inertia_at_crank_kg_m2 - 52.0).abs() < 1e-12);
        assert_eq!(on_crank.torque_at_crank(123.0), 30.0);
    }

    #[test]
    fn a_table_is_joined_by_lines_and_held_beyond_its_ends() {
        let table = MotorSpec::Table {
            points: vec![(0.0, 300.0), (1000.0, 200.0), (1500.0, 0.0)],
        };
        let m = drive(table, 1.0, Shaft::Crank).expect("valid").motor;
        assert!((m.torque(500.0 * RPM) - 250.0).abs() < 1e-9);
        assert!((m.torque(1250.0 * RPM) - 100.0).abs() < 1e-9);
        assert_eq!(m.torque(-5.0), 300.0);
        assert_eq!(m.torque(2000.0 * RPM), 0.0);
    }

    #[test]
    fn a_bad_drive_is_refused_naming_the_field_and_its_range() {
        let constant = || MotorSpec::Constant { torque_n_m: 1.0 };
        let name_of = |r: Result<Drive>| match r {
            Err(LinkageError::InvalidParameter {
                param: Param::Scene(name),
                ..
            }) => name,
            other => panic!("expected a refusal, got {other:?}"),
        };
        assert_eq!(
            name_of(drive(constant(), 0.0, Shaft::Crank)),
            "drive.gear_ratio"
        );
        assert_eq!(
            name_of(drive(constant(), f64::NAN, Shaft::Crank)),
            "drive.gear_ratio"
        );
        let backwards = MotorSpec::Linear {
            no_load_rpm: 1000.0,
            rated_torque_n_m: 1.0,
            rated_rpm: 1200.0,
        };
        assert_eq!(
            name_of(drive(backwards, 1.0, Shaft::Crank)),
            "drive.rated_rpm"
        );
        let unsorted = MotorSpec::Table {
            points: vec![(0.0, 1.0), (0.0, 2.0)],
        };
        assert_eq!(
            name_of(drive(unsorted, 1.0, Shaft::Crank)),
            "drive.points[1] speed"
        );
    }
}
