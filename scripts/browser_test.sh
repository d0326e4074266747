#!/usr/bin/env bash
# Real-browser test of the web demo: builds it (scripts/build_web.sh; not when
# LINKAGE_WEB_BUILT is set, as CI has built it), serves dist/ on
# 127.0.0.1, and runs tests/browser/browser_test.mjs in Debian's headless Chromium via
# playwright-core, once per build (WebGL2, WebGPU; in the WebGPU build what its renderer
# decides, over every scene), and every_scene.mjs, links_and_drops.mjs,
# exercise.mjs, every_device.mjs (phones and tablets, by touch) and laptop.mjs in the
# WebGL2 build.
# First the unit tests of the browser tests' own judges (frames_test.mjs).
# Installs chromium and the npm packages if missing.
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v chromium >/dev/null; then
    sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo"
    $sudo apt-get update && $sudo apt-get install -y chromium
fi
(cd tests/browser && npm ci --no-audit --no-fund)
node --test tests/browser/frames_test.mjs
started=$(date +%s)
# CI builds dist/ beforehand, beside the native build (scripts/check.sh).
if [ -z "${LINKAGE_WEB_BUILT:-}" ]; then
    bash scripts/build_web.sh
    echo "== web builds took $(( $(date +%s) - started )) s"
fi
# The CLI the browser test compares the app's diagram download with (in CI the one
# the tests built: scripts/check.sh).
[ -n "${LINKAGE_BINS_FROM_TESTS:-}" ] || cargo build -q -p linkage-cli
target_dir="${CARGO_TARGET_DIR:-target}"
case "$target_dir" in /*) ;; *) target_dir="$PWD/$target_dir" ;; esac
export LINKAGE_CLI="$target_dir/debug/linkage"
for wasm in dist/*/linkage-lab_bg.wasm; do
    gzip -9 -c "$wasm" | wc -c | awk -v w="$wasm" -v raw="$(stat -c %s "$wasm")" \
        '{printf "%s: %.2f MB raw, %.2f MB gzipped\n", w, raw/1e6, $1/1e6}'
done

# A free port, so that nothing else listening (another run, a demo server) answers.
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory dist >/dev/null 2>&1 &
server=$!
trap 'kill $server 2>/dev/null || true' EXIT
for _ in $(seq 50); do curl -sf "http://127.0.0.1:$port/" >/dev/null && break; sleep 0.2; done
if ! kill -0 "$server" 2>/dev/null; then
    echo "the web server on 127.0.0.1:$port did not start" >&2
    exit 1
fi
# Both builds: Chromium without a WebGPU adapter loads the WebGL2 one, with
# SwiftShader's Vulkan as adapter the WebGPU-only one (tests/browser/common.mjs).
status=0
# Each script's seconds, for where CI's time goes (docs/architecture.md, "CI time").
timed() {
    local began=$(date +%s) rc=0
    "$@" || rc=$?
    echo "== $(basename "$2") ($LINKAGE_BUILD) took $(( $(date +%s) - began )) s"
    return $rc
}
for build in webgl2 webgpu; do
    echo "== $build build (at $(( $(date +%s) - started )) s of the browser test script)"
    export LINKAGE_BUILD=$build
    # Every check in the WebGL2 build; in the WebGPU build what its renderer decides:
    # the die cutter drawn, dragged and played, then every shipped scene opened by its
    # link and drawn, and its edit's CPU measured. The files, links, editor, search and
    # controls are the same code, drawn five times slower through SwiftShader's Vulkan.
    checks=all; [ "$build" = webgpu ] && checks=drawn
    LINKAGE_BROWSER_CHECKS=$checks timed node tests/browser/browser_test.mjs "http://127.0.0.1:$port/" || status=1
    # Every scene file, every kind of control it offers (WebGL2 only).
    if [ "$build" = webgl2 ]; then
        timed node tests/browser/every_scene.mjs "http://127.0.0.1:$port/" || status=1
    fi
done
# The page's other doors (a pasted link, back and forward, a dropped file) are the
# same code in both builds and draw nothing of their own: once, in the WebGL2 build
# (53 s in the WebGPU build on this machine).
LINKAGE_BUILD=webgl2 timed node tests/browser/links_and_drops.mjs "http://127.0.0.1:$port/" || status=1
# An exercise's link, an answer typed, thirty students' codes made in the page and
# graded by the command line (the same code in both builds, drawing nothing of its own).
LINKAGE_BUILD=webgl2 timed node tests/browser/exercise.mjs "http://127.0.0.1:$port/" || status=1
# Layout and touch are the same code in both builds, and the WebGPU build draws
# through SwiftShader's Vulkan at a fifth of the speed: the devices and the laptop
# run once. Their screenshots of every scene go to SCREENSHOT_DIR, to be looked at.
export SCREENSHOT_DIR="${SCREENSHOT_DIR:-$target_dir/browser-screens}"
mkdir -p "$SCREENSHOT_DIR"
LINKAGE_BUILD=webgl2 timed node tests/browser/every_device.mjs "http://127.0.0.1:$port/" || status=1
LINKAGE_BUILD=webgl2 timed node tests/browser/laptop.mjs "http://127.0.0.1:$port/" || status=1
echo "== screenshots in $SCREENSHOT_DIR"
exit $status
