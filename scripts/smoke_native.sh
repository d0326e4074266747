#!/usr/bin/env bash
# Native smoke run: opens the desktop window under Xvfb (wgpu on Mesa's CPU Vulkan
# driver), renders 120 frames with the animation playing, and must exit cleanly; prints the app's mean CPU time
# per frame.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -m700 -p /tmp/xdg && export XDG_RUNTIME_DIR=/tmp/xdg
# Debug build; in CI the one the tests built (scripts/check.sh).
[ -n "${LINKAGE_BINS_FROM_TESTS:-}" ] || cargo build -q -p linkage-lab
timeout 300 xvfb-run -a -s "-screen 0 1500x950x24" \
    "${CARGO_TARGET_DIR:-target}/debug/linkage-lab" --exit-after-frames 120 --play
echo "native smoke run: ok"
