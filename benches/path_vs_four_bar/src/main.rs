//! Path synthesis on random ordinary four-bars (`cases.rs`), Linkage Lab's path
//! search with its default options, and the `four-bar` crate on the same targets.
//!
//! `cargo run --release --manifest-path benches/path_vs_four_bar/Cargo.toml --
//! [--cases 50] [--hard 50] [--seed 1] [--ours-only] [--peer-seconds 10]`
//!
//! `--cases` ordinary four-bars as before, then `--hard` of the hard family (small
//! cranks with far coupler points, `cases::hard_case`), drawn from a stream of their
//! own so that the ordinary cases stay the same whatever the count of hard ones.
//!
//! Ours: `PathSearch` with `PathConstraints::default()` and `SearchOptions::default()`
//! run to its end; success is a design whose largest miss is within 1e-6 of the
//! targets' size, the time is the whole run's wall time. Both sides' error at time
//! budgets: the best design's largest distance from a target to its coupler curve
//! (ours: at the crank angle it meets the target, in order or at its timing; four-bar:
//! anywhere on the curve, since it fits shapes), over the targets' size.

mod cases;
mod peer;

use std::time::Instant;

use linkage::synthesis::path::{PathConstraints, PathSearch, SearchOptions};

/// A case is met when the largest miss is at most this share of the targets' size.
const GOAL: f64 = 1e-6;
/// The time budgets both sides' errors are compared at, s.
const BUDGETS: [f64; 5] = [0.1, 0.3, 1.0, 3.0, 10.0];

struct Args {
    cases: usize,
    hard: usize,
    seed: u64,
    ours_only: bool,
    peer_seconds: f64,
    only: Option<usize>,
    dump: bool,
    /// Search seeds per case (1: the default seed only, as a user runs it).
    seeds: u64,
}

fn args() -> Args {
    let mut a = Args {
        cases: 50,
        hard: 50,
        seed: 1,
        ours_only: false,
        peer_seconds: 10.0,
        only: None,
        dump: false,
        seeds: 1,
    };
    let mut it = std::env::args().skip(1);
    while let Some(flag) = it.next() {
        let mut value = || {
            it.next()
                .and_then(|v| v.parse::<f64>().ok())
                .unwrap_or(f64::NAN)
        };
        match flag.as_str() {
            "--cases" => a.cases = value() as usize,
            "--hard" => a.hard = value() as usize,
            "--seed" => a.seed = value() as u64,
            "--ours-only" => a.ours_only = true,
            "--peer-seconds" => a.peer_seconds = value(),
            "--only" => a.only = Some(value() as usize),
            "--dump" => a.dump = true,
            "--seeds" => a.seeds = value() as u64,
            other => {
                eprintln!("unknown argument {other}");
                std::process::exit(2);
            }
        }
    }
    a
}

/// Our search on one case: whether it met the goal, its wall time, and its best
/// error after each budget.
struct Ours {
    met: bool,
    seconds: f64,
    error_at: [f64; BUDGETS.len()],
}

fn ours(case: &cases::Case, seed: u64) -> Ours {
    let options = SearchOptions {
        seed,
        ..SearchOptions::default()
    };
    let mut search = PathSearch::new(&case.targets, &PathConstraints::default(), options)
        .unwrap_or_else(|e| panic!("the case is refused: {e}"));
    let started = Instant::now();
    // (time, best error so far) after each slice of a few milliseconds.
    let mut timeline: Vec<(f64, f64)> = Vec::new();
    let mut best = f64::INFINITY;
    loop {
        let p = search.step(500);
        let t = started.elapsed().as_secs_f64();
        let now = search
            .designs()
            .first()
            .map_or(p.best_relative_error, |d| d.relative_error);
        best = best.min(now);
        timeline.push((t, best));
        if p.done {
            let error_at = BUDGETS.map(|budget| {
                timeline
                    .iter()
                    .filter(|(at, _)| *at <= budget)
                    .map(|(_, e)| *e)
                    .fold(f64::INFINITY, f64::min)
            });
            return Ours {
                met: p.solutions >= 1 && best <= GOAL,
                seconds: t,
                error_at,
            };
        }
    }
}

fn percentile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let k = ((sorted.len() - 1) as f64 * q).round() as usize;
    sorted[k]
}

