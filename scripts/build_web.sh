#!/usr/bin/env bash
# Builds the web demo into dist/ without trunk: cargo for wasm32 (two builds, one
# drawing with WebGPU, one with WebGL2), then wasm-bindgen at exactly the Cargo.lock version
# (installed with cargo if missing), optionally wasm-opt (WASM_OPT=1), then index.html
# with the trunk link replaced by web/load.js, which picks the build. With --serve, serves dist/ on
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

# Two builds: WebGPU through wgpu (the `webgpu` feature), and WebGL2 through eframe's
# glow renderer (the `webgl` feature) for browsers without a WebGPU adapter.
# web/load.js picks one.
rm -rf dist && mkdir -p dist
for build in webgpu webgl2; do
    feature=webgpu; [ "$build" = webgl2 ] && feature=webgl
    cargo build --profile wasm-release --target wasm32-unknown-unknown --bin linkage-lab --features "$feature"
    wasm-bindgen --target web --no-typescript --out-dir "dist/$build" \
        "${CARGO_TARGET_DIR:-target}/wasm32-unknown-unknown/wasm-release/linkage-lab.wasm"
done
# wasm-opt (binaryen 132 from npm; Debian's 108 breaks this wasm) only when asked for
# (WASM_OPT=1): measured here, -Os takes 3.5 min and makes the wasm 5 % smaller raw but
# no smaller gzipped, and the first frame no sooner (docs/journal.md, "The viewer").
if [ "${WASM_OPT:-0}" = 1 ]; then
    (cd scripts/web_tools && npm ci --no-audit --no-fund --silent)
    for wasm in dist/*/linkage-lab_bg.wasm; do
        before=$(stat -c %s "$wasm")
        scripts/web_tools/node_modules/.bin/wasm-opt -Os --strip-debug --strip-producers \
            "$wasm" -o "$wasm.opt"
        mv "$wasm.opt" "$wasm"
        echo "wasm-opt $wasm: $before -> $(stat -c %s "$wasm") bytes"
    done
fi
# window.wasmBindings, as trunk names it: the browser test reads the app's controls there.
cp web/load.js dist/
# The Chinese face, fetched by the app only once Chinese text is shown (src/web_font.rs).
mkdir -p dist/fonts && cp assets/fonts/NotoSansSC-Subset.otf assets/fonts/OFL.txt dist/fonts/
sed -e 's|<link data-trunk rel="rust"[^>]*/>|<script type="module" src="./load.js"></script>|' \
    index.html > dist/index.html
ls -l dist dist/*/

if [ "${1:-}" = "--serve" ]; then
    echo "serving http://127.0.0.1:8080"
    exec python3 -m http.server 8080 --bind 127.0.0.1 --directory dist
fi
