//! A cam as a joint of the mechanism: the paper-cup feed whose rocker pivot rides on
//! a cam-driven bell crank, against references written here: the program, finite
//! differences of the solved positions, the pitch curve differentiated numerically on
//! the turning cam, the standalone disc cam, and virtual work for the torque.

use crate::common;

use std::f64::consts::TAU;

use linkage::cam::{DiscCam, Face, Follower, Law, Program, Segment, SegmentKind};
use linkage::kinetostatics::Kinetostatics;
use linkage::motion::Vec2;
use linkage::scene::SolverPath;
use linkage::{Kinematics, Mechanism};

use common::{kinematics, mechanism, wrap};

const SCENE: &str = "paper_cup_cam_feed.ron";

fn turn(v: Vec2, a: f64) -> Vec2 {
    let (s, c) = a.sin_cos();
    Vec2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

/// On both solver paths: the closed form places the follower as a group of its own,
/// Newton closes the cam's row with the loops.
#[test]
fn the_follower_turns_by_the_program_at_every_crank_angle() {
    for path in [SolverPath::ClosedForm, SolverPath::Newton] {
        let mut k = kinematics(SCENE, path);
        let m = k.mechanism().clone();
        let cam = &m.cams[0];
        let omega = m.driver.speed_rad_s;
        for i in 0..720 {
            let phi = TAU * i as f64 / 720.0;
            let s = k.solve(phi).expect("solves");
            let program = cam.program.at(phi);
            let arm = &s.links[cam.follower];
            let gap = wrap(arm.angle_rad() - cam.rest - program.s);
            assert!(gap.abs() < 1e-12, "{path:?} at {phi}: {gap}");
            assert!((arm.omega_rad_s - program.v * omega).abs() < 1e-10 * omega);
            let a = program.a * omega * omega;
            assert!(
                (arm.alpha_rad_s2 - a).abs() < 1e-9 * omega * omega,
                "{path:?} at {phi}"
            );
        }
    }
}

#[test]
fn velocities_and_accelerations_match_finite_differences_of_positions() {
    let mut k = kinematics(SCENE, SolverPath::Auto);
    let m = k.mechanism().clone();
    let omega = m.driver.speed_rad_s;
    let h = 1e-5;
    for i in 0..72 {
        let phi = 0.013 + TAU * i as f64 / 72.0;
        let [a, b, c] = [phi - h, phi, phi + h].map(|x| k.solve(x).expect("solves"));
        for p in m.point_ids() {
            let (pa, pb, pc) = (a.points[p], b.points[p], c.points[p]);
            let v_fd = (pc.position - pa.position) / (2.0 * h) * omega;
            let a_fd = (pc.position - pb.position * 2.0 + pa.position) / (h * h) * omega * omega;
            let size = m.size_m;
            assert!(
                (v_fd - pb.velocity).norm() < 1e-6 * size * omega,
                "{} at {phi}: {v_fd} vs {}",
                m.points[p].name,
                pb.velocity
            );
            assert!(
                (a_fd - pb.acceleration).norm() < 1e-3 * size * omega * omega,
                "{} at {phi}",
                m.points[p].name
            );
        }
    }
}

/// The pitch curve as the turning cam sees it, from the solved roller positions by
/// central differences: its normal and radius of curvature at the cam angle.
fn pitch_by_differences(k: &mut Kinematics, phi: f64, h: f64) -> (Vec2, f64) {
    let m = k.mechanism().clone();
    let cam = &m.cams[0];
    let q = |k: &mut Kinematics, x: f64| {
        let s = k.solve(x).expect("solves");
        turn(s.points[cam.roller].position - cam.centre, -x)
    };
    let [a, b, c] = [phi - h, phi, phi + h].map(|x| q(k, x));
    let d1 = (c - a) / (2.0 * h);
    let d2 = (c - b * 2.0 + a) / (h * h);
    let radius = d1.norm().powi(3) / (d1.x * d2.y - d1.y * d2.x);
    // The cam turns counter-clockwise, so the roller runs clockwise on it: the
    // outward normal is the tangent turned by +90°, back in the world.
    let outward = Vec2::new(-d1.y, d1.x) / d1.norm();
    (turn(outward, phi), -radius)
}

#[test]
fn the_contact_normal_and_curvature_match_the_pitch_curve_differentiated_on_the_cam() {
    let mut k = kinematics(SCENE, SolverPath::Auto);
    let m = k.mechanism().clone();
    let cam = &m.cams[0];
    for i in 0..36 {
        let phi = 0.021 + TAU * i as f64 / 36.0;
        let contact = cam.contact(phi);
        let (normal, radius) = pitch_by_differences(&mut k, phi, 1e-4);
        assert!((contact.normal - normal).norm() < 1e-6, "normal at {phi}");
        assert!(
            (contact.pitch_radius_m - radius).abs() < 1e-5 * radius.abs().max(m.size_m),
            "radius at {phi}: {} vs {radius}",
            contact.pitch_radius_m
        );
        // The contact point is the roller's radius in along the normal, and the
        // pressure angle is between the normal and the roller centre's velocity.
        let s = k.solve(phi).expect("solves");
        let roller = s.points[cam.roller];
        assert!((contact.roller - roller.position).norm() < 1e-12 * m.size_m);
        let gap = (contact.point - roller.position).norm() - cam.roller_radius_m;
        assert!(gap.abs() < 1e-12 * m.size_m);
        if roller.velocity.norm() > 1e-9 * m.size_m {
            let v = roller.velocity / roller.velocity.norm();
            let cos = v.dot(&contact.normal).abs();
            assert!(
                (cos - contact.pressure_angle_rad.cos()).abs() < 1e-9,
                "at {phi}"
            );
        }
    }
}

/// The layouts' program (as their scenes write it): a cycloidal rise of `lift` over
/// 120°, a dwell of 60°, a modified-sine return over 100°, a dwell of 80°.
fn layout_program(lift: f64) -> Program {
    let seg = |kind, deg: f64| Segment {
        kind,
        angle_rad: deg.to_radians(),
    };
    let (rise, fall) = (Law::Cycloidal, Law::ModifiedSine);
    Program::new(vec![
        seg(SegmentKind::Rise { law: rise, lift }, 120.0),
        seg(SegmentKind::Dwell, 60.0),
        seg(SegmentKind::Return { law: fall, lift }, 100.0),
        seg(SegmentKind::Dwell, 80.0),
    ])
    .expect("program")
}

/// The cam joint's profile, pressure angle and pitch radius against the disc cam's at
/// 3600 cam angles, to 1e-9 (of the base radius, relative).
fn assert_like_the_disc_cam(cam: &linkage::model::CamJoint, disc: &DiscCam) {
    let base = disc.base_radius_m;
    for i in 0..3600 {
        let theta = TAU * i as f64 / 3600.0;
        let (joint, reference) = (cam.contact(theta), disc.at(theta));
        let on_cam = turn(joint.point - cam.centre, -theta);
        let expected = Vec2::new(reference.profile_m[0], reference.profile_m[1]);
        assert!(
            (on_cam - expected).norm() < 1e-9 * base,
            "profile at {theta}"
        );
        let (a, b) = (joint.pressure_angle_rad, reference.pressure_angle_rad);
        assert!(
            (a.tan() - b.tan()).abs() < 1e-9 * (1.0 + b.tan().abs()),
            "at {theta}"
        );
        let (ra, rb) = (joint.pitch_radius_m, reference.pitch_radius_m);
        assert!((ra - rb).abs() < 1e-9 * rb.abs().max(base), "at {theta}");
    }
}

/// A scene of the disc cam's own layout: the cam's centre at the origin, the arm's
/// pivot on +x at `pivot`, the roller below the axis (as `DiscCam` places it).
fn disc_layout_scene(pivot: f64, arm: f64, base: f64, roller: f64, rest_deg: f64) -> String {
    format!(
        r#"Scene(
    name: "disc cam layout", models: Kinematics, length_unit: Millimetre,
    links: [
        (name: "ground", ground: true, points: {{"A": (0.0, 0.0), "O": ({pivot}, 0.0)}}),
        (name: "cam", points: {{"A": (0.0, 0.0), "T": ({base}, 0.0)}}),
        (name: "arm", points: {{"O": (0.0, 0.0), "R": ({arm}, 0.0)}}),
    ],
    driver: (link: "cam", speed: Rpm(60.0)),
    output: Some("arm"),
    cams: [(cam: "cam", follower: "arm", roller: "R", roller_radius: {roller},
        rest: {rest_deg}, segments: [
            Rise(law: Cycloidal, lift: 20.0, deg: 120.0), Dwell(deg: 60.0),
            Return(law: ModifiedSine, lift: 20.0, deg: 100.0), Dwell(deg: 80.0)])],
)"#
    )
}

