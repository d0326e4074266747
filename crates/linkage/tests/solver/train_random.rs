//! Gear trains nobody chose: random members (some on carriers), gears of 6 to 200
//! teeth (some internal), meshes and belt stages between any of them, inputs on any
//! member with any speed, a name now and then that is not defined. Every train is
//! solved with finite speeds or refused with words; a load on any member gives finite
//! torques whose powers cancel, or is refused; as a scene's drive, a finite ratio and
//! inertia or a refusal. Nothing panics.

use linkage::gears::Train;
use linkage::gears::train_file::{
    GearFile, InputFile, MemberFile, StageFile, StageKind, TrainFile,
};
use linkage::model::DriveTrain;
use linkage::scene::DriveTrainSpec;
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("LINKAGE_PROPERTY_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(512)
}

/// Member `i`'s name; index 9 is a name no member has.
fn member(i: usize) -> String {
    if i == 9 {
        "nowhere".into()
    } else {
        format!("m{i}")
    }
}

/// A random train of `members` members.
fn train_file(
    members: &[(Option<usize>, f64)],
    gears: &[(usize, u32, bool)],
    meshes: &[(usize, usize)],
    stages: &[(usize, usize, f64, bool)],
    inputs: &[(usize, f64)],
) -> TrainFile {
    let n = members.len();
    TrainFile {
        name: "random".into(),
        notes: String::new(),
        module_mm: Some(2.0),
        members: members
            .iter()
            .enumerate()
            .map(|(i, &(carrier, inertia))| MemberFile {
                name: member(i),
                axis_on: carrier.map_or("frame".into(), |c| member(c % n)),
                planets: Some(3),
                inertia_kg_m2: inertia,
            })
            .collect(),
        gears: gears
            .iter()
            .enumerate()
            .map(|(g, &(m, teeth, internal))| GearFile {
                name: format!("z{g}"),
                member: member(m % (n + 1)).replace(&format!("m{n}"), "nowhere"),
                teeth,
                internal,
            })
            .collect(),
        meshes: meshes
            .iter()
            .map(|&(a, b)| (format!("z{a}"), format!("z{b}")))
            .collect(),
        mesh_efficiency: None,
        stages: stages
            .iter()
            .map(|&(a, b, ratio, crossed)| StageFile {
                kind: StageKind::Belt,
                from: member(a % n),
                to: member(b % n),
                ratio,
                crossed,
                efficiency: None,
            })
            .collect(),
        inputs: inputs
            .iter()
            .map(|&(m, rpm)| InputFile {
                member: member(m % n),
                rpm,
            })
            .collect(),
    }
}

/// A train of mostly valid shape: each member a gear meshing with the next one's
/// (where `chain` says so), some extra meshes and belts between any two, inputs on any
/// member; random enough that every refusal is met too.
#[allow(clippy::type_complexity)]
fn shaped(
    members: &[(Option<usize>, f64, u32, bool, bool)],
    extra: &[(usize, usize)],
    stages: &[(usize, usize, f64, bool)],
    inputs: &[(usize, f64)],
) -> TrainFile {
    let n = members.len();
    let gears: Vec<(usize, u32, bool)> = members
        .iter()
        .enumerate()
        .map(|(i, m)| (i, m.2, m.3))
        .collect();
    let mut meshes: Vec<(usize, usize)> = (1..n)
        .filter(|&i| members[i].4)
        .map(|i| (i - 1, i))
        .collect();
    meshes.extend(extra.iter().map(|&(a, b)| (a % n.max(1), b % (n + 1))));
    let carriers: Vec<(Option<usize>, f64)> = members.iter().map(|m| (m.0, m.1)).collect();
    train_file(&carriers, &gears, &meshes, stages, inputs)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn random_trains_are_solved_finite_or_refused(
        members in prop::collection::vec((
            prop::option::weighted(0.15, 0usize..6),
            0.0f64..10.0,
            6u32..200,
            prop::bool::weighted(0.15),
            prop::bool::weighted(0.9),
        ), 1..6),
        extra in prop::collection::vec((0usize..7, 0usize..7), 0..2),
        stages in prop::collection::vec((0usize..6, 0usize..6, 0.1f64..10.0, any::<bool>()), 0..2),
        inputs in prop::collection::vec((0usize..6, prop::sample::select(vec![0.0, 1450.0, -100.0])), 1..3),
        load in -1000.0f64..1000.0,
        eta in prop::option::of(0.5f64..1.0),
    ) {
        let mut file = shaped(&members, &extra, &stages, &inputs);
        // Efficiencies on every mesh and stage, or none (ideal).
        file.mesh_efficiency = eta;
        for stage in &mut file.stages {
            stage.efficiency = eta;
        }
        let drive = DriveTrainSpec {
            motor_member: member(0),
            crank_member: member(members.len() - 1),
            train: file.clone(),
        };
        match DriveTrain::from_spec(&drive) {
            Ok(d) => {
                prop_assert!(d.ratio.is_finite() && d.ratio != 0.0, "{d:?}");
                prop_assert!(d.inertia_at_crank_kg_m2.is_finite() && d.inertia_at_crank_kg_m2 >= 0.0);
            }
            Err(e) => prop_assert!(!e.to_string().is_empty()),
        }
        let train = match Train::new(file) {
            Ok(t) => t,
            Err(e) => {
                prop_assert!(!e.to_string().is_empty());
                return Ok(());
            }
        };
        let s = match train.solve() {
            Ok(s) => s,
            Err(e) => {
                prop_assert!(!e.to_string().is_empty());
                return Ok(());
            }
        };
        prop_assert!(s.speeds_rpm.iter().all(|m| m.rpm.is_finite()), "{s:?}");
        prop_assert!(s.willis.iter().all(|w| w.ratio.is_finite()), "{s:?}");
        for m in &s.speeds_rpm {
            match train.torques(&s, &m.member, load) {
                Ok(q) => {
                    prop_assert!(q.members.iter().all(|t| t.torque_n_m.is_finite() && t.power_w.is_finite()), "{q:?}");
                    // Relative to the load's torque at the fastest member's speed (a
                    // load on a member standing still moves no power at all).
                    let fastest = s.speeds_rpm.iter().map(|m| m.rpm.abs()).fold(0.0, f64::max);
                    let scale = load.abs() * fastest * std::f64::consts::TAU / 60.0;
                    let net: f64 = q.members.iter().map(|t| t.power_w).sum();
                    let tolerance = 1e-9 * scale.max(f64::MIN_POSITIVE);
                    if eta.is_none() {
                        // Ideal gears: what goes in comes out.
                        prop_assert!(net.abs() <= tolerance, "{net} of {scale}: {q:?}");
                    } else {
                        // With losses the train takes power, never gives it, and
                        // says how much.
                        prop_assert!(net >= -tolerance, "{net} of {scale}: {q:?}");
                        prop_assert!((q.lost_w - net).abs() <= tolerance, "{q:?}");
                    }
                }
                Err(e) => prop_assert!(!e.to_string().is_empty()),
            }
        }
    }
}
