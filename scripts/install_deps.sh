#!/usr/bin/env bash
# Installs what the tests need on a fresh Debian machine, skipping what is present:
# Xvfb and Mesa's CPU Vulkan/GL drivers (lavapipe, llvmpipe) for the headless wgpu
# tests and the native smoke run, the X11/xkbcommon libraries winit loads, Chromium
# for the browser test, zenity and xdotool for the file-dialog smoke run, and the Rust
# components and wasm32 target; poppler-utils (pdftotext, pdffonts, pdfinfo) to read
# the PDFs back.
set -euo pipefail
pkgs="xvfb xauth mesa-vulkan-drivers libvulkan1 libgl1-mesa-dri libegl1 libxkbcommon-x11-0 libxcursor1 libxrandr2 libxi6 libx11-xcb1 zenity xdotool chromium curl poppler-utils nodejs npm"
missing=$(for p in $pkgs; do dpkg -s "$p" >/dev/null 2>&1 || echo "$p"; done)
# node and npm may come from outside Debian (as on the CI image): then they are present.
if command -v node >/dev/null && command -v npm >/dev/null; then
    missing=$(echo "$missing" | grep -vx -e nodejs -e npm || true)
fi
if [ -n "$missing" ]; then
    sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo"
    $sudo apt-get update
    # shellcheck disable=SC2086
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends $missing
fi
rustup component add rustfmt clippy >/dev/null 2>&1 || true
rustup target add wasm32-unknown-unknown >/dev/null
