//! The quantities a question can ask, each one the analyses already compute, and
//! their values (the truth) on one variant, in SI.

use linkage::analysis::{Report, report};
use linkage::cam::CamDesign;
use linkage::instant_centres::{Centre, instant_centres};
use linkage::kinetostatics::Kinetostatics;
use linkage::{Kinematics, LinkageError, Solution};
use serde::{Deserialize, Serialize};

use super::unit::Kind;

/// What a question asks.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Quantity {
    /// A point's speed (the size of its velocity) at a crank angle.
    PointSpeed {
        /// The point's name.
        point: String,
        /// The crank's angle, degrees.
        crank_deg: f64,
    },
    /// The size of a point's acceleration at a crank angle.
    PointAcceleration {
        /// The point's name.
        point: String,
        /// The crank's angle, degrees.
        crank_deg: f64,
    },
    /// A link's angular velocity at a crank angle, counter-clockwise positive.
    AngularVelocity {
        /// The link's name.
        link: String,
        /// The crank's angle, degrees.
        crank_deg: f64,
    },
    /// A link's angular acceleration at a crank angle, counter-clockwise positive.
    AngularAcceleration {
        /// The link's name.
        link: String,
        /// The crank's angle, degrees.
        crank_deg: f64,
    },
    /// One coordinate of the instant centre of two links at a crank angle, in the
    /// scene's axes.
    InstantCentre {
        /// The two links' names.
        links: (String, String),
        /// The crank's angle, degrees.
        crank_deg: f64,
        /// Which coordinate.
        axis: Axis,
    },
    /// The time ratio K of the main output.
    TimeRatio,
    /// A slider's stroke (the output's name as the report names it).
    Stroke {
        /// The slider output's name.
        output: String,
    },
    /// A rocker's swing.
    Swing {
        /// The rocker output's name.
        output: String,
    },
    /// The least transmission angle over the cycle.
    LeastTransmissionAngle,
    /// The balancing torque on the crank at a crank angle (kinetostatics,
    /// counter-clockwise positive).
    BalancingTorque {
        /// The crank's angle, degrees.
        crank_deg: f64,
    },
    /// A cam's largest pressure angle over the turn (its size).
    LargestPressureAngle,
    /// A cam profile's least radius of curvature where the pitch curve is convex.
    LeastRadiusOfCurvature,
}

/// A coordinate axis of the scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Axis {
    /// x.
    X,
    /// y.
    Y,
}

/// Why a question has no value on a variant.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Unanswerable {
    /// The subject has no point of that name.
    #[error("there is no point \"{name}\" (the points: {})", known.join(", "))]
    NoPoint {
        /// The name asked for.
        name: String,
        /// The points there are.
        known: Vec<String>,
    },
    /// The subject has no link of that name.
    #[error("there is no link \"{name}\" (the links: {})", known.join(", "))]
    NoLink {
        /// The name asked for.
        name: String,
        /// The links there are.
        known: Vec<String>,
    },
    /// A motion asked of the frame, which does not move.
    #[error("\"{0}\" is the frame: it does not move")]
    Frame(String),
    /// The report has no output of that name.
    #[error("there is no {kind} output \"{name}\" (the outputs: {})", known.join(", "))]
    NoOutput {
        /// "slider" or "rocker".
        kind: &'static str,
        /// The name asked for.
        name: String,
        /// The outputs there are.
        known: Vec<String>,
    },
    /// A cam question asked of a mechanism, or a mechanism's of a cam.
    #[error("{0} is asked of a cam, the subject is a mechanism (or the other way round)")]
    WrongSubject(&'static str),
    /// The chain does not assemble at the crank angle asked.
    #[error("the mechanism does not assemble at crank angle {crank_deg} deg")]
    CannotAssemble {
        /// The angle asked, degrees.
        crank_deg: f64,
    },
    /// No time ratio: the crank does not turn fully or the output has no two limits.
    #[error("the mechanism has no time ratio K (its crank does not turn fully)")]
    NoTimeRatio,
    /// No transmission angle (no group with one).
    #[error("the mechanism has no transmission angle")]
    NoTransmissionAngle,
    /// The instant centre is at infinity or not fixed at this pose.
    #[error("the instant centre of {0} and {1} is at infinity or not fixed there")]
    CentreNotFinite(String, String),
    /// Another refusal of the solver.
    #[error("{0}")]
    Solver(String),
}

