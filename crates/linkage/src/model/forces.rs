//! The force elements (springs, dampers, forces, torques, gravity) in SI, each naming
//! points and links the scene has.

use super::units::{finite, invalid, positive, positive_named, scene_angle};
use crate::error::SceneProblem;
use crate::error::{LinkageError, Result};
use crate::error::{Param, Valid};
use crate::model::{Link, Point};
use crate::scene::{ForcesSpec, FreeLength};

pub(super) fn convert_forces(
    f: &ForcesSpec,
    len: f64,
    ang: f64,
    links: &[Link],
    points: &[Point],
) -> Result<ForcesSpec> {
    let has_point = |n: &str, ctx: &str| -> Result<()> {
        if points.iter().any(|p| p.name == n) {
            Ok(())
        } else {
            Err(invalid(SceneProblem::ForceNamesUnknownPoint {
                element: ctx.to_string(),
                name: n.to_string(),
            }))
        }
    };
    let has_link = |n: &str, ctx: &str| -> Result<()> {
        if links.iter().any(|l| l.name == n) {
            Ok(())
        } else {
            Err(invalid(SceneProblem::ForceNamesUnknownLink {
                element: ctx.to_string(),
                name: n.to_string(),
            }))
        }
    };
    let mut out = f.clone();
    for s in &mut out.springs {
        has_point(&s.a, "spring")?;
        has_point(&s.b, "spring")?;
        positive_named(s.k_n_per_m, || format!("spring {}-{} k_n_per_m", s.a, s.b))?;
        if let FreeLength::Length(l) = &mut s.free_length {
            *l = finite("spring free_length", *l)? * len;
            if *l < 0.0 {
                return Err(LinkageError::invalid(
                    Param::Scene(format!("spring {}-{} free_length", s.a, s.b)),
                    *l,
                    Valid::NonNegativeOnly,
                ));
            }
        }
    }
    for d in &out.dampers {
        match d {
            crate::scene::DamperSpec::Linear { a, b, c_n_s_per_m } => {
                has_point(a, "damper")?;
                has_point(b, "damper")?;
                positive("damper c_n_s_per_m", *c_n_s_per_m)?;
            }
            crate::scene::DamperSpec::Rotational {
                link_a,
                link_b,
                c_n_m_s,
            } => {
                has_link(link_a, "damper")?;
                has_link(link_b, "damper")?;
                positive("damper c_n_m_s", *c_n_m_s)?;
            }
        }
    }
    for pf in &out.point_forces {
        has_point(&pf.point, "point force")?;
        finite("point force x", pf.force_n.0)?;
        finite("point force y", pf.force_n.1)?;
    }
    for t in &out.torques {
        has_link(&t.link, "torque")?;
        finite("torque", t.torque_n_m)?;
    }
    for s in &mut out.stops {
        has_link(&s.link, "stop")?;
        s.angle = scene_angle("stop angle", s.angle, ang)?;
    }
    if let Some((gx, gy)) = out.gravity {
        finite("gravity x", gx)?;
        finite("gravity y", gy)?;
    }
    Ok(out)
}
