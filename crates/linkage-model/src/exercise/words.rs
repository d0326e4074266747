//! An exercise's words in the user's language, for the app's desk and the task
//! sheets alike: each question as the textbooks ask it, the variant's data (the
//! frame's pivots, the guides, every length as the length sliders name it, points
//! carried, the crank's speed; a cam's radii, offset, stroke and program), a typed
//! answer's refusal, a tolerance and a unit as shown, a cam law's name.

use linkage::SceneFile;
use linkage::cam::Law;
use linkage::cam::{CamSpec, FaceSpec, FollowerSpec, SegmentSpec};
use linkage::scene::Speed;
use linkage_diagram::numbers::significant;
use linkage_diagram::words::Lang;

use super::code::TypedAnswerError;
use super::quantity::{Axis, Quantity};
use super::{SubjectData, Tolerance, Unit};
use crate::session::params::{is_joint_point, length_params};
use crate::session::words::mw;

/// A question about `subject` as the student reads it.
pub fn question(q: &Quantity, subject: &SubjectData, lang: Lang) -> String {
    let scene = match subject {
        SubjectData::Scene(scene) => Some(scene.as_ref()),
        SubjectData::Cam(_) => None,
    };
    let link_words = |name: &str, lang| link_words(name, scene, lang);
    let deg = |d: &f64| significant(*d, 6);
    match q {
        Quantity::PointSpeed { point, crank_deg } => {
            mw!(
                lang,
                "exercise.q_point_speed",
                point = point,
                deg = deg(crank_deg)
            )
        }
        Quantity::PointAcceleration { point, crank_deg } => {
            mw!(
                lang,
                "exercise.q_point_acceleration",
                point = point,
                deg = deg(crank_deg)
            )
        }
        Quantity::AngularVelocity { link, crank_deg } => {
            mw!(
                lang,
                "exercise.q_angular_velocity",
                link = link_words(link, lang),
                deg = deg(crank_deg)
            )
        }
        Quantity::AngularAcceleration { link, crank_deg } => {
            mw!(
                lang,
                "exercise.q_angular_acceleration",
                link = link_words(link, lang),
                deg = deg(crank_deg)
            )
        }
        Quantity::InstantCentre {
            links: (a, b),
            crank_deg,
            axis,
        } => {
            let axis = match axis {
                Axis::X => "x",
                Axis::Y => "y",
            };
            mw!(
                lang,
                "exercise.q_instant_centre",
                axis = axis,
                a = link_words(a, lang),
                b = link_words(b, lang),
                deg = deg(crank_deg)
            )
        }
        Quantity::TimeRatio => mw!(lang, "exercise.q_time_ratio"),
        Quantity::Stroke { output } => {
            mw!(lang, "exercise.q_stroke", output = link_words(output, lang))
        }
        Quantity::Swing { output } => {
            mw!(lang, "exercise.q_swing", output = link_words(output, lang))
        }
        Quantity::LeastTransmissionAngle => mw!(lang, "exercise.q_least_transmission"),
        Quantity::BalancingTorque { crank_deg } => {
            mw!(lang, "exercise.q_balancing_torque", deg = deg(crank_deg))
        }
        Quantity::LargestPressureAngle => mw!(lang, "exercise.q_pressure_angle"),
        Quantity::LeastRadiusOfCurvature => mw!(lang, "exercise.q_curvature"),
    }
}

/// Why a typed answer was refused.
pub fn refusal(e: &TypedAnswerError, lang: Lang) -> String {
    match e {
        TypedAnswerError::NotANumber(_) => mw!(lang, "exercise.not_a_number"),
        TypedAnswerError::Unit { expected, .. } => {
            mw!(lang, "exercise.give_unit", unit = unit_words(*expected))
        }
    }
}

/// A unit as shown beside an answer (`m/s²`, `N·m`, `°`).
pub fn unit_words(unit: Unit) -> String {
    match unit {
        Unit::MetrePerSecondSquared => "m/s²".into(),
        Unit::MillimetrePerSecondSquared => "mm/s²".into(),
        Unit::RadianPerSecondSquared => "rad/s²".into(),
        Unit::Degree => "°".into(),
        Unit::NewtonMetre => "N·m".into(),
        Unit::KilogramSquareMetre => "kg·m²".into(),
        Unit::Rpm => "r/min".into(),
        other => other.symbol().to_string(),
    }
}

