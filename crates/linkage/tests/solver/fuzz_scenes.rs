//! Mutated scene files, byte- and token-level, from every shipped scene: none may
//! panic, and every refusal must say where (a line and column) or what (a field,
//! link, point or parameter by name). A scene that loads is then built and solved at
//! a few inputs, and its assembly range found: errors there are fine, panics and
//! non-finite poses are not.
//!
//! `LINKAGE_FUZZ_CASES` sets the number of mutated files (3,000 by default; CI runs
//! 100,000 with the test build: scripts/check.sh). The mutations come from a fixed seed,
//! so a failure names the case that reproduces it.

use crate::common;

use linkage::{Kinematics, Mechanism};

/// Numbers a mutation puts in place of one: extremes, signs, non-finite spellings.
const NUMBERS: [&str; 14] = [
    "0.0",
    "-0.0",
    "1e300",
    "-1e300",
    "1e-300",
    "NaN",
    "inf",
    "-inf",
    "-1.0",
    "1e16",
    "3",
    "-1e-15",
    "0.000001",
    "999999999999",
];
/// Tokens a mutation inserts or swaps in.
const TOKENS: [&str; 16] = [
    "(",
    ")",
    "[",
    "]",
    "{",
    "}",
    ",",
    ":",
    "\"",
    "Some(",
    "None",
    "true",
    "ground",
    "\"B\": (1.0, 0.0)",
    "relative_angel: 5.0",
    "//",
];

/// xorshift64*: a fixed, dependency-free stream (the cases must replay exactly).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

fn cases() -> usize {
    std::env::var("LINKAGE_FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(3000)
}

/// Byte offsets of the numbers in `text`.
fn number_spans(text: &str) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut spans = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let starts =
            b[i].is_ascii_digit() || (b[i] == b'-' && b.get(i + 1).is_some_and(u8::is_ascii_digit));
        if starts && (i == 0 || !b[i - 1].is_ascii_alphanumeric()) {
            let s = i;
            i += 1;
            while i < b.len() && (b[i].is_ascii_digit() || b".eE-+".contains(&b[i])) {
                i += 1;
            }
            spans.push((s, i));
        } else {
            i += 1;
        }
    }
    spans
}

/// One to three mutations of `text`: bytes flipped, inserted or deleted; a number
/// replaced; a token inserted; a line deleted or duplicated.
fn mutate(text: &str, rng: &mut Rng) -> String {
    let mut t = text.to_string();
    for _ in 0..1 + rng.below(3) {
        let len = t.len().max(1);
        let at = rng.below(len);
        // Only cut at character boundaries (the scenes hold a few non-ASCII letters).
        let at = (0..=at).rev().find(|&i| t.is_char_boundary(i)).unwrap_or(0);
        match rng.below(7) {
            0 => {
                let byte = b" \n\t(),:\"{}[]-.0123456789eaZ_"[rng.below(28)] as char;
                t.insert(at, byte);
            }
            1 => {
                if let Some(c) = t[at..].chars().next() {
                    t.replace_range(at..at + c.len_utf8(), "");
                }
            }
            2 | 3 => {
                let spans = number_spans(&t);
                if !spans.is_empty() {
                    let (s, e) = spans[rng.below(spans.len())];
                    t.replace_range(s..e, NUMBERS[rng.below(NUMBERS.len())]);
                }
            }
            4 => t.insert_str(at, TOKENS[rng.below(TOKENS.len())]),
            _ => {
                let lines: Vec<&str> = t.lines().collect();
                let n = rng.below(lines.len());
                let mut out: Vec<&str> = lines.clone();
                if rng.below(2) == 0 {
                    out.remove(n);
                } else {
                    out.insert(n, lines[n]);
                }
                t = out.join("\n");
            }
        }
    }
    t
}

/// Whether an error message says where or what: a line/column, or a name in
/// backticks or quotes, or a named parameter (`name = value is invalid`).
fn says_where(msg: &str) -> bool {
    msg.contains("line ") || msg.contains('`') || msg.contains('"') || msg.contains(" = ")
}

/// Loads, builds and solves one scene text; an error message for a refusal.
fn exercise(text: &str) -> Result<(), String> {
    let m = Mechanism::from_ron(text).map_err(|e| e.to_string())?;
    let mut k = Kinematics::new(m).map_err(|e| e.to_string())?;
    let _ = linkage::analysis::assembly_ranges_of(&k);
    for x in [0.0, 1.0, 2.5, 4.0] {
        if let Ok(s) = k.solve(x) {
            let finite = s.points.iter().all(|p| {
                p.position
                    .iter()
                    .chain(p.velocity.iter())
                    .all(|v| v.is_finite())
            });
            assert!(finite, "a non-finite pose at {x} rad");
        }
    }
    Ok(())
}

/// The cases `case % parts == part` of the one fixed stream: the stream is drawn
/// whole (a mutation costs little beside a solve), so each case is the same text
/// however the cases are shared out, and the halves run on two cores.
fn fuzz_share(part: usize, parts: usize) {
    let sources: Vec<String> = common::SCENES
        .iter()
        .map(|f| common::scene_text(f))
        .collect();
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let (mut loaded, mut refused) = (0usize, 0usize);
    let mut vague = Vec::new();
    let started = std::time::Instant::now();
    let total = cases();
    for case in 0..total {
        let text = mutate(&sources[case % sources.len()], &mut rng);
        if case % parts != part {
            continue;
        }
        let outcome = std::panic::catch_unwind(|| exercise(&text));
        match outcome {
            Ok(Ok(())) => loaded += 1,
            Ok(Err(msg)) => {
                refused += 1;
                if !says_where(&msg) {
                    vague.push(format!("case {case}: {msg}"));
                }
            }
            Err(_) => panic!("case {case} panicked on this scene:\n{text}"),
        }
    }
    println!(
        "cases {part} mod {parts} of {total} mutated scenes: {loaded} loaded and solved, \
         {refused} refused, in {:.1} s",
        started.elapsed().as_secs_f64()
    );
    assert!(
        vague.is_empty(),
        "{} refusals name no place or field:\n{}",
        vague.len(),
        vague[..vague.len().min(10)].join("\n")
    );
}

#[test]
fn mutated_scene_files_never_panic_and_say_where_they_fail_even_cases() {
    fuzz_share(0, 2);
}

#[test]
fn mutated_scene_files_never_panic_and_say_where_they_fail_odd_cases() {
    fuzz_share(1, 2);
}
