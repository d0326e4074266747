#!/usr/bin/env bash
# Sets up a fresh Debian machine for the desktop app (runtime libraries for winit and
# wgpu: X11, xkbcommon, Vulkan/GL drivers, CPU fallback included) and runs it.
set -euo pipefail
cd "$(dirname "$0")/.."
pkgs="libxkbcommon-x11-0 libxcursor1 libxrandr2 libxi6 libx11-xcb1 libvulkan1 mesa-vulkan-drivers libgl1-mesa-dri libegl1"
missing=$(for p in $pkgs; do dpkg -s "$p" >/dev/null 2>&1 || echo "$p"; done)
if [ -n "$missing" ]; then
    sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo"
    $sudo apt-get update
    # shellcheck disable=SC2086
    $sudo apt-get install -y $missing
fi
exec cargo run --release -p linkage-lab -- "$@"