fn main() {
    let a = args();
    let mut rng = cases::Rng::new(a.seed);
    let mut all: Vec<cases::Case> = (0..a.cases).map(|i| cases::case(i, &mut rng)).collect();
    let mut hard_rng = cases::Rng::new(a.seed.wrapping_add(0x4841_5244));
    all.extend((0..a.hard).map(|i| cases::hard_case(i, &mut hard_rng)));
    println!(
        "| case | kind | targets | timed | whole turn | ours: met | s | best error | four-bar error at {} s |",
        a.peer_seconds
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    let mut times = Vec::new();
    let mut met = 0;
    let mut ours_at: Vec<[f64; BUDGETS.len()]> = Vec::new();
    let mut seed_runs: Vec<usize> = Vec::new();
    let mut peer_at: Vec<[f64; BUDGETS.len()]> = Vec::new();
    for (i, c) in all.iter().enumerate() {
        if a.only.is_some_and(|k| k != i) {
            continue;
        }
        if a.dump {
            println!(
                "{}",
                serde_json::json!({"targets": c.targets.points_m, "crank_deg": c.targets.crank_deg, "truth": c.truth.params(), "left": c.truth.c_left_of_bd, "angles": c.truth_angles, "determination": c.determination})
            );
            continue;
        }
        let o = ours(c, 1);
        if a.seeds > 1 {
            // Other seeds: whether the outcome is the seed's or the targets'.
            let others = (2..=a.seeds)
                .filter(|&seed| {
                    let o = ours(c, seed);
                    eprintln!("case {i} seed {seed}: met {} in {:.2} s", o.met, o.seconds);
                    o.met
                })
                .count();
            let met_by = others + usize::from(o.met);
            seed_runs.push(met_by);
            println!("case {i}: {met_by}/{} seeds met", a.seeds);
        }
        times.push(o.seconds);
        met += usize::from(o.met);
        ours_at.push(o.error_at);
        let peer = if a.ours_only {
            None
        } else {
            let p = peer::run(c, a.peer_seconds, &BUDGETS);
            peer_at.push(p);
            Some(p[BUDGETS.len() - 1])
        };
        println!(
            "| {i} | {} | {} | {} | {} | {} | {:.2} | {:.1e} | {} |",
            c.kind.name(),
            c.targets.points_m.len(),
            if c.timed { "yes" } else { "no" },
            if c.whole_turn { "yes" } else { "no" },
            if o.met { "yes" } else { "NO" },
            o.seconds,
            o.error_at[BUDGETS.len() - 1],
            peer.map_or("-".into(), |e| format!("{e:.1e}")),
        );
    }
    let n = times.len();
    times.sort_by(f64::total_cmp);
    println!();
    println!(
        "ours: {met}/{n} met ({:.1} %), median {:.2} s, 90th percentile {:.2} s, slowest {:.2} s",
        100.0 * met as f64 / n as f64,
        percentile(&times, 0.5),
        percentile(&times, 0.9),
        times.last().copied().unwrap_or(f64::NAN)
    );
    if a.seeds > 1 {
        let same = seed_runs
            .iter()
            .filter(|&&m| m == 0 || m == a.seeds as usize)
            .count();
        println!(
            "seeds 1 to {}: the same outcome with every seed in {same}/{} cases ({:.1} %)",
            a.seeds,
            seed_runs.len(),
            100.0 * same as f64 / seed_runs.len().max(1) as f64
        );
    }
    println!();
    println!(
        "| budget, s | ours: median error | ours: met | four-bar: median error | four-bar: met |"
    );
    println!("|---|---|---|---|---|");
    for (k, budget) in BUDGETS.iter().enumerate() {
        let column = |rows: &[[f64; BUDGETS.len()]]| {
            let mut v: Vec<f64> = rows.iter().map(|r| r[k]).collect();
            v.sort_by(f64::total_cmp);
            (
                percentile(&v, 0.5),
                v.iter().filter(|e| **e <= GOAL).count(),
            )
        };
        let (om, on) = column(&ours_at);
        let (pm, pn) = column(&peer_at);
        println!(
            "| {budget} | {om:.1e} | {on}/{} | {} | {} |",
            ours_at.len(),
            if peer_at.is_empty() {
                "-".into()
            } else {
                format!("{pm:.1e}")
            },
            if peer_at.is_empty() {
                "-".into()
            } else {
                format!("{pn}/{}", peer_at.len())
            },
        );
    }
}
