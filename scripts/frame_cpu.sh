#!/usr/bin/env bash
# The desktop app's CPU per frame for every shipped scene, playing: the release
# build under Xvfb (Mesa's CPU Vulkan driver), 600 frames per scene, the app's own
# mean over its last frames (all of `ui`: pose, polygons, shapes, panels, plots;
# not the GPU's time). Prints a Markdown table for the README's key figures.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -m700 -p /tmp/xdg && export XDG_RUNTIME_DIR=/tmp/xdg
cargo build -q --release -p linkage-lab
bin="${CARGO_TARGET_DIR:-target}/release/linkage-lab"
echo "| scene | CPU per frame | of which the solver |"
echo "|---|---|---|"
for file in assets/scenes/*.ron; do
    scene=$(basename "$file" .ron)
    line=$(timeout 300 xvfb-run -a -s "-screen 0 1500x950x24" \
        "$bin" --scene "$scene" --play --exit-after-frames 600 2>/dev/null | grep "mean CPU per frame")
    # "600 frames, mean CPU per frame 512.3 us (solver 40.1 us)"
    frame=$(sed -E 's/.*per frame ([0-9.]+) us.*/\1/' <<<"$line")
    solver=$(sed -E 's/.*solver ([0-9.]+) us.*/\1/' <<<"$line")
    echo "| $scene | $(awk "BEGIN{printf \"%.2f ms\", $frame/1000}") | $solver µs |"
done
