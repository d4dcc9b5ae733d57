#!/usr/bin/env bash
# Makes docs/images/inspect.png: the built-in scene, paused, with the 18 kg particle selected
# and its edit prompt open, captured by the app's own F12 and scaled to 75 %.
#
#   scripts/inspect_image.sh PATH/TO/particle-sandbox [OUTPUT_PNG]
#
# Needs Xvfb (xvfb-run), xdotool and ImageMagick (scripts/install-deps.sh --test).
set -euo pipefail
BIN=${1:?usage: inspect_image.sh PATH/TO/particle-sandbox [OUTPUT_PNG]}
OUT=${2:-docs/images/inspect.png}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

cat >"$WORK/drive.sh" <<'DRIVE'
set -euo pipefail
"$BIN" --renderer software --window 600x600 --paused --screenshot-dir "$WORK" >"$WORK/log" &
pid=$!
wid=$(timeout 20 xdotool search --sync --onlyvisible --pid "$pid" --name "Particle Sandbox" | head -1)
eval "$(xdotool getwindowgeometry --shell "$wid")"
until grep -q "View: zoom" "$WORK/log"; do sleep 0.05; done
read -r zoom bx by < <(sed -nE 's/.*zoom ([0-9.]+) px\/m, box top-left at \[([-0-9.]+), ([-0-9.]+)\].*/\1 \2 \3/p' "$WORK/log" | head -1)
# The 18 kg particle at (520, 160) m.
px=$(awk -v z="$zoom" -v b="$bx" -v o="$X" 'BEGIN { printf "%d", o + b + 520 * z }')
py=$(awk -v z="$zoom" -v b="$by" -v o="$Y" 'BEGIN { printf "%d", o + b + 160 * z }')
xdotool mousemove --sync "$px" "$py" sleep 0.1 click 1
sleep 0.3
xdotool key --window "$wid" Return sleep 0.2 type --window "$wid" --delay 50 "25"
sleep 0.2
xdotool key --window "$wid" F12
until grep -q "Saved screenshot" "$WORK/log"; do sleep 0.05; done
xdotool key --window "$wid" Escape
sleep 0.2
# The window may be gone before xdotool sends the key release.
xdotool key --window "$wid" Escape 2>/dev/null || true
wait "$pid"
DRIVE
BIN=$BIN WORK=$WORK xvfb-run -a -s "-screen 0 800x800x24" bash "$WORK/drive.sh"
convert "$WORK"/particle-sandbox-*.png -resize 75% -strip "$OUT"
echo "wrote $OUT"