#[test]
fn an_arm_in_the_disc_cams_layout_gives_the_disc_cams_profile_and_pressure_angle() {
    let (pivot, arm, base, roller): (f64, f64, f64, f64) = (120.0, 90.0, 40.0, 10.0);
    let rp = base + roller;
    let gamma0 = -((rp * rp - pivot * pivot - arm * arm) / (2.0 * pivot * arm)).acos();
    let m = Mechanism::from_ron(&disc_layout_scene(
        pivot,
        arm,
        base,
        roller,
        gamma0.to_degrees(),
    ))
    .expect("valid");
    let program = layout_program(20f64.to_radians());
    let mm = 1e-3;
    let follower = Follower::Oscillating {
        pivot_m: pivot * mm,
        arm_m: arm * mm,
        face: Face::Roller {
            radius_m: roller * mm,
        },
    };
    let disc = DiscCam::new(program, base * mm, follower).expect("disc cam");
    assert_like_the_disc_cam(&m.cams[0], &disc);
}

/// The scene with masses, gravity, a spring and a speed: kinetostatics through the
/// cam.
fn loaded() -> Kinematics {
    Kinematics::new(common::loaded(mechanism(SCENE))).expect("solves")
}

#[test]
fn the_torque_through_the_cam_contact_agrees_with_virtual_work() {
    let mut k = loaded();
    let mut ks = Kinetostatics::new(&mut k).expect("kinetostatics");
    let mut largest = 0.0_f64;
    let mut states = Vec::new();
    for i in 0..360 {
        let s = ks.at(&mut k, TAU * i as f64 / 360.0).expect("solves");
        largest = largest.max(s.torque_virtual_work.abs());
        states.push(s);
    }
    for s in &states {
        let diff = s.torque_newton_euler - s.torque_virtual_work;
        assert!(diff.abs() < 1e-9 * largest, "at {}: {diff}", s.input_rad);
        let cam = s.joints.last().expect("the cam contact");
        let push = cam.push.expect("a cam contact's push");
        assert!((push.hypot(0.0) - cam.force.0.hypot(cam.force.1)).abs() < 1e-9 * largest);
    }
}

