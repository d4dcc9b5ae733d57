#!/usr/bin/env bash
# Renders particle-sandbox.svg to the PNGs of the hicolor icon theme's usual sizes, into
# hicolor/SIZExSIZE/apps/. The PNGs are committed; run this after changing the SVG.
# Needs rsvg-convert (Debian: librsvg2-bin).
set -euo pipefail
cd "$(dirname "$0")"
for size in 16 22 24 32 48 64 128 256 512; do
  mkdir -p "hicolor/${size}x${size}/apps"
  rsvg-convert --width "$size" --height "$size" particle-sandbox.svg \
    --output "hicolor/${size}x${size}/apps/particle-sandbox.png"
done
