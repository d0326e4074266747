//! Gear trains against closed forms written here: a planetary set's three ratios
//! (ring fixed 1 + z_r/z_s, sun fixed 1 + z_s/z_r, carrier fixed −z_r/z_s), a
//! differential's carrier (z_s ω_s + z_r ω_r)/(z_s + z_r), a compound train's sign
//! and size (−1)^externals · Π z_driven/z_driving, an idler's sign, a crossed belt;
//! the shipped train files; Willis' ratio; the assembly conditions; refusals.

use linkage::gears::train_file::TrainFile;
use linkage::gears::{AssemblyCheck, Train, TrainError};

fn train(text: &str) -> Train {
    let file: TrainFile = ron::from_str(text).unwrap_or_else(|e| panic!("{e}"));
    Train::new(file).unwrap_or_else(|e| panic!("{e}"))
}

/// The planetary set (sun 20, planets 30, ring 80) with `inputs`.
fn planetary(inputs: &str) -> String {
    format!(
        r#"(name: "set", members: [(name: "sun"), (name: "planet", axis_on: "carrier"),
            (name: "carrier", planets: Some(4)), (name: "ring")],
            gears: [(name: "s", member: "sun", teeth: 20), (name: "p", member: "planet", teeth: 30),
                    (name: "r", member: "ring", teeth: 80, internal: true)],
            meshes: [("s", "p"), ("p", "r")], inputs: [{inputs}])"#
    )
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1.0)
}

#[test]
fn a_planetary_sets_three_ratios_are_the_textbooks() {
    let (zs, zr) = (20.0, 80.0);
    let ring_fixed = train(&planetary(
        r#"(member: "sun", rpm: 1000.0), (member: "ring", rpm: 0.0)"#,
    ));
    let s = ring_fixed.solve().expect("solved");
    assert_eq!(s.dof, 2);
    assert!(close(
        s.ratio("sun", "carrier").expect("a member"),
        1.0 + zr / zs
    ));
    let sun_fixed = train(&planetary(
        r#"(member: "ring", rpm: 1000.0), (member: "sun", rpm: 0.0)"#,
    ));
    let s = sun_fixed.solve().expect("solved");
    assert!(close(
        s.ratio("ring", "carrier").expect("a member"),
        1.0 + zs / zr
    ));
    let carrier_fixed = train(&planetary(
        r#"(member: "sun", rpm: 1000.0), (member: "carrier", rpm: 0.0)"#,
    ));
    let s = carrier_fixed.solve().expect("solved");
    assert!(close(s.ratio("sun", "ring").expect("a member"), -zr / zs));
    // The planet about its own axis, relative to the carrier: −z_s/z_p of the sun's.
    let planet = s.speed_rpm("planet").expect("a member");
    assert!(close(planet, -1000.0 * zs / 30.0));
    // Willis' converted ratio of the sun and the ring, whatever the inputs.
    let w = &s.willis[0];
    assert_eq!(
        (w.carrier.as_str(), w.from.as_str(), w.to.as_str()),
        ("carrier", "sun", "ring")
    );
    assert!(close(w.ratio, -zr / zs));
}

