//! A gear train in a scene's drive: its ratio and inertias reach the crank as a bare
//! ratio with the same inertia on the crank would (the steady state the same to
//! round-off), the flywheel sizing counts them, the shipped example carries the train
//! of assets/trains, and every way a train cannot drive the crank is refused as data.

use linkage::error::{DriveEnd, DriveTrainProblem, TrainError};
use linkage::gears::train_file::{InputFile, TrainFile};
use linkage::machine::{size_flywheel, steady_state};
use linkage::scene::{DriveSpec, SceneFile, Shaft};
use linkage::{Kinematics, LinkageError, Mechanism, SceneProblem};

fn repo(path: &str) -> String {
    let full = format!("{}/../../{path}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&full).unwrap_or_else(|e| panic!("cannot read {full}: {e}"))
}

fn example() -> SceneFile {
    SceneFile::parse(&repo("docs/examples/die_cutter_with_train.ron")).expect("scene")
}

fn drive(scene: &SceneFile) -> &DriveSpec {
    scene.drive.as_ref().expect("a drive")
}

fn kinematics(scene: &SceneFile) -> Kinematics {
    Kinematics::new(Mechanism::from_scene(scene).expect("valid")).expect("kinematics")
}

/// What the drive is refused for, where it is a train's problem.
fn refused(scene: &SceneFile) -> DriveTrainProblem {
    match Mechanism::from_scene(scene) {
        Err(LinkageError::SceneInvalid(p)) => match *p {
            SceneProblem::DriveTrain(t) => t,
            other => panic!("another problem: {other:?}"),
        },
        other => panic!("expected a refusal, got {other:?}"),
    }
}

#[test]
fn the_example_carries_the_shipped_train_file() {
    let shipped =
        TrainFile::from_ron(&repo("assets/trains/die_cutter_drive.ron")).expect("train file");
    let scene = example();
    let spec = drive(&scene).train.as_ref().expect("a train");
    assert_eq!(spec.train, shipped);
    let m = Mechanism::from_scene(&scene).expect("valid");
    let d = m.drive.as_ref().expect("a drive");
    let train = d.train.as_ref().expect("a train");
    // 1450 rpm over 2.9 · (40/20) · (95/19): 29, the motor turning the crank's way.
    assert!(
        (train.ratio - 29.0).abs() <= 1e-12 * 29.0,
        "{}",
        train.ratio
    );
    assert!((d.gear_ratio - 29.0).abs() <= 1e-12 * 29.0);
    // Σ J (ω/ω_crank)², written out: the rotor at 29, the input shaft at −10 (one
    // external mesh later it turns back), the intermediate at −5, the crank's wheel.
    let want = 1.6 * 29.0 * 29.0 + 3.0 * 10.0 * 10.0 + 4.0 * 5.0 * 5.0 + 63.0;
    assert!((train.inertia_at_crank_kg_m2 - want).abs() <= 1e-12 * want);
    let flywheel = 45.7 * 29.0 * 29.0;
    assert!((d.flywheel_at_crank_kg_m2 - flywheel).abs() <= 1e-12 * flywheel);
    assert!((d.inertia_at_crank_kg_m2 - flywheel - want).abs() <= 1e-12 * (flywheel + want));
}

/// The train's inertias act as the same inertia on the crank: the scene with a bare
/// ratio of 29 and a flywheel on the crank of the train's and the flywheel's inertia
/// together runs the same steady state to round-off.
#[test]
fn a_train_drives_as_a_bare_ratio_with_its_inertia_on_the_crank() {
    let with_train = example();
    let mut bare = with_train.clone();
    let d = bare.drive.as_mut().expect("a drive");
    let reduced = 1.6 * 29.0 * 29.0 + 3.0 * 100.0 + 4.0 * 25.0 + 63.0;
    d.flywheel_kg_m2 = d.flywheel_kg_m2 * 29.0 * 29.0 + reduced;
    d.flywheel_on = Shaft::Crank;
    d.train = None;
    d.gear_ratio = 29.0;
    let a = steady_state(&kinematics(&with_train)).expect("steady");
    let b = steady_state(&kinematics(&bare)).expect("steady");
    let scale = a.max_rad_s;
    for (x, y) in [
        (a.max_rad_s, b.max_rad_s),
        (a.min_rad_s, b.min_rad_s),
        (a.mean_rad_s, b.mean_rad_s),
    ] {
        assert!((x - y).abs() <= 1e-9 * scale, "{x} against {y}");
    }
    // And the train's inertia matters: without it the speed fluctuates more.
    let mut no_train_inertia = with_train.clone();
    let d = no_train_inertia.drive.as_mut().expect("a drive");
    d.train = None;
    d.gear_ratio = 29.0;
    let c = steady_state(&kinematics(&no_train_inertia)).expect("steady");
    assert!(c.delta > a.delta * 1.02, "{} against {}", c.delta, a.delta);
}

#[test]
fn the_flywheel_sizing_counts_the_drives_inertia() {
    let mut scene = example();
    let s = size_flywheel(&mut kinematics(&scene), 0.05).expect("sized");
    let reduced = 1.6 * 29.0 * 29.0 + 3.0 * 100.0 + 4.0 * 25.0 + 63.0;
    let j = s.flywheel_kg_m2;
    assert!((s.drive_inertia_kg_m2 - reduced).abs() <= 1e-12 * j);
    assert!((s.flywheel_to_add_kg_m2 - (j - reduced)).abs() <= 1e-12 * j);
    let on_motor = s.flywheel_to_add_on_motor_kg_m2.expect("a drive");
    assert!((on_motor * 29.0 * 29.0 - (j - reduced)).abs() <= 1e-12 * j);
    // The flywheel itself is what is being sized: it does not count against itself.
    drive_mut(&mut scene).flywheel_kg_m2 = 1000.0;
    let again = size_flywheel(&mut kinematics(&scene), 0.05).expect("sized");
    assert_eq!(again.drive_inertia_kg_m2, s.drive_inertia_kg_m2);
    // Without a drive there is nothing beside the flywheel.
    scene.drive = None;
    let bare = size_flywheel(&mut kinematics(&scene), 0.05).expect("sized");
    assert_eq!(bare.drive_inertia_kg_m2, 0.0);
    assert_eq!(bare.flywheel_to_add_kg_m2, bare.flywheel_kg_m2);
    assert_eq!(bare.flywheel_to_add_on_motor_kg_m2, None);
}

/// The paper-cup feed ships with its drive as the die cutter does: the example
/// carries assets/trains/paper_cup_feed_drive.ron as shipped, its ratio is the
/// stages' product written out (a belt of 3.2, the external pair 18/72 reversing, a
/// chain of 2.5: −32, the motor turning against the crank), its members reduced to
/// the crank join the flywheel sizing, and they cover what the energy method asks for
/// at δ = 0.05 (no flywheel to add).
#[test]
fn the_paper_cup_feed_ships_with_its_drive() {
    let shipped =
        TrainFile::from_ron(&repo("assets/trains/paper_cup_feed_drive.ron")).expect("train file");
    let scene =
        SceneFile::parse(&repo("docs/examples/paper_cup_cam_feed_with_drive.ron")).expect("scene");
    assert_eq!(
        drive(&scene).train.as_ref().expect("a train").train,
        shipped
    );
    let m = Mechanism::from_scene(&scene).expect("valid");
    let train = m
        .drive
        .as_ref()
        .and_then(|d| d.train.as_ref())
        .expect("a train");
    let ratio = -(3.2 * (72.0 / 18.0) * 2.5);
    assert!(
        (train.ratio - ratio).abs() <= 1e-12 * 32.0,
        "{}",
        train.ratio
    );
    // Σ J (ω/ω_crank)²: the rotor at −32, the input shaft at −10, the output shaft
    // at 2.5, the crank's sprocket.
    let want = 0.02 * 32.0 * 32.0 + 0.05 * 10.0 * 10.0 + 0.3 * 2.5 * 2.5 + 0.8;
    assert!((train.inertia_at_crank_kg_m2 - want).abs() <= 1e-12 * want);
    let s = size_flywheel(&mut kinematics(&scene), 0.05).expect("sized");
    assert!((s.drive_inertia_kg_m2 - want).abs() <= 1e-12 * want);
    assert!(
        s.flywheel_kg_m2 > 0.0 && s.flywheel_kg_m2 < want,
        "{}",
        s.flywheel_kg_m2
    );
    assert_eq!(s.flywheel_to_add_kg_m2, 0.0);
}

fn drive_mut(scene: &mut SceneFile) -> &mut DriveSpec {
    scene.drive.as_mut().expect("a drive")
}

fn train_mut(scene: &mut SceneFile) -> &mut TrainFile {
    &mut drive_mut(scene).train.as_mut().expect("a train").train
}

#[test]
fn a_train_that_cannot_drive_the_crank_is_refused_naming_why() {
    let mut s = example();
    drive_mut(&mut s)
        .train
        .as_mut()
        .expect("train")
        .motor_member = "rotor".into();
    assert!(matches!(
        refused(&s),
        DriveTrainProblem::NoSuchMember { end: DriveEnd::Motor, ref name, ref known }
            if name == "rotor" && known.len() == 4
    ));
    let mut s = example();
    train_mut(&mut s).inputs.push(InputFile {
        member: "crank".into(),
        rpm: 10.0,
    });
    assert!(matches!(
        refused(&s),
        DriveTrainProblem::SecondInput { ref member, rpm } if member == "crank" && rpm == 10.0
    ));
    // The crank's member held by an input of 0 (and the motor's input dropped): the
    // train is fixed but the crank stands still.
    let mut s = example();
    train_mut(&mut s).inputs = vec![InputFile {
        member: "crank".into(),
        rpm: 0.0,
    }];
    assert!(matches!(
        refused(&s),
        DriveTrainProblem::StandsStill {
            end: DriveEnd::Crank,
            ..
        }
    ));
    let mut s = example();
    drive_mut(&mut s).gear_ratio = 30.0;
    assert!(matches!(
        refused(&s),
        DriveTrainProblem::RatioContradicts { given, train } if given == 30.0 && (train - 29.0).abs() < 1e-9
    ));
    // The ratio given as the train's is accepted.
    let mut s = example();
    drive_mut(&mut s).gear_ratio = 29.0;
    assert!(Mechanism::from_scene(&s).is_ok());
    let mut s = example();
    train_mut(&mut s).gears[0].member = "shaft".into();
    assert!(matches!(
        refused(&s),
        DriveTrainProblem::Train(TrainError::Unknown { ref name, .. }) if name == "shaft"
    ));
    let mut s = example();
    train_mut(&mut s).inputs.clear();
    assert!(matches!(
        refused(&s),
        DriveTrainProblem::Train(TrainError::Inputs { dof: 1, given: 0 })
    ));
}

/// A train that turns the motor the other way from the crank (one external mesh)
/// drives it the same: the motor's direction is its own.
#[test]
fn a_motor_turning_the_other_way_gives_the_same_drive() {
    let mut s = example();
    let t = train_mut(&mut s);
    t.stages[0].crossed = true;
    let m = Mechanism::from_scene(&s).expect("valid");
    let d = m.drive.as_ref().expect("a drive");
    let train = d.train.as_ref().expect("a train");
    assert!(
        (train.ratio + 29.0).abs() <= 1e-12 * 29.0,
        "{}",
        train.ratio
    );
    assert!((d.gear_ratio - 29.0).abs() <= 1e-12 * 29.0);
}
