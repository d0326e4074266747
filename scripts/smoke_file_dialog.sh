#!/usr/bin/env bash
# The desktop's real file dialog, end to end: under Xvfb, with no session bus (so no
# XDG portal) the app falls back to zenity; xdotool clicks "Open scene…", types a
# scene's path into zenity's file chooser, and the app must log that it opened it.
# Needs zenity and xdotool (scripts/install_deps.sh installs them).
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -m700 -p /tmp/xdg && export XDG_RUNTIME_DIR=/tmp/xdg
scene="$PWD/assets/scenes/quick_return.ron"

# Runs inside Xvfb: start the app, drive the dialog, wait for the app's log line.
drive() {
    DBUS_SESSION_BUS_ADDRESS=unix:path=/nonexistent/bus \
        "${CARGO_TARGET_DIR:-target}/debug/linkage-lab" --scene slider_crank --lang en >"$log" 2>&1 &
    local app=$!
    trap 'kill $app 2>/dev/null || true' RETURN
    local win
    win=$(timeout 60 xdotool search --sync --name '^Linkage Lab$' | head -1)
    sleep 2 # the first frames (wgpu on a CPU driver) before the button can be hit
    # "Open scene…" is the first button of the top bar: centre at (133, 12).
    xdotool mousemove --window "$win" 133 12 click 1
    local dialog
    dialog=$(timeout 60 xdotool search --sync --onlyvisible --class zenity | head -1)
    # Without a window manager nothing gives the dialog the keyboard: focus it, and on
    # a loaded machine (GTK still building the chooser) try again until it takes.
    for _ in 1 2 3 4 5; do
        xdotool windowfocus --sync "$dialog" 2>/dev/null || break
        sleep 1
        xdotool key ctrl+l
        sleep 0.5
        xdotool key ctrl+a
        xdotool type --delay 20 "$scene"
        sleep 0.5
        xdotool key Return
        for _ in $(seq 50); do
            grep -q "opened quick_return.ron" "$log" && return 0
            sleep 0.2
        done
    done
    echo "the app did not open the scene chosen in the dialog; its log:" >&2
    cat "$log" >&2
    return 1
}
if [ "${1:-}" = --inside-xvfb ]; then
    log=$2
    drive
    exit
fi
# In CI the build the tests made (scripts/check.sh).
[ -n "${LINKAGE_BINS_FROM_TESTS:-}" ] || cargo build -q -p linkage-lab
log=$(mktemp)
# xvfb-run is a POSIX sh script, which drops exported bash functions: run this
# script again inside it instead.
timeout 300 xvfb-run -a -s "-screen 0 1500x950x24" bash "$0" --inside-xvfb "$log"
grep "opened" "$log"
echo "native file dialog (zenity): ok"
