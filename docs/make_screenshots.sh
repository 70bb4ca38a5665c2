#!/usr/bin/env bash
# Re-makes the user guide's screenshots with the project's own screenshot tool (build it first:
# `cmake --build build --target gui_screenshot`). Runs offscreen; needs ../shared/reference_data for
# the real-frame shots (skipped where it is absent).
set -euo pipefail
cd "$(dirname "$0")/.."
shot=build/tests/gui_screenshot
out=docs/screenshots
export QT_QPA_PLATFORM=offscreen
mkdir -p "$out"

# Debugging a missed ball: truth and detections side by side with the ball's edge points.
"$shot" "$out/missed-ball.png" sample_streams/difficult --size 1280x800 --frame 0 \
    --layers percepts,truth,ball.edge_points --mode side --dock detections_dock

# A venue's table: the click preview (magenta) before the click, on an upright NUbots picture.
nubots=../shared/reference_data/nubots_nusight_frames
if [ -d "$nubots" ]; then
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    cp "$nubots"/*.jpg "$tmp"/
    "$shot" "$out/venue-preview.png" "$tmp" --size 1280x800 --orientation 180 \
        --dock lut_dock --tool click --colour green --preview 160,200 --mode blend
fi

# Sample regions and the LUT editor at the size of a laptop screen.
"$shot" "$out/lut-editor.png" sample_streams/lab1 --size 1280x800 --dock lut_dock --frame 3
