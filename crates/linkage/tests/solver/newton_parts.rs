//! Newton's parts apart (issue 32, item 4): the model is fixed once built, the
//! continuation state is a value the caller holds and passes, and the workspace
//! carries nothing from one solve to the next. So from the same continuation an input
//! solves to the same bits whatever was solved before it with the same workspace: in
//! input order, in a shuffled order, or with a fresh workspace each time. Over every
//! shipped scene and template, the Newton-only triad (its branch traced to its folds
//! first), and random inputs and orders.

use linkage::rng::SplitMix;
use linkage::{Continuation, Kinematics, LinkMotion, Mechanism, NewtonModel, NewtonWorkspace};
use proptest::prelude::*;

use crate::common;

/// A solve's outcome, exactly: every link's motion and the conditioning, or the
/// refusal, with the state it leaves.
type Outcome = String;

/// The chains to solve: each with its Newton model and the state at its start pose.
fn chains() -> Vec<(String, Mechanism, NewtonModel, Continuation)> {
    let scenes = common::SCENES
        .iter()
        .map(|f| (f.to_string(), common::mechanism(f)));
    let templates = common::TEMPLATES.iter().map(|f| {
        let m = Mechanism::from_ron(&common::template_text(f)).expect("template");
        (format!("template {f}"), m)
    });
    let triad = Mechanism::from_ron(&common::triad::Triad::locking().scene(0.01)).expect("triad");
    let mut all: Vec<_> = scenes
        .chain(templates)
        .map(|(n, m)| parts(n, m, false))
        .collect();
    all.push(parts("triad".into(), triad, true));
    all
}

fn parts(
    name: String,
    m: Mechanism,
    trace: bool,
) -> (String, Mechanism, NewtonModel, Continuation) {
    let start = m.driver.start_rad;
    let mut pose = Kinematics::new(m.clone())
        .and_then(|mut k| k.solve(start))
        .unwrap_or_else(|e| panic!("{name}: {e}"))
        .links;
    let model = NewtonModel::new(&m, m.solver.tolerance, m.solver.max_iterations)
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    let mut state = model.start(&pose, start);
    if trace {
        let mut work = model.workspace();
        model
            .trace_range(&mut pose, &mut state, &mut work)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
    }
    (name, m, model, state)
}

fn solve(
    m: &Mechanism,
    model: &NewtonModel,
    from: &Continuation,
    input: f64,
    work: &mut NewtonWorkspace,
) -> Outcome {
    let mut links = vec![LinkMotion::default(); m.links.len()];
    let mut state = from.clone();
    let outcome = model.solve_links(input, m.driver.speed_rad_s, &mut links, &mut state, work);
    // The whole state the solve leaves: coordinates, derivatives, rotations, the
    // factored Jacobian.
    format!("{outcome:?} {links:?} {state:?}")
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(6))]

    #[test]
    fn an_input_solves_from_the_same_state_to_the_same_bits_in_any_order(seed in any::<u64>()) {
        let mut rng = SplitMix::new(seed);
        for (name, m, model, start) in chains() {
            let at = start.last_input().expect("a start input");
            // Inputs up to 100 deg either side of the start: continuation over many
            // steps, and some outside a limited branch (refused, the same way).
            let inputs: Vec<f64> = (0..8).map(|_| at + (rng.unit() - 0.5) * 3.5).collect();
            let mut order: Vec<usize> = (0..inputs.len()).collect();
            for i in (1..order.len()).rev() {
                order.swap(i, rng.below(i + 1));
            }
            let mut work = model.workspace();
            let in_order: Vec<Outcome> =
                inputs.iter().map(|&x| solve(&m, &model, &start, x, &mut work)).collect();
            let mut shuffled = vec![String::new(); inputs.len()];
            for &i in &order {
                shuffled[i] = solve(&m, &model, &start, inputs[i], &mut work);
                // A mobility check between solves leaves the workspace at a shaken
                // pose: the next solve must not read it.
                let mut scratch = vec![LinkMotion::default(); m.links.len()];
                model.mobility(at, &mut scratch, &mut start.clone(), &mut work);
            }
            for (i, &x) in inputs.iter().enumerate() {
                let fresh = solve(&m, &model, &start, x, &mut model.workspace());
                prop_assert_eq!(&in_order[i], &shuffled[i], "{}: {} rad, shuffled", name, x);
                prop_assert_eq!(&in_order[i], &fresh, "{}: {} rad, fresh workspace", name, x);
            }
        }
    }
}