#[test]
fn a_cam_joint_is_refused_by_name_where_it_cannot_work() {
    let text = common::scene_text(SCENE);
    let cases = [
        (r#"cam: "crank""#, r#"cam: "coupler""#, "no pin on ground"),
        (
            r#"follower: "bell_crank""#,
            r#"follower: "rocker""#,
            "pinned to ground",
        ),
        (
            "roller_radius: 15.0",
            "roller_radius: 90.0",
            "no cam is left",
        ),
        (
            "roller_radius: 15.0",
            "roller_radius: -1.0",
            "roller_radius",
        ),
    ];
    for (from, to, expected) in cases {
        let err = Mechanism::from_ron(&text.replace(from, to)).expect_err(to);
        assert!(err.to_string().contains(expected), "{to}: {err}");
    }
    // Without its cam the bell crank is free: the count names the cam contacts.
    let start = text.find("    cams: [").expect("cams");
    let without = format!("{})", &text[..start]);
    let err = Mechanism::from_ron(&without).expect_err("two degrees of freedom");
    assert!(err.to_string().contains("mobility 2"), "{err}");
    assert!(err.to_string().contains("0 cam contacts"), "{err}");
}

/// A translating roller follower in the disc cam's layout: its guide along +y at the
/// offset, the roller's centre on the slider, travel from the guide's point on the
/// x-axis.
fn translating_layout_scene(offset: f64, base: f64, roller: f64) -> String {
    let rest = ((base + roller).powi(2) - offset * offset).sqrt();
    format!(
        r#"Scene(
    name: "translating layout", models: Kinematics, length_unit: Millimetre,
    links: [
        (name: "ground", ground: true, points: {{"A": (0.0, 0.0), "T": ({offset}, 0.0)}}),
        (name: "cam", points: {{"A": (0.0, 0.0), "Q": ({base}, 0.0)}}),
        (name: "follower", points: {{"R": (0.0, 0.0)}}),
    ],
    sliders: [(slider: "follower", point: "R", guide: "ground", through: "T", angle: 90.0)],
    driver: (link: "cam", speed: Rpm(60.0)),
    output: Some("follower"),
    cams: [(cam: "cam", follower: "follower", roller: "R", roller_radius: {roller},
        rest: {rest}, segments: [
            Rise(law: Cycloidal, lift: 20.0, deg: 120.0), Dwell(deg: 60.0),
            Return(law: ModifiedSine, lift: 20.0, deg: 100.0), Dwell(deg: 80.0)])],
)"#
    )
}