#[test]
fn a_differential_sums_its_two_inputs() {
    let (ws, wr) = (1450.0, -100.0);
    let t = train(&planetary(&format!(
        r#"(member: "sun", rpm: {ws}), (member: "ring", rpm: {wr})"#
    )));
    let s = t.solve().expect("solved");
    let carrier = (20.0 * ws + 80.0 * wr) / 100.0;
    assert!(close(s.speed_rpm("carrier").expect("a member"), carrier));
    // One input is not enough.
    let one = train(&planetary(r#"(member: "sun", rpm: 1450.0)"#));
    assert_eq!(
        one.solve().expect_err("two needed"),
        TrainError::Inputs { dof: 2, given: 1 }
    );
}

#[test]
fn a_compound_train_with_an_idler_and_a_crossed_belt() {
    let t = train(
        r#"(name: "compound", members: [(name: "a"), (name: "b"), (name: "idler"), (name: "c"), (name: "d")],
            gears: [(name: "z1", member: "a", teeth: 18), (name: "z2", member: "b", teeth: 54),
                    (name: "z3", member: "b", teeth: 21), (name: "zi", member: "idler", teeth: 33),
                    (name: "z4", member: "c", teeth: 63)],
            meshes: [("z1", "z2"), ("z3", "zi"), ("zi", "z4")],
            stages: [(kind: Chain, from: "c", to: "d", ratio: 1.5, crossed: false)],
            inputs: [(member: "a", rpm: 900.0)])"#,
    );
    let s = t.solve().expect("solved");
    assert_eq!(s.dof, 1);
    // Three external meshes: (−1)³; the idler's teeth cancel.
    let a_over_c = (-1.0_f64).powi(3) * (54.0 / 18.0) * (63.0 / 21.0);
    assert!(close(s.ratio("a", "c").expect("a member"), a_over_c));
    assert!(close(s.ratio("c", "d").expect("a member"), 1.5));
    let crossed = train(
        r#"(name: "belt", members: [(name: "a"), (name: "b")],
            stages: [(kind: Belt, from: "a", to: "b", ratio: 2.0, crossed: true)],
            inputs: [(member: "a", rpm: 100.0)])"#,
    );
    assert!(close(
        crossed
            .solve()
            .expect("solved")
            .speed_rpm("b")
            .expect("a member"),
        -50.0
    ));
}

#[test]
fn the_shipped_trains_solve_and_the_die_cutters_crank_turns_at_fifty() {
    let dir = format!("{}/../../assets/trains", env!("CARGO_MANIFEST_DIR"));
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("assets/trains")
        .flatten()
        .map(|e| e.path())
        .collect();
    files.sort();
    assert!(files.len() >= 3);
    for path in files {
        let text = std::fs::read_to_string(&path).expect("read");
        let s = train(&text)
            .solve()
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(s.speeds_rpm.iter().all(|m| m.rpm.is_finite()));
        if path.ends_with("die_cutter_drive.ron") {
            assert!(
                close(s.speed_rpm("crank").expect("a member"), 50.0),
                "{s:?}"
            );
            assert!(close(s.ratio("motor", "crank").expect("a member"), 29.0));
            // J_motor 29² + J_input 10² + J_intermediate 5² + J_crank: what the drive
            // adds at the crank.
            let t = train(&text);
            let reduced = t
                .reduced_inertia_kg_m2(&s, "crank")
                .expect("the crank turns");
            assert!(
                close(reduced, 1.6 * 29.0 * 29.0 + 3.0 * 100.0 + 4.0 * 25.0 + 63.0),
                "{reduced}"
            );
        }
        if path.ends_with("planetary_ring_fixed.ron") {
            assert!(close(s.speed_rpm("carrier").expect("a member"), 290.0));
        }
    }
}