impl Quantity {
    /// What it measures.
    pub fn kind(&self) -> Kind {
        match self {
            Quantity::PointSpeed { .. } => Kind::Speed,
            Quantity::PointAcceleration { .. } => Kind::Acceleration,
            Quantity::AngularVelocity { .. } => Kind::AngularSpeed,
            Quantity::AngularAcceleration { .. } => Kind::AngularAcceleration,
            Quantity::InstantCentre { .. }
            | Quantity::Stroke { .. }
            | Quantity::LeastRadiusOfCurvature => Kind::Length,
            Quantity::TimeRatio => Kind::Ratio,
            Quantity::Swing { .. }
            | Quantity::LeastTransmissionAngle
            | Quantity::LargestPressureAngle => Kind::Angle,
            Quantity::BalancingTorque { .. } => Kind::Torque,
        }
    }

    /// Whether it is asked of a cam (else of a mechanism).
    pub fn of_cam(&self) -> bool {
        matches!(
            self,
            Quantity::LargestPressureAngle | Quantity::LeastRadiusOfCurvature
        )
    }

    /// The crank angle it is asked at, degrees, if any.
    pub fn crank_deg(&self) -> Option<f64> {
        match self {
            Quantity::PointSpeed { crank_deg, .. }
            | Quantity::PointAcceleration { crank_deg, .. }
            | Quantity::AngularVelocity { crank_deg, .. }
            | Quantity::AngularAcceleration { crank_deg, .. }
            | Quantity::InstantCentre { crank_deg, .. }
            | Quantity::BalancingTorque { crank_deg } => Some(*crank_deg),
            _ => None,
        }
    }
}

/// A variant's subject built for the analyses: a mechanism with its report made
/// once when first asked for, or a cam.
pub enum Built {
    /// A mechanism.
    Mechanism {
        /// Its kinematics.
        kinematics: Box<Kinematics>,
        /// Its report, once made.
        report: Option<Box<Report>>,
    },
    /// A disc cam.
    Cam(Box<CamDesign>),
}

impl Built {
    /// The mechanism's report (made on the first call).
    ///
    /// # Errors
    /// The subject is a cam, or the report is refused (the chain assembles nowhere).
    pub fn report(&mut self) -> Result<&Report, Unanswerable> {
        let Built::Mechanism {
            kinematics,
            report: slot,
        } = self
        else {
            return Err(Unanswerable::WrongSubject("a mechanism's quantity"));
        };
        if slot.is_none() {
            let made = report(kinematics).map_err(|e| Unanswerable::Solver(e.to_string()))?;
            *slot = Some(Box::new(made));
        }
        Ok(slot.as_deref().expect("just made"))
    }

    fn kinematics(&mut self) -> Result<&mut Kinematics, Unanswerable> {
        match self {
            Built::Mechanism { kinematics, .. } => Ok(kinematics),
            Built::Cam(_) => Err(Unanswerable::WrongSubject("a mechanism's quantity")),
        }
    }

    /// The motion at crank angle `crank_deg`.
    fn solve(&mut self, crank_deg: f64) -> Result<(Solution, &Kinematics), Unanswerable> {
        let k = self.kinematics()?;
        let s = k
            .solve(crank_deg.to_radians())
            .and_then(|s| linkage::overflow::check(k, &s).map(|()| s))
            .map_err(|e| match e {
                LinkageError::CannotAssemble { .. } => Unanswerable::CannotAssemble { crank_deg },
                other => Unanswerable::Solver(other.to_string()),
            })?;
        Ok((s, k))
    }
}

/// The value of `q` on `built`, SI (rad for angles).
///
/// # Errors
/// A name the subject lacks, a pose where the chain does not assemble, a quantity
/// the subject does not have.
pub fn truth_si(q: &Quantity, built: &mut Built) -> Result<f64, Unanswerable> {
    match q {
        Quantity::PointSpeed { point, crank_deg } => {
            motion_at(built, Read::Point(point), *crank_deg, false)
        }
        Quantity::PointAcceleration { point, crank_deg } => {
            motion_at(built, Read::Point(point), *crank_deg, true)
        }
        Quantity::AngularVelocity { link, crank_deg } => {
            motion_at(built, Read::Link(link), *crank_deg, false)
        }
        Quantity::AngularAcceleration { link, crank_deg } => {
            motion_at(built, Read::Link(link), *crank_deg, true)
        }
        Quantity::InstantCentre {
            links,
            crank_deg,
            axis,
        } => centre_coordinate(built, links, *crank_deg, *axis),
        Quantity::TimeRatio => built.report()?.time_ratio.ok_or(Unanswerable::NoTimeRatio),
        Quantity::Stroke { output } => output_span(built.report()?, output, true),
        Quantity::Swing { output } => output_span(built.report()?, output, false),
        Quantity::LeastTransmissionAngle => built
            .report()?
            .transmission_angle_rad
            .as_ref()
            .map(|t| t.min)
            .ok_or(Unanswerable::NoTransmissionAngle),
        Quantity::BalancingTorque { crank_deg } => balancing_torque(built, *crank_deg),
        Quantity::LargestPressureAngle | Quantity::LeastRadiusOfCurvature => cam_truth(q, built),
    }
}