#[test]
fn a_translating_follower_gives_the_disc_cams_profile_and_pressure_angle() {
    let (offset, base, roller): (f64, f64, f64) = (8.0, 40.0, 10.0);
    let mut k = Kinematics::new(
        Mechanism::from_ron(&translating_layout_scene(offset, base, roller)).expect("valid"),
    )
    .expect("solves");
    let m = k.mechanism().clone();
    let program = layout_program(20e-3);
    let mm = 1e-3;
    let face = Face::Roller {
        radius_m: roller * mm,
    };
    let follower = Follower::Translating {
        offset_m: offset * mm,
        face,
    };
    let disc = DiscCam::new(program, base * mm, follower).expect("disc cam");
    let cam = &m.cams[0];
    assert_like_the_disc_cam(cam, &disc);
    let omega = m.driver.speed_rad_s;
    for i in 0..360 {
        let theta = TAU * i as f64 / 360.0;
        // The slider itself moves by the program.
        let s = k.solve(theta).expect("solves");
        let slide = s.slides[0];
        let motion = disc.program.at(theta);
        let rest = cam.rest;
        assert!((slide.displacement_m - rest - motion.s).abs() < 1e-12 * base * mm);
        assert!((slide.velocity_m_s - motion.v * omega).abs() < 1e-12 * base * mm * omega);
    }
}