#[test]
fn a_planetary_sets_assembly_conditions() {
    let s = train(&planetary(
        r#"(member: "sun", rpm: 1.0), (member: "ring", rpm: 0.0)"#,
    ))
    .solve()
    .expect("a member");
    let find = |f: &dyn Fn(&AssemblyCheck) -> bool| s.assembly.iter().find(|c| f(c)).cloned();
    // 80 = 20 + 2·30: coaxial; (20 + 80)/4 = 25: equal spacing; (20 + 30) sin 45° = 35.4 > 32.
    assert!(matches!(
        find(&|c| matches!(c, AssemblyCheck::Coaxial { .. })),
        Some(AssemblyCheck::Coaxial { holds: true, .. })
    ));
    assert!(matches!(
        find(&|c| matches!(c, AssemblyCheck::EqualSpacing { .. })),
        Some(AssemblyCheck::EqualSpacing { holds: true, .. })
    ));
    let Some(AssemblyCheck::Neighbours {
        clearance_modules,
        holds,
        ..
    }) = find(&|c| matches!(c, AssemblyCheck::Neighbours { .. }))
    else {
        panic!("no neighbour check");
    };
    assert!(
        holds
            && close(
                clearance_modules,
                50.0 * (std::f64::consts::PI / 4.0).sin() - 32.0
            )
    );
    // One planet: no neighbour to clear, no spacing to check.
    let one = planetary(r#"(member: "sun", rpm: 1.0), (member: "ring", rpm: 0.0)"#)
        .replace("Some(4)", "Some(1)");
    let s1 = train(&one).solve().expect("solved");
    assert!(!s1.assembly.iter().any(|c| matches!(
        c,
        AssemblyCheck::Neighbours { .. } | AssemblyCheck::EqualSpacing { .. }
    )));
    // Double planets at two distances (sun 30 with P1 15 at 22.5; P2 15 meshing P1
    // and a ring of 75 at 30): coaxial, each planet at its own distance.
    let double = train(
        r#"(name: "double", members: [(name: "sun"), (name: "p1", axis_on: "carrier"), (name: "p2", axis_on: "carrier"),
            (name: "carrier"), (name: "ring")],
            gears: [(name: "s", member: "sun", teeth: 30), (name: "a", member: "p1", teeth: 15),
                    (name: "b", member: "p2", teeth: 15), (name: "r", member: "ring", teeth: 75, internal: true)],
            meshes: [("s", "a"), ("a", "b"), ("b", "r")],
            inputs: [(member: "sun", rpm: 100.0), (member: "ring", rpm: 0.0)])"#,
    );
    let sd = double.solve().expect("solved");
    assert!(
        sd.assembly
            .iter()
            .any(|c| matches!(c, AssemblyCheck::Coaxial { holds: true, .. })),
        "{:?}",
        sd.assembly
    );
    // A double-planet set, ring fixed: the carrier turns with the sun, 1/(1 − z_r/z_s).
    assert!(close(
        sd.ratio("sun", "carrier").expect("a member"),
        1.0 - 75.0 / 30.0
    ));
    // A ring of 81: not coaxial, and (20 + 81)/4 not whole.
    let odd = planetary(r#"(member: "sun", rpm: 1.0), (member: "ring", rpm: 0.0)"#)
        .replace("teeth: 80", "teeth: 81");
    let s = train(&odd).solve().expect("solved");
    assert!(
        s.assembly
            .iter()
            .any(|c| matches!(c, AssemblyCheck::Coaxial { holds: false, .. }))
    );
    assert!(
        s.assembly
            .iter()
            .any(|c| matches!(c, AssemblyCheck::EqualSpacing { holds: false, .. }))
    );
}

