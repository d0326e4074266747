#!/usr/bin/env bash
# The app's UI tests (tests/app) on a machine with a real GPU and no display: the
# frames render offscreen through egui_kittest's wgpu renderer on the GPU's Vulkan
# driver instead of lavapipe. Two halves:
#   bash scripts/gpu_app_tests.sh prepare   # here: the test binary and the Vulkan
#                                           # loader packages into .gl/ (git-ignored)
#   LINKAGE_ON_GPU_MACHINE=1 bash scripts/gpu_app_tests.sh run
#                                           # there, from the repository root, with
#                                           # .gl/ carried beside the working tree
# Measured on an NVIDIA H100 (driver 580.159) on 2026-11-27: 68 passed, 2 ignored, 1
# filtered out (the desktop binary's own test: it runs the built app, not carried).
set -euo pipefail
case "${1:-}" in
prepare)
    bin=$(XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp/xdg} cargo test -q --test app --no-run \
        --message-format=json | python3 -c '
import json, sys
for line in sys.stdin:
    m = json.loads(line)
    if m.get("reason") == "compiler-artifact" and m["target"]["name"] == "app" and m.get("executable"):
        print(m["executable"])')
    mkdir -p .gl /tmp/amd64/partial
    strip -o .gl/app_tests "$bin"
    o='-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/amd64'
    # shellcheck disable=SC2086
    apt-get $o update >/dev/null
    # shellcheck disable=SC2086
    (cd .gl && apt-get $o download libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2)
    du -sh .gl
    ;;
run)
    # It unpacks the loader libraries into /, as the lent machine's notes say: never
    # on a machine of one's own.
    if [ "${LINKAGE_ON_GPU_MACHINE:-}" != 1 ]; then
        echo "run only on the lent GPU machine, with LINKAGE_ON_GPU_MACHINE=1" >&2
        exit 2
    fi
    for f in .gl/*.deb; do dpkg -x "$f" /; done
    ldconfig
    export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
    # The binary finds its assets and snapshots where it was built.
    here=$PWD
    mkdir -p /work
    [ -e /work/main ] || ln -s "$here" /work/main
    cd /work/main
    export XDG_RUNTIME_DIR=/tmp/xdg
    mkdir -p "$XDG_RUNTIME_DIR"
    WGPU_BACKEND=vulkan .gl/app_tests --test-threads 8 --skip the_desktop_binary_answers
    ;;
*)
    echo "usage: $0 prepare|run" >&2
    exit 2
    ;;
esac
