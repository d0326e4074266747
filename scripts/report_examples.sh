#!/usr/bin/env bash
# Regenerates the example course-design reports under docs/examples/reports: the die
# cutter, the paper-cup feed with its cam and the gravity flipper, in English and in
# Chinese (`linkage course-report --pdf`). Run from the repository root after a change
# to the report's layout or words: crates/linkage-cli/tests/command_line/course_report.rs reads them back.
set -euo pipefail
cargo build -q -p linkage-cli
out=docs/examples/reports
mkdir -p "$out"
for key in die_cutter paper_cup_cam_feed gravity_flipper; do
    target/debug/linkage course-report "assets/scenes/$key.ron" --pdf "$out/${key}_en.pdf"
    target/debug/linkage course-report "assets/scenes/$key.ron" --lang zh-CN --pdf "$out/${key}_zh.pdf"
done
ls -l "$out"
