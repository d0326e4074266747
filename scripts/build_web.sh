#!/usr/bin/env bash
# Builds the web demo into dist/ without trunk: cargo for wasm32, then wasm-bindgen at
# exactly the Cargo.lock version (installed with cargo if missing), optionally wasm-opt
# (WASM_OPT=1), then index.html with the trunk link replaced by a module import. With --serve, serves dist/ on
# http://127.0.0.1:8080 (python3's http.server).
set -euo pipefail
cd "$(dirname "$0")/.."

rustup target add wasm32-unknown-unknown >/dev/null
want=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/[^0-9.]/, ""); print; exit }' Cargo.lock)
have=$(wasm-bindgen --version 2>/dev/null | awk '{print $2}' || true)
if [ "$have" != "$want" ]; then
    echo "installing wasm-bindgen-cli $want (Cargo.lock) ..."
    # Not --locked: its lock file names a crate version this registry lacks.
    cargo install wasm-bindgen-cli --version "$want"
fi

cargo build --profile wasm-release --target wasm32-unknown-unknown --bin linkage-lab
rm -rf dist && mkdir -p dist
wasm-bindgen --target web --no-typescript --out-dir dist \
    "${CARGO_TARGET_DIR:-target}/wasm32-unknown-unknown/wasm-release/linkage-lab.wasm"
# wasm-opt (binaryen 132 from npm; Debian's 108 breaks this wasm) only when asked for
# (WASM_OPT=1): measured here, -Os takes 3.5 min and makes the wasm 5 % smaller raw but
# no smaller gzipped, and the first frame no sooner (README, "The viewer").
if [ "${WASM_OPT:-0}" = 1 ]; then
    (cd scripts/web_tools && npm ci --no-audit --no-fund --silent)
    before=$(stat -c %s dist/linkage-lab_bg.wasm)
    scripts/web_tools/node_modules/.bin/wasm-opt -Os --strip-debug --strip-producers \
        dist/linkage-lab_bg.wasm -o dist/linkage-lab_bg.opt.wasm
    mv dist/linkage-lab_bg.opt.wasm dist/linkage-lab_bg.wasm
    echo "wasm-opt: $before -> $(stat -c %s dist/linkage-lab_bg.wasm) bytes"
fi
# window.wasmBindings, as trunk names it: the browser test reads the app's controls there.
sed -e 's|<link data-trunk rel="rust"[^>]*/>|<script type="module">import init, * as bindings from "./linkage-lab.js"; window.wasmBindings = bindings; init();</script>|' \
    index.html > dist/index.html
ls -l dist

if [ "${1:-}" = "--serve" ]; then
    echo "serving http://127.0.0.1:8080"
    exec python3 -m http.server 8080 --bind 127.0.0.1 --directory dist
fi
