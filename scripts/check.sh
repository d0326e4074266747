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

section "clippy (native, all targets)"
cargo clippy --workspace --all-targets -- -D warnings

section "clippy (wasm32: the solver, the CLI and the app compile for the browser)"
# With the browser's own lints: std::time::Instant/SystemTime compile for wasm32 but
# panic there at run time, so they are refused (use web_time).
# The app in both web builds: WebGL2 through glow (`webgl`), WebGPU through wgpu (`webgpu`).
CLIPPY_CONF_DIR=scripts/clippy_wasm cargo clippy --workspace --target wasm32-unknown-unknown \
    --features linkage-lab/webgl -- -D warnings
CLIPPY_CONF_DIR=scripts/clippy_wasm cargo clippy -p linkage-lab --features webgpu \
    --target wasm32-unknown-unknown -- -D warnings

section "tests"
# winit and wgpu warn without a runtime dir; the UI tests need none, give them one.
mkdir -m700 -p /tmp/xdg && export XDG_RUNTIME_DIR=/tmp/xdg
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
    cargo test --workspace --test fuzz_scenes --test properties -- --nocapture

section "CLI over every scene"
bin="${CARGO_TARGET_DIR:-target}/debug"
for scene in assets/scenes/*.ron; do
    "$bin/linkage" report "$scene" > /dev/null
    "$bin/linkage" sweep "$scene" --steps 36 > /dev/null
    echo "ok $scene"
done

section "native smoke run (Xvfb)"
bash scripts/smoke_native.sh

section "native file dialog (zenity under Xvfb)"
bash scripts/smoke_file_dialog.sh

section "web demo in headless Chromium"
bash scripts/browser_test.sh

section "done"