#[test]
fn refusals_name_what_is_wrong() {
    let bad = |text: &str| {
        let file: TrainFile = ron::from_str(text).unwrap_or_else(|e| panic!("{e}"));
        Train::new(file)
            .and_then(|t| t.solve())
            .expect_err("refused")
            .to_string()
    };
    let unknown =
        bad(r#"(name: "x", members: [(name: "a")], gears: [(name: "g", member: "b", teeth: 20)])"#);
    assert!(unknown.contains("gear g's member names `b`"), "{unknown}");
    let apart = bad(
        r#"(name: "x", members: [(name: "h1"), (name: "h2"), (name: "p", axis_on: "h1"), (name: "q", axis_on: "h2")],
            gears: [(name: "gp", member: "p", teeth: 20), (name: "gq", member: "q", teeth: 20)],
            meshes: [("gp", "gq")], inputs: [])"#,
    );
    assert!(apart.contains("cannot mesh"), "{apart}");
    let teeth =
        bad(r#"(name: "x", members: [(name: "a")], gears: [(name: "g", member: "a", teeth: 2)])"#);
    assert!(
        teeth.contains("gear g's teeth 2 is outside the range 3 … 10000"),
        "{teeth}"
    );
    let empty = bad(r#"(name: "x", members: [])"#);
    assert!(empty.contains("at least one member"), "{empty}");
    let small_ring = bad(r#"(name: "x", members: [(name: "a"), (name: "b")],
            gears: [(name: "g", member: "a", teeth: 30), (name: "r", member: "b", teeth: 20, internal: true)],
            meshes: [("g", "r")])"#);
    assert!(
        small_ring.contains("must have more teeth than `g`"),
        "{small_ring}"
    );
    let frame =
        bad(r#"(name: "x", members: [(name: "a")], inputs: [(member: "frame", rpm: 0.0)])"#);
    assert!(frame.contains("an input names `frame`"), "{frame}");
    let tied = bad(
        r#"(name: "x", members: [(name: "a"), (name: "b"), (name: "c")],
            gears: [(name: "ga", member: "a", teeth: 20), (name: "gb", member: "b", teeth: 40)],
            meshes: [("ga", "gb")], inputs: [(member: "a", rpm: 1.0), (member: "b", rpm: 1.0)])"#,
    );
    assert!(tied.contains("the inputs do not fix the train"), "{tied}");
}

/// Torques through a planetary set against the textbooks' closed forms: the set's
/// members are coaxial and its planets take no torque from outside, so the sun's,
/// ring's and carrier's torques sum to zero (moment balance) and their powers too
/// (an ideal set); with the ring held, T_sun = −T_carrier/(1 + z_r/z_s). Every
/// way of holding it, and every member's power summing to zero, to round-off.
#[test]
fn a_planetary_sets_torques_balance_and_conserve_power() {
    let (zs, zr) = (20.0, 80.0);
    let load = -500.0;
    for inputs in [
        r#"(member: "sun", rpm: 1450.0), (member: "ring", rpm: 0.0)"#,
        r#"(member: "ring", rpm: 1450.0), (member: "sun", rpm: 0.0)"#,
    ] {
        let t = train(&planetary(inputs));
        let s = t.solve().expect("solved");
        let q = t.torques(&s, "carrier", load).expect("torques");
        let torque = |m: &str| {
            q.members
                .iter()
                .find(|x| x.member == m)
                .map(|x| x.torque_n_m)
                .expect("a member")
        };
        let power: f64 = q.members.iter().map(|m| m.power_w).sum();
        let through = q
            .members
            .iter()
            .map(|m| m.power_w.abs())
            .fold(0.0, f64::max);
        assert!(power.abs() <= 1e-12 * through, "{q:?}");
        let (ts, tr, tc) = (torque("sun"), torque("ring"), torque("carrier"));
        assert!((ts + tr + tc).abs() <= 1e-12 * load.abs(), "{q:?}");
        assert_eq!(q.frame_n_m, 0.0, "the ring's brake is a member: {q:?}");
        assert_eq!(torque("planet"), 0.0);
        assert_eq!(tc, load);
        if inputs.starts_with(r#"(member: "sun""#) {
            assert!(
                (ts + load / (1.0 + zr / zs)).abs() <= 1e-12 * load.abs(),
                "{ts}"
            );
        } else {
            assert!(
                (tr + load / (1.0 + zs / zr)).abs() <= 1e-12 * load.abs(),
                "{tr}"
            );
        }
    }
}

/// A fixed-axis train: the motor's torque is the load's over the ratio (with the
/// ratio's sign), the housing takes the rest, and the idle shafts none.
#[test]
fn a_fixed_axis_trains_torques_are_the_load_over_the_ratio() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../assets/trains/die_cutter_drive.ron"
    ))
    .expect("read");
    let t = train(&text);
    let s = t.solve().expect("solved");
    let load = -15_915.5;
    let q = t.torques(&s, "crank", load).expect("torques");
    let motor = q
        .members
        .iter()
        .find(|m| m.member == "motor")
        .expect("motor");
    assert!(
        (motor.torque_n_m + load / 29.0).abs() <= 1e-12 * load.abs(),
        "{q:?}"
    );
    let power: f64 = q.members.iter().map(|m| m.power_w).sum();
    assert!(power.abs() <= 1e-12 * motor.power_w.abs(), "{q:?}");
    for idle in ["input_shaft", "intermediate_shaft"] {
        let m = q.members.iter().find(|m| m.member == idle).expect("member");
        assert_eq!(m.torque_n_m, 0.0);
    }
    assert!((q.frame_n_m + motor.torque_n_m + load).abs() <= 1e-12 * load.abs());
    // A load where the speed is given is refused, as is a name not in the train.
    assert_eq!(
        t.torques(&s, "motor", 1.0),
        Err(TrainError::LoadWhereSpeedGiven {
            member: "motor".into()
        })
    );
    assert!(matches!(
        t.torques(&s, "flywheel", 1.0),
        Err(TrainError::Unknown { .. })
    ));
}

