#!/usr/bin/env bash
# Re-makes the user guide's screenshots with the project's own screenshot tool (build it first:
# `cmake --build build --target gui_screenshot`), each with a `.signature` beside it: what the shot
# shows of the window's make-up (menu titles, docks and their tabs, tool bar action ids, the layer
# list). Runs offscreen; needs ../shared/reference_data for the real-frame shots (skipped where it
# is absent).
#   docs/make_screenshots.sh [GUI_SCREENSHOT]           re-make them (commit PNGs and signatures)
#   docs/make_screenshots.sh --check [GUI_SCREENSHOT]   make them in a temporary folder and fail
#        when a signature differs from the committed one: the window changed since the screenshots
#        were made (CTest `user_guide_screenshots_show_the_current_window` runs this)
set -euo pipefail
cd "$(dirname "$0")/.."
check=0
if [ "${1:-}" = --check ]; then
    check=1
    shift
fi
shot=${1:-build/tests/gui_screenshot}
committed=docs/screenshots
out=$committed
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [ $check = 1 ]; then
    out=$tmp/shots
fi
export QT_QPA_PLATFORM=offscreen
mkdir -p "$out"
made=()

# shoot NAME STREAM ARGS...: NAME.png and NAME.signature in the output folder.
shoot() {
    local name=$1
    shift
    "$shot" "$out/$name.png" "$@" --signature "$out/$name.signature" >/dev/null
    made+=("$name")
}

# Debugging a missed ball: truth and detections side by side with the ball's edge points.
shoot missed-ball sample_streams/difficult --size 1280x800 --frame 0 \
    --layers percepts,truth,ball.edge_points --mode side --dock detections_dock

# A venue's table: the click preview (magenta) before the click, on an upright NUbots picture.
nubots=../shared/reference_data/nubots_nusight_frames
if [ -d "$nubots" ]; then
    mkdir -p "$tmp/nubots"
    cp "$nubots"/*.jpg "$tmp/nubots"/
    shoot venue-preview "$tmp/nubots" --size 1280x800 --orientation 180 \
        --dock lut_dock --tool click --colour green --preview 160,200 --mode blend
else
    echo "venue-preview: skipped, $nubots is absent"
fi

# Sample regions and the LUT editor at the size of a laptop screen.
shoot lut-editor sample_streams/lab1 --size 1280x800 --dock lut_dock --frame 3

if [ $check = 1 ]; then
    status=0
    for name in "${made[@]}"; do
        if ! diff -u "$committed/$name.signature" "$out/$name.signature"; then
            echo "docs/screenshots/$name.png shows an older window: re-make the screenshots" \
                 "with docs/make_screenshots.sh (after building gui_screenshot), look at them and" \
                 "commit the PNGs with their .signature files"
            status=1
        fi
    done
    [ $status = 0 ] && echo "the ${#made[@]} screenshots made here match their committed signatures"
    exit $status
fi