/// A tolerance as shown with a mark: `3 %` or `± 0.03 m/s`.
pub fn tolerance(t: Tolerance, unit: Unit) -> String {
    match t {
        Tolerance::Relative(r) => format!("{} %", significant(r * 100.0, 3)),
        Tolerance::Absolute(a) => format!("± {} {}", significant(a, 3), unit_words(unit))
            .trim_end()
            .to_string(),
    }
}

/// The mechanism's data: the frame's pivots (x, y), the sliders' guides, every
/// length as the sliders name it, then the crank's speed.
pub fn mechanism_data(scene: &SceneFile, lang: Lang) -> Vec<(String, String)> {
    let unit = linkage_diagram::numbers::unit_symbol(scene.length_unit);
    let mut rows: Vec<(String, String)> = Vec::new();
    for link in scene.links.iter().filter(|l| l.ground) {
        for (name, (x, y)) in &link.points {
            let at = format!("({}, {}) {unit}", significant(*x, 6), significant(*y, 6));
            rows.push((mw!(lang, "exercise.pivot", point = name), at));
        }
    }
    for s in &scene.sliders {
        let guide = mw!(
            lang,
            "exercise.guide_value",
            point = &s.through,
            deg = significant(s.angle, 6)
        );
        rows.push((mw!(lang, "exercise.guide", slider = &s.slider), guide));
    }
    rows.extend(length_params(scene).iter().filter_map(|p| {
        Some((
            p.label.clone(),
            format!("{} {unit}", significant(p.value(scene)?, 6)),
        ))
    }));
    rows.extend(carried_points(scene, unit, lang));
    let rpm = match scene.driver.speed {
        Speed::Rpm(n) => n,
        Speed::RadPerSecond(w) => w * 60.0 / std::f64::consts::TAU,
    };
    rows.push((mw!(lang, "exercise.crank_speed"), turning(rpm, lang)));
    rows.push((mw!(lang, "exercise.phi"), mw!(lang, "exercise.phi_from")));
    rows
}

/// A speed and its sense: `40 r/min, counter-clockwise`.
fn turning(rpm: f64, lang: Lang) -> String {
    let n = significant(rpm.abs(), 6);
    if rpm < 0.0 {
        mw!(lang, "exercise.turning_cw", n = n)
    } else {
        mw!(lang, "exercise.turning_ccw", n = n)
    }
}

/// A link of `scene` as the student reads it: the textbooks' word for a link named
/// by its role (ground, crank, coupler, rocker, slider), else by the joints it
/// carries as the textbooks name a link ("link CE", "构件 CE"), else its name as
/// written. Never the scene's inner name (`link_ce`) where the joints name it.
pub fn link_words(name: &str, scene: Option<&SceneFile>, lang: Lang) -> String {
    match name.to_ascii_lowercase().as_str() {
        "ground" | "frame" => mw!(lang, "exercise.ground"),
        "crank" => mw!(lang, "exercise.crank"),
        "coupler" => mw!(lang, "exercise.coupler"),
        "rocker" => mw!(lang, "exercise.rocker"),
        "slider" => mw!(lang, "exercise.slider"),
        "die" => mw!(lang, "exercise.die"),
        _ => match scene.and_then(|scene| joints_of(scene, name)) {
            Some(joints) => mw!(lang, "exercise.link_by_joints", joints = joints),
            None => mw!(lang, "exercise.link_named", name = name),
        },
    }
}

/// The joints the link `name` carries (its points other links or a guide share),
/// in order: `CE` for one-letter names, `O2-B` otherwise; none for fewer than two.
fn joints_of(scene: &SceneFile, name: &str) -> Option<String> {
    let (index, link) = scene
        .links
        .iter()
        .enumerate()
        .find(|(_, l)| l.name == name)?;
    let joints: Vec<&str> = link
        .points
        .keys()
        .filter(|p| is_joint_point(scene, p, index))
        .map(String::as_str)
        .collect();
    let single = joints.iter().all(|j| j.chars().count() == 1);
    (joints.len() >= 2).then(|| joints.join(if single { "" } else { "-" }))
}