/// The paper-cup feed's drive (assets/trains/paper_cup_feed_drive.ron) turns the
/// crank at the paper's 45 rpm (one turn per cup), counter-clockwise as the scene's
/// crank, from a 1440 rpm motor: a total ratio of −32 (belt 3.2 · gears 72/18 ·
/// chain 2.5, the gear pair reversing).
#[test]
fn the_paper_cup_drive_turns_the_crank_at_the_papers_speed() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../assets/trains/paper_cup_feed_drive.ron"
    ))
    .expect("read");
    let s = train(&text).solve().expect("solved");
    let crank = s.speed_rpm("crank").expect("crank");
    assert!((crank - 45.0).abs() <= 1e-12 * 45.0, "{s:?}");
    let ratio = s.ratio("motor", "crank").expect("ratio");
    assert!(
        (ratio + 3.2 * 72.0 / 18.0 * 2.5).abs() <= 1e-12 * 32.0,
        "{ratio}"
    );
}

/// With efficiencies, the textbooks' closed forms: the die cutter's drive (a belt of
/// η_b = 0.96, two meshes of η = 0.98 in series) asks of its motor the load over
/// i·η_b·η², and loses 1 − η_b·η² of what the motor gives; a planetary set with the
/// ring held and the sun driving the loaded carrier: T_sun = −T_H/(1 + η^H z_r/z_s),
/// η^H = η² (sun to planet, planet to ring in the converted train), the set's
/// efficiency (1 + η^H z_r/z_s)/(1 + z_r/z_s); efficiencies outside (0, 1] refused.
#[test]
fn efficiencies_take_their_share_as_the_textbooks_say() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../assets/trains/");
    let read = |f: &str| std::fs::read_to_string(format!("{path}{f}")).expect("read");
    let with = |text: &str, mesh: f64, belt: Option<f64>| {
        let mut file = TrainFile::from_ron(text).expect("file");
        file.mesh_efficiency = Some(mesh);
        for s in &mut file.stages {
            s.efficiency = belt;
        }
        Train::new(file).expect("train")
    };
    let (eta, eta_b) = (0.98, 0.96);
    let drive = with(&read("die_cutter_drive.ron"), eta, Some(eta_b));
    let s = drive.solve().expect("solved");
    let load = -15_915.5;
    let q = drive.torques(&s, "crank", load).expect("torques");
    let motor = q
        .members
        .iter()
        .find(|m| m.member == "motor")
        .expect("motor");
    let through = eta_b * eta * eta;
    assert!(
        (motor.torque_n_m + load / (29.0 * through)).abs() <= 1e-12 * load.abs(),
        "{q:?}"
    );
    assert!(
        (q.lost_w - (1.0 - through) * motor.power_w).abs() <= 1e-9 * motor.power_w,
        "{q:?}"
    );
    let set = with(&read("planetary_ring_fixed.ron"), eta, None);
    let s = set.solve().expect("solved");
    let load = -100.0;
    let q = set.torques(&s, "carrier", load).expect("torques");
    let sun = q.members.iter().find(|m| m.member == "sun").expect("sun");
    let (zs, zr) = (20.0, 80.0);
    let eta_h = eta * eta;
    assert!(
        (sun.torque_n_m + load / (1.0 + eta_h * zr / zs)).abs() <= 1e-12 * load.abs(),
        "{q:?}"
    );
    let out = -q
        .members
        .iter()
        .find(|m| m.member == "carrier")
        .expect("carrier")
        .power_w;
    let efficiency = out / sun.power_w;
    let textbook = (1.0 + eta_h * zr / zs) / (1.0 + zr / zs);
    assert!(
        (efficiency - textbook).abs() <= 1e-12,
        "{efficiency} vs {textbook}"
    );
    // Ideal, nothing is lost.
    let ideal = train(&read("planetary_ring_fixed.ron"));
    let s = ideal.solve().expect("solved");
    assert_eq!(
        ideal.torques(&s, "carrier", load).expect("torques").lost_w,
        0.0
    );
    for bad in [0.0, 1.2, f64::NAN] {
        let mut file = TrainFile::from_ron(&read("die_cutter_drive.ron")).expect("file");
        file.mesh_efficiency = Some(bad);
        assert!(
            matches!(Train::new(file), Err(TrainError::OutOfRange { .. })),
            "{bad}"
        );
    }
}
