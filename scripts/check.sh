#!/usr/bin/env bash
# Every check CI runs: formatting, clippy (native and wasm32), all tests (the UI tests
# render through wgpu on Mesa's CPU Vulkan driver), the CLI over every shipped scene,
# a native smoke run of the window under Xvfb, and the web demo in headless Chromium.
# Installs what it needs on a fresh Debian machine. Run it from anywhere in the
# repository.
set -euo pipefail
cd "$(dirname "$0")/.."

# Each section's header carries the seconds since the start: where CI's time goes
# (docs/architecture.md, "CI time").
checks_started=$(date +%s)
section() { echo "== $1 (at $(( $(date +%s) - checks_started )) s)"; }

section "dependencies"
bash scripts/install_deps.sh

section "cargo fmt --check"
cargo fmt --all -- --check

section "architecture: no import cycle, docs/architecture.md's module graphs true"
python3 scripts/test_code_measures.py
python3 scripts/code_measures.py --check

# Clippy lints the workspace's own crates as they are compiled: clippy-driver is a
# rustc that also lints, and `cargo clippy` is `cargo check` with it as the workspace's
# compiler wrapper (RUSTC_WORKSPACE_WRAPPER; its arguments in CLIPPY_ARGS). Set for the
# builds themselves, the lints cost no build of their own: a separate `cargo clippy`
# compiled every dependency a second time, for checking only (509 s of 2553 s at
# 5fdfd1e, docs/architecture.md, "CI time").
clippy_driver="$(rustc --print sysroot)/bin/clippy-driver"
[ -x "$clippy_driver" ] || { echo "clippy-driver missing: rustup component add clippy" >&2; exit 1; }
# `-D warnings`, as cargo-clippy hands it to the driver.
clippy_args="-D__CLIPPY_HACKERY__warnings__CLIPPY_HACKERY__"

section "web builds start (in the background, linted for wasm32)"
# The two web builds (WebGPU, WebGL2) run beside the native build and tests, in a
# target folder of their own (cargo locks a target folder for one build at a time):
# their whole-program optimisation runs on one core for minutes, which the native
# build and tests fill. With the browser's own lints: std::time::Instant/SystemTime
# compile for wasm32 but panic there at run time, so they are refused (use web_time).
# These builds lint the solver, the model, the diagrams and the app for wasm32; the
# CLI is not built for the browser.
web_log="${CARGO_TARGET_DIR:-target}/web-builds.log"
mkdir -p "$(dirname "$web_log")"
# Its own process group (setsid), so that a failure below stops it too.
CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$PWD/target}/web" \
    CLIPPY_CONF_DIR="$PWD/scripts/clippy_wasm" \
    RUSTC_WORKSPACE_WRAPPER="$clippy_driver" CLIPPY_ARGS="$clippy_args" \
    setsid bash -c 'began=$(date +%s); bash scripts/build_web.sh
        echo "== web builds took $(( $(date +%s) - began )) s"' > "$web_log" 2>&1 &
web_builds=$!
trap 'kill -- -"$web_builds" 2>/dev/null || true' EXIT

section "tests (clippy, native, all targets: as they build)"
# winit and wgpu warn without a runtime dir; the UI tests need none, give them one.
mkdir -m700 -p /tmp/xdg && export XDG_RUNTIME_DIR=/tmp/xdg
# The same wrapper for every native cargo command below, else they compile anew.
export RUSTC_WORKSPACE_WRAPPER="$clippy_driver"
export CLIPPY_ARGS="$clippy_args"
# All targets are linted as `cargo clippy --all-targets` did (the benches too), then
# the tests run.
cargo test --workspace --all-targets --no-run
cargo test --workspace
# The CLI's and the app's binaries, built by the tests (their integration tests run
# them), with the tests' features: the sections below run these. Built again alone
# (`cargo build -p linkage-lab`), eframe compiles anew without the accessibility
# feature the UI tests' harness turns on, and the CLI's dependencies likewise.
export LINKAGE_BINS_FROM_TESTS=1

section "fuzzing and properties at scale"
# 10^5 mutated scene files, and 34,000 each of random four-bars, slider-cranks and
# six-bars on both solver paths (the plain test run above does a few thousand), with
# the test binaries built above: the test build compiles the solver optimised
# (Cargo.toml), and a release build of its own took 118 s to save 30 s of running
# (docs/architecture.md, "CI time").
# `--workspace`, not `-p linkage`: the solver alone is built with other features
# than in the workspace (no `parallel`), and was built anew (70 s).
LINKAGE_FUZZ_CASES=100000 LINKAGE_PROPERTY_CASES=34000 \
    cargo test --workspace --test solver -- fuzz_scenes:: properties:: --nocapture

section "CLI over every scene"
bin="${CARGO_TARGET_DIR:-target}/debug"
for scene in assets/scenes/*.ron; do
    "$bin/linkage" report "$scene" > /dev/null
    "$bin/linkage" sweep "$scene" --steps 36 > /dev/null
    echo "ok $scene"
done

section "web builds (waiting for them)"
web_rc=0; wait "$web_builds" || web_rc=$?
# Cargo's progress lines are left out; errors and lints are not.
grep -v -e '^ *Compiling ' -e '^ *Blocking ' "$web_log" || true
[ "$web_rc" = 0 ] || { echo "the web builds failed (exit $web_rc): $web_log" >&2; exit 1; }

section "native smoke run (Xvfb)"
bash scripts/smoke_native.sh

section "native file dialog (zenity under Xvfb)"
bash scripts/smoke_file_dialog.sh

section "web demo in headless Chromium"
# dist/ holds the builds made above.
LINKAGE_WEB_BUILT=1 bash scripts/browser_test.sh

section "done"
