#!/usr/bin/env bash
# Makes the app's pictures in docs/images, each the app's own F12 screenshot under Xvfb:
#   sandbox.png  the built-in scene (7 m box, 1 px = 1 cm), paused, labels on (S), 800x800
#   help.png     the built-in scene, paused, with the help overlay (H), 720x720 window
#   inspect.png  the built-in scene, paused, the 18 kg particle selected by a click and its
#                edit prompt open with 25 typed (Enter, 2, 5), 600x600 window scaled to 75 %
#
#   scripts/app_images.sh PATH/TO/particle-sandbox [OUTPUT_DIR]
#
# Needs Xvfb (xvfb-run), xdotool and ImageMagick (scripts/install-deps.sh --test).
set -euo pipefail
BIN=${1:?usage: app_images.sh PATH/TO/particle-sandbox [OUTPUT_DIR]}
OUT=${2:-docs/images}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

cat >"$WORK/drive.sh" <<'DRIVE'
set -euo pipefail
# start SIZE SHOT_DIR: the app, paused, on the built-in scene; sets pid, wid, X, Y, zoom, bx, by.
start() {
    "$BIN" --renderer software --window "$1" --paused --screenshot-dir "$2" >"$2/log" &
    pid=$!
    wid=$(timeout 20 xdotool search --sync --onlyvisible --pid "$pid" --name "Particle Sandbox" | head -1)
    eval "$(xdotool getwindowgeometry --shell "$wid")"
    until grep -q "View: zoom" "$2/log"; do sleep 0.05; done
    read -r zoom bx by < <(sed -nE 's/.*zoom ([0-9.]+) px\/m, box top-left at \[([-0-9.]+), ([-0-9.]+)\].*/\1 \2 \3/p' "$2/log" | head -1)
}
# shoot_and_quit SHOT_DIR ESCAPES
shoot_and_quit() {
    sleep 0.3
    xdotool key --window "$wid" F12
    until grep -q "Saved screenshot" "$1/log"; do sleep 0.05; done
    for ((k = 1; k < $2; ++k)); do xdotool key --window "$wid" Escape; sleep 0.2; done
    # The window may be gone before xdotool sends the key release.
    xdotool key --window "$wid" Escape 2>/dev/null || true
    wait "$pid"
}

mkdir -p "$WORK/sandbox" "$WORK/help" "$WORK/inspect"
start 800x800 "$WORK/sandbox"
xdotool key --window "$wid" s
shoot_and_quit "$WORK/sandbox" 1

start 720x720 "$WORK/help"
xdotool key --window "$wid" h
shoot_and_quit "$WORK/help" 2  # Esc closes the help, then quits

start 600x600 "$WORK/inspect"
# The 18 kg particle at (5.2, 1.6) m.
px=$(awk -v z="$zoom" -v b="$bx" -v o="$X" 'BEGIN { printf "%d", o + b + 5.2 * z }')
py=$(awk -v z="$zoom" -v b="$by" -v o="$Y" 'BEGIN { printf "%d", o + b + 1.6 * z }')
xdotool mousemove --sync "$px" "$py" sleep 0.1 click 1
sleep 0.3
xdotool key --window "$wid" Return sleep 0.2 type --window "$wid" --delay 50 "25"
shoot_and_quit "$WORK/inspect" 2
DRIVE
BIN=$BIN WORK=$WORK xvfb-run -a -s "-screen 0 900x900x24" bash ${APP_IMAGES_TRACE:+-x} "$WORK/drive.sh"
convert "$WORK"/sandbox/particle-sandbox-*.png -strip "$OUT/sandbox.png"
convert "$WORK"/help/particle-sandbox-*.png -strip "$OUT/help.png"
convert "$WORK"/inspect/particle-sandbox-*.png -resize 75% -strip "$OUT/inspect.png"
echo "wrote $OUT/sandbox.png, $OUT/help.png and $OUT/inspect.png"
