//! A planetary set's assembly conditions, in modules (one module for the set):
//! coaxiality (every planet meets every central gear at one distance from the
//! carrier's axis), equal spacing of k planets ((z_sun + z_ring)/k whole, for planets
//! of one gear), and neighbouring planets clear ((z_s + z_p) sin(π/k) > z_p + 2).

use std::f64::consts::PI;

use super::train_file::{GearFile, TrainFile};
use super::train_results::AssemblyCheck;

/// The checks of every carrier with planets.
pub(crate) fn checks(file: &TrainFile) -> Vec<AssemblyCheck> {
    let mut out = Vec::new();
    for h in &file.members {
        let planets: Vec<&str> = file
            .members
            .iter()
            .filter(|m| m.axis_on == h.name)
            .map(|m| m.name.as_str())
            .collect();
        if planets.is_empty() {
            continue;
        }
        // (planet gear, central gear) of every mesh between them.
        let pairs: Vec<(&GearFile, &GearFile)> = file
            .meshes
            .iter()
            .filter_map(|(a, b)| {
                let (ga, gb) = (find(file, a)?, find(file, b)?);
                let on = |g: &GearFile| planets.contains(&g.member.as_str());
                match (on(ga), on(gb)) {
                    (true, false) => Some((ga, gb)),
                    (false, true) => Some((gb, ga)),
                    _ => None,
                }
            })
            .collect();
        if pairs.is_empty() {
            continue;
        }
        // Each planet's axis at one distance from the carrier's, whatever central
        // gears it meets (double planets may sit at two distances).
        let mut distances: Vec<f64> = Vec::new();
        let mut holds = true;
        for planet in &planets {
            let mut own: Vec<f64> = Vec::new();
            for (p, c) in pairs.iter().filter(|(p, _)| p.member == *planet) {
                let d = centre_distance(p, c);
                if !own.iter().any(|x| (x - d).abs() < 1e-9) {
                    own.push(d);
                }
            }
            holds &= own.len() <= 1;
            for d in own {
                if !distances.iter().any(|x| (x - d).abs() < 1e-9) {
                    distances.push(d);
                }
            }
        }
        out.push(AssemblyCheck::Coaxial {
            carrier: h.name.clone(),
            holds,
            distances_modules: distances,
        });
        if let Some(k) = h.planets {
            simple_set(&mut out, &h.name, k, &pairs);
        }
    }
    out
}

/// Equal spacing and neighbours for planets of one gear between a sun and a ring.
fn simple_set(
    out: &mut Vec<AssemblyCheck>,
    carrier: &str,
    k: u32,
    pairs: &[(&GearFile, &GearFile)],
) {
    let sun = pairs.iter().find(|(_, c)| !c.internal);
    let ring = pairs.iter().find(|(_, c)| c.internal);
    let (Some((p, s)), Some((p2, r))) = (sun, ring) else {
        return;
    };
    // One planet has no neighbour, and spaces equally on its own.
    if p.name != p2.name || k < 2 {
        return;
    }
    let value = f64::from(s.teeth + r.teeth) / f64::from(k);
    out.push(AssemblyCheck::EqualSpacing {
        carrier: carrier.into(),
        planets: k,
        value,
        holds: (value - value.round()).abs() < 1e-9,
    });
    let (zs, zp) = (f64::from(s.teeth), f64::from(p.teeth));
    let clearance = (zs + zp) * (PI / f64::from(k)).sin() - (zp + 2.0);
    out.push(AssemblyCheck::Neighbours {
        carrier: carrier.into(),
        planets: k,
        clearance_modules: clearance,
        holds: clearance > 0.0,
    });
}

/// The distance between a planet's axis and a central gear's, modules.
fn centre_distance(planet: &GearFile, central: &GearFile) -> f64 {
    let (zp, zc) = (f64::from(planet.teeth), f64::from(central.teeth));
    if central.internal {
        0.5 * (zc - zp)
    } else {
        0.5 * (zc + zp)
    }
}

fn find<'a>(file: &'a TrainFile, name: &str) -> Option<&'a GearFile> {
    file.gears.iter().find(|g| g.name == name)
}