/// Points a moving link carries that no other link shares (a coupler's tracer
/// point): each one's distance from the link's joints (`BE = 187 mm, CE = 193 mm`).
fn carried_points(scene: &SceneFile, unit: &str, lang: Lang) -> Vec<(String, String)> {
    let shared = |name: &str, me: usize| is_joint_point(scene, name, me);
    let mut rows = Vec::new();
    for (i, link) in scene.links.iter().enumerate().filter(|(_, l)| !l.ground) {
        let joints: Vec<_> = link.points.iter().filter(|(n, _)| shared(n, i)).collect();
        for (name, p) in link.points.iter().filter(|(n, _)| !shared(n, i)) {
            let distances: Vec<String> = joints
                .iter()
                .map(|(j, q)| {
                    format!(
                        "{j}{name} = {} {unit}",
                        significant((p.0 - q.0).hypot(p.1 - q.1), 6)
                    )
                })
                .collect();
            if !distances.is_empty() {
                rows.push((
                    mw!(
                        lang,
                        "exercise.carried",
                        point = name,
                        link = link_words(&link.name, Some(scene), lang)
                    ),
                    distances.join(", "),
                ));
            }
        }
    }
    rows
}

/// A cam's data: its radii, offset, stroke, speed and program.
pub fn cam_data(cam: &CamSpec, lang: Lang) -> Vec<(String, String)> {
    let mm = |v: f64| format!("{} mm", significant(v, 6));
    let mut rows = vec![(mw!(lang, "exercise.base_radius"), mm(cam.base_radius_mm))];
    let face = match cam.follower {
        FollowerSpec::Translating { offset_mm, face } => {
            rows.push((mw!(lang, "exercise.offset"), mm(offset_mm)));
            face
        }
        FollowerSpec::Oscillating { face, .. } => face,
    };
    if let FaceSpec::Roller { radius_mm } = face {
        rows.push((mw!(lang, "exercise.roller_radius"), mm(radius_mm)));
    }
    if let Some(h) = cam.segments.iter().find_map(SegmentSpec::lift) {
        rows.push((mw!(lang, "exercise.cam_stroke"), mm(h)));
    }
    rows.push((mw!(lang, "exercise.cam_speed"), turning(cam.rpm, lang)));
    let program: Vec<String> = cam
        .segments
        .iter()
        .enumerate()
        .map(|(i, s)| segment(s, i.checked_sub(1).map(|p| &cam.segments[p]), lang))
        .collect();
    rows.push((
        mw!(lang, "exercise.program"),
        program.join(&mw!(lang, "exercise.joiner")),
    ));
    rows
}

/// A segment of a cam's program; a dwell after a rise is the outer (远休止), any
/// other the inner (近休止).
fn segment(s: &SegmentSpec, before: Option<&SegmentSpec>, lang: Lang) -> String {
    let deg = significant(s.angle_deg(), 6);
    match *s {
        SegmentSpec::Rise { law, .. } => {
            mw!(
                lang,
                "exercise.seg_rise",
                deg = deg,
                law = law_name(law, lang)
            )
        }
        SegmentSpec::Return { law, .. } => {
            mw!(
                lang,
                "exercise.seg_return",
                deg = deg,
                law = law_name(law, lang)
            )
        }
        SegmentSpec::Dwell { .. } if matches!(before, Some(SegmentSpec::Rise { .. })) => {
            mw!(lang, "exercise.seg_dwell_far", deg = deg)
        }
        SegmentSpec::Dwell { .. } => mw!(lang, "exercise.seg_dwell_near", deg = deg),
    }
}

/// A law as the textbooks name it.
pub fn law_name(law: Law, lang: Lang) -> String {
    match law {
        Law::ConstantVelocity => mw!(lang, "law.constant_velocity"),
        Law::SimpleHarmonic => mw!(lang, "law.simple_harmonic"),
        Law::Cycloidal => mw!(lang, "law.cycloidal"),
        Law::Polynomial345 => mw!(lang, "law.polynomial_345"),
        Law::Polynomial4567 => mw!(lang, "law.polynomial_4567"),
        Law::ModifiedTrapezoid => mw!(lang, "law.modified_trapezoid"),
        Law::ModifiedSine => mw!(lang, "law.modified_sine"),
        Law::ModifiedConstantVelocity => mw!(lang, "law.modified_constant_velocity"),
    }
}

/// The heading of a variant's data.
pub fn data_heading(lang: Lang) -> String {
    mw!(lang, "exercise.data")
}

/// The heading of the questions.
pub fn questions_heading(lang: Lang) -> String {
    mw!(lang, "exercise.questions")
}

/// `text` with its subscripts marked `_{...}` written plainly (`v_{E}` as `v_E`),
/// for a terminal.
pub fn plain(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(at) = rest.find("_{") {
        let Some(len) = rest[at..].find('}') else {
            break;
        };
        out.push_str(&rest[..at + 1]);
        out.push_str(&rest[at + 2..at + len]);
        rest = &rest[at + len + 1..];
    }
    out.push_str(rest);
    out
}
