#!/usr/bin/env bash
# Renders the application icon's PNG sizes for the hicolor theme from its SVG (run after editing
# the SVG; the PNGs are committed, so building needs no SVG renderer). Needs rsvg-convert
# (Debian: librsvg2-bin).
set -euo pipefail
cd "$(dirname "$0")"
id=io.github.fieldsight.Fieldsight
for size in 48 64 128 256; do
    mkdir -p "hicolor/${size}x${size}"
    rsvg-convert -w "$size" -h "$size" "$id.svg" -o "hicolor/${size}x${size}/$id.png"
done