#[test]
fn the_timing_diagram_shows_the_cams_dwells_and_the_linkages_motion_on_one_shaft() {
    let mut k = kinematics(SCENE, SolverPath::Auto);
    let m = k.mechanism().clone();
    let cam = &m.cams[0];
    let diagram = linkage::analysis::timing(&mut k, 720).expect("timing");
    let names: Vec<&str> = diagram.lanes.iter().map(|l| l.name.as_str()).collect();
    // The outputs: links pinned to ground (the rocker now rides the bell crank), then
    // sliders.
    assert_eq!(names, ["bell_crank", "slider"]);
    let arm = &diagram.lanes[0];
    // The program's dwells, to the half degree the diagram is sampled at.
    let lift = cam.program.largest_lift();
    let expected = [[110.0, 180.0], [290.0, 359.5]];
    assert_eq!(arm.dwells.len(), 2, "{:?}", arm.dwells);
    for (got, want) in arm.dwells.iter().zip(expected) {
        for (g, w) in got.iter().zip(want) {
            assert!(
                (g.to_degrees() - w).abs() <= 0.5 + 1e-9,
                "{got:?} vs {want:?}"
            );
        }
    }
    // Its share of the stroke is the program's lift over the largest lift.
    for (x, share) in diagram.shaft_rad.iter().zip(&arm.share) {
        let s = cam.program.at(*x).s;
        assert!((share - s / lift).abs() < 1e-9, "at {x}");
    }
    assert!((arm.range[1] - arm.range[0] - lift).abs() < 1e-12);
    // The slider, moved by the four-bar too, never rests for two samples.
    assert!(diagram.lanes[1].dwells.is_empty());
}

/// The loaded cam feed (docs/examples): its closing spring keeps the roller on the
/// cam all the way round, and without it the push turns into a pull (the roller
/// would lift off), which is what the kinetostatics through the contact is for.
#[test]
fn the_closing_spring_keeps_the_roller_on_the_cam_and_without_it_the_roller_lifts() {
    let path = format!(
        "{}/../../docs/examples/paper_cup_cam_feed_loaded.ron",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).expect("the example");
    let least_push = |text: &str| {
        let mut k = Kinematics::new(Mechanism::from_ron(text).expect("valid")).expect("solves");
        let mut ks = Kinetostatics::new(&mut k).expect("kinetostatics");
        let mut least = f64::INFINITY;
        for i in 0..360 {
            let s = ks.at(&mut k, TAU * i as f64 / 360.0).expect("solves");
            let scale = s.torque_virtual_work.abs().max(1.0);
            assert!((s.torque_newton_euler - s.torque_virtual_work).abs() < 1e-9 * scale);
            least = least.min(s.joints.last().and_then(|j| j.push).expect("a push"));
        }
        least
    };
    assert!(least_push(&text) > 100.0, "{}", least_push(&text));
    let spring = r#"springs: [(a: "D", b: "Q", k_n_per_m: 4000.0, free_length: Length(100.0))],"#;
    assert!(text.contains(spring));
    assert!(least_push(&text.replace(spring, "")) < 0.0);
}

/// Released from rest, the loaded cam feed (its feed resistance taken off, so that
/// every force has a potential) keeps its energy through the cam's contact: the push
/// does no work, and the reduced model carries the follower's inertia through the
/// program's slope. DOP853 at rtol 1e-11 over a second.
#[test]
fn released_the_cam_feed_keeps_its_energy_through_the_cam() {
    use linkage::dynamics::{Method, Settings, simulate};
    let path = format!(
        "{}/../../docs/examples/paper_cup_cam_feed_loaded.ron",
        env!("CARGO_MANIFEST_DIR")
    );
    let mut m =
        Mechanism::from_ron(&std::fs::read_to_string(&path).expect("the example")).expect("valid");
    m.models = linkage::scene::Models::Dynamics;
    m.forces.point_forces.clear();
    m.driver.speed_rad_s = 0.0;
    let k = Kinematics::new(m).expect("solves");
    let mut s = Settings::new(Method::Dop853);
    s.rtol = 1e-11;
    s.t_end = 1.0;
    s.output_dt = Some(1e-3);
    let sim = simulate(&k, &s).expect("runs");
    let e0 = sim.samples[0].energy_balance();
    let (moved, drift) = sim.samples.iter().fold((0.0_f64, 0.0_f64), |(k, d), x| {
        (k.max(x.kinetic), d.max((x.energy_balance() - e0).abs()))
    });
    assert!(moved > 0.0, "it moved");
    assert!(drift < 1e-8 * moved, "drift {drift:e} of {moved:e} J");
}