/// What a question reads off the motion at one pose: a point's speed or the size of
/// its acceleration, a link's angular velocity or acceleration.
enum Read<'a> {
    Point(&'a str),
    Link(&'a str),
}

fn motion_at(
    built: &mut Built,
    read: Read,
    crank_deg: f64,
    acceleration: bool,
) -> Result<f64, Unanswerable> {
    // The names first: a name the subject lacks is said whether or not the chain
    // assembles at the angle.
    match read {
        Read::Point(name) => point_id(built.kinematics()?.mechanism(), name).map(drop)?,
        Read::Link(name) => moving_link_id(built.kinematics()?.mechanism(), name).map(drop)?,
    }
    let (s, k) = built.solve(crank_deg)?;
    let m = k.mechanism();
    let derivative = usize::from(acceleration);
    match read {
        Read::Point(name) => {
            let p = &s.points[point_id(m, name)?];
            Ok([p.velocity, p.acceleration][derivative].norm())
        }
        Read::Link(name) => {
            let l = &s.links[moving_link_id(m, name)?];
            Ok([l.omega_rad_s, l.alpha_rad_s2][derivative])
        }
    }
}

/// The point named `name`, or the points there are.
fn point_id(m: &linkage::Mechanism, name: &str) -> Result<linkage::PointId, Unanswerable> {
    m.point_index(name).ok_or_else(|| Unanswerable::NoPoint {
        name: name.into(),
        known: m.points.iter().map(|p| p.name.clone()).collect(),
    })
}

/// The link named `name`, or the links there are.
fn link_id(m: &linkage::Mechanism, name: &str) -> Result<linkage::LinkId, Unanswerable> {
    m.link_index(name).ok_or_else(|| Unanswerable::NoLink {
        name: name.into(),
        known: m.links.iter().map(|l| l.name.clone()).collect(),
    })
}

/// The moving link named `name` (the frame refused: it does not move).
fn moving_link_id(m: &linkage::Mechanism, name: &str) -> Result<linkage::LinkId, Unanswerable> {
    let id = link_id(m, name)?;
    if id == m.ground {
        return Err(Unanswerable::Frame(name.into()));
    }
    Ok(id)
}

fn centre_coordinate(
    built: &mut Built,
    (a, b): &(String, String),
    crank_deg: f64,
    axis: Axis,
) -> Result<f64, Unanswerable> {
    let m = built.kinematics()?.mechanism();
    link_id(m, a)?;
    link_id(m, b)?;
    let (s, k) = built.solve(crank_deg)?;
    let m = k.mechanism();
    let (i, j) = (link_id(m, a)?, link_id(m, b)?);
    let at = instant_centres(m, &s)
        .between(i, j)
        .and_then(|c| match c.centre {
            Centre::At(p) => Some(p),
            Centre::AtInfinity(_) => None,
        });
    let p = at.ok_or_else(|| Unanswerable::CentreNotFinite(a.clone(), b.clone()))?;
    Ok(match axis {
        Axis::X => p[0],
        Axis::Y => p[1],
    })
}

fn output_span(report: &Report, output: &str, slider: bool) -> Result<f64, Unanswerable> {
    let map = if slider {
        &report.strokes_m
    } else {
        &report.swings_rad
    };
    map.get(output)
        .copied()
        .ok_or_else(|| Unanswerable::NoOutput {
            kind: if slider { "slider" } else { "rocker" },
            name: output.to_string(),
            known: map.keys().cloned().collect(),
        })
}

fn balancing_torque(built: &mut Built, crank_deg: f64) -> Result<f64, Unanswerable> {
    let k = built.kinematics()?;
    let solver = |e: LinkageError| Unanswerable::Solver(e.to_string());
    let mut statics = Kinetostatics::new(k).map_err(solver)?;
    let state = statics.at(k, crank_deg.to_radians()).map_err(|e| match e {
        LinkageError::CannotAssemble { .. } => Unanswerable::CannotAssemble { crank_deg },
        other => solver(other),
    })?;
    Ok(state.torque_newton_euler)
}

fn cam_truth(q: &Quantity, built: &Built) -> Result<f64, Unanswerable> {
    let Built::Cam(design) = built else {
        return Err(Unanswerable::WrongSubject("a cam's quantity"));
    };
    let extremes = design.cam.extremes();
    Ok(match q {
        Quantity::LargestPressureAngle => extremes
            .pressure_by_segment
            .iter()
            .map(|e| e.value.abs())
            .fold(0.0, f64::max),
        _ => extremes.smallest_profile_radius.value,
    })
}
