#!/usr/bin/env bash
# Makes the app's pictures in docs/images, each the app's own F12 screenshot under Xvfb:
#   sandbox.png  the built-in scene (7 m box, 1 px = 1 cm), paused, labels on (S), 800x800
#   overlays-momentum.png  the built-in scene running 4 s with V and all trails (L, L), 720x720
#   overlays-gas.png       04-gas-in-a-box after 13 s with K and D, arrows off, 900x720
#   help.png     the built-in scene, paused, with the help overlay (H), 720x720 window
#   inspect.png  the built-in scene, paused, the 18 kg particle selected by a click and its
#                edit prompt open with 25 typed (Enter, 2, 5), 960x640 window scaled to 75 %
#   galton.png   09-galton-board 30 s into its run (run by particle-sim, beside the app in the
#                build tree, and saved with its bins), opened paused: its bins panel against
#                the binomial and the normal curve, 1200x850
#   funnel.png, hourglass.png, ramp.png, basketball.png  the obstacle presets 10-13, each run
#                from paused for a few seconds then paused again, arrows off (the basketball
#                with all trails; the ramp 1 s in, its spin marks shown), 800x800 windows scaled
#                to 60 %
#
#   scripts/app_images.sh PATH/TO/particle-sandbox [OUTPUT_DIR [NAME]]
#
# With NAME (sandbox, overlays-momentum, overlays-gas, help, inspect, galton, funnel, hourglass,
# ramp, basketball) only that picture is made.
#
# Needs Xvfb (xvfb-run), xdotool and ImageMagick (scripts/install-deps.sh --test).
set -euo pipefail
BIN=${1:?usage: app_images.sh PATH/TO/particle-sandbox [OUTPUT_DIR]}
OUT=${2:-docs/images}
ONLY=${3:-}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

cat >"$WORK/drive.sh" <<'DRIVE'
set -euo pipefail
# start SIZE SHOT_DIR [ARGS...]: the app (paused on the built-in scene unless ARGS say
# otherwise); sets pid, wid, X, Y, zoom, bx, by.
start() {
    local size=$1 dir=$2
    shift 2
    [[ $# -gt 0 ]] || set -- --paused
    "$BIN" --no-settings --renderer software --window "$size" --screenshot-dir "$dir" "$@" >"$dir/log" &
    pid=$!
    wid=$(timeout 20 xdotool search --sync --onlyvisible --pid "$pid" --name "Particle Sandbox" | head -1)
    eval "$(xdotool getwindowgeometry --shell "$wid")"
    # The pointer in the window's bottom-right corner, off the box and the panel: no launch
    # preview at the middle of the picture and no tooltip.
    xdotool mousemove --sync $((X + WIDTH - 5)) $((Y + HEIGHT - 5))
    until grep -q "View: zoom" "$dir/log"; do sleep 0.05; done
    read -r zoom bx by < <(sed -nE 's/.*zoom ([0-9.]+) px\/m, box top-left at \[([-0-9.]+), ([-0-9.]+)\].*/\1 \2 \3/p' "$dir/log" | head -1)
}
# shoot_and_quit SHOT_DIR ESCAPES
shoot_and_quit() {
    sleep 0.3
    xdotool key --window "$wid" F12
    until grep -q "Saved screenshot" "$1/log"; do sleep 0.05; done
    for ((k = 1; k < $2; ++k)); do xdotool key --window "$wid" Escape 2>/dev/null || true; sleep 0.2; done
    # The window may be gone before xdotool sends the key release.
    xdotool key --window "$wid" Escape 2>/dev/null || true
    # Still there: it asks, Enter quits (nothing unsaved), or D discards the unsaved changes.
    sleep 0.5
    if kill -0 "$pid" 2>/dev/null; then
        if grep -q "Quit Particle Sandbox?" "$1/log"; then
            xdotool key --window "$wid" Return 2>/dev/null || true
        else
            xdotool key --window "$wid" d 2>/dev/null || true
        fi
    fi
    wait "$pid"
}

# want NAME: whether to make picture NAME.
want() { [[ -z "$ONLY" || "$ONLY" == "$1" ]]; }
mkdir -p "$WORK/sandbox" "$WORK/help" "$WORK/inspect" "$WORK/momentum" "$WORK/gas" "$WORK/galton"
if want galton; then
# The run takes longer than a picture should wait for the window: the runner runs it.
"$SIM" "$ASSETS/scenes/09-galton-board.json" --duration 30 --report /dev/null \
    --save "$WORK/galton-30s.json"
start 1200x850 "$WORK/galton" "$WORK/galton-30s.json" --paused
shoot_and_quit "$WORK/galton" 1
fi

if want overlays-momentum; then
start 720x720 "$WORK/momentum" --seed 1
for k in v l l; do xdotool key --window "$wid" "$k"; sleep 0.1; done
sleep 4
xdotool key --window "$wid" space  # paused: nothing to lose, one Esc quits
shoot_and_quit "$WORK/momentum" 1
fi

if want overlays-gas; then
start 900x720 "$WORK/gas" "$ASSETS/scenes/04-gas-in-a-box.json" --no-arrows
for k in k d; do xdotool key --window "$wid" "$k"; sleep 0.1; done
sleep 13
shoot_and_quit "$WORK/gas" 1
fi

if want sandbox; then
start 800x800 "$WORK/sandbox"
xdotool key --window "$wid" s
shoot_and_quit "$WORK/sandbox" 1
fi

if want help; then
start 720x720 "$WORK/help"
xdotool key --window "$wid" h
shoot_and_quit "$WORK/help" 2  # Esc closes the help, then quits
fi

if want inspect; then
start 960x640 "$WORK/inspect"
# The 18 kg particle at (5.2, 1.6) m.
px=$(awk -v z="$zoom" -v b="$bx" -v o="$X" 'BEGIN { printf "%d", o + b + 5.2 * z }')
py=$(awk -v z="$zoom" -v b="$by" -v o="$Y" 'BEGIN { printf "%d", o + b + 1.6 * z }')
xdotool mousemove --sync "$px" "$py" sleep 0.1 click 1
sleep 0.3
xdotool key --window "$wid" Return sleep 0.2 type --window "$wid" --delay 50 "25"
shoot_and_quit "$WORK/inspect" 2
fi

# run_preset NAME FILE SECONDS [KEYS...]: the preset paused with arrows off, KEYS pressed, run
# for SECONDS, paused again and shot.
run_preset() {
    local name=$1 file=$2 seconds=$3
    shift 3
    want "$name" || return 0
    mkdir -p "$WORK/$name"
    start 800x800 "$WORK/$name" --paused --no-arrows "$ASSETS/scenes/$file"
    for k in "$@"; do xdotool key --window "$wid" "$k"; sleep 0.1; done
    xdotool key --window "$wid" space
    sleep "$seconds"
    xdotool key --window "$wid" space
    shoot_and_quit "$WORK/$name" 1
}
run_preset funnel 10-funnel.json 4
run_preset hourglass 11-hourglass.json 1.2
run_preset ramp 12-ramp.json 1.0
run_preset basketball 13-basketball-and-tennis-ball.json 1.25 l l
DRIVE
ASSETS=$(cd "$(dirname "$0")/../assets" && pwd)
SIM=$(cd "$(dirname "$BIN")/../cli" && pwd)/particle-sim
BIN=$BIN WORK=$WORK ASSETS=$ASSETS ONLY=$ONLY SIM=$SIM xvfb-run -a -s "-screen 0 1300x900x24" bash ${APP_IMAGES_TRACE:+-x} "$WORK/drive.sh"
# convert_one NAME DIR [OPTIONS...]: the screenshot in WORK/DIR as OUT/NAME.png, when made.
convert_one() {
    local name=$1 dir=$2
    shift 2
    if [[ -z "$ONLY" || "$ONLY" == "$name" ]]; then
        convert "$WORK/$dir"/particle-sandbox-*.png "$@" -strip "$OUT/$name.png"
    fi
}
convert_one sandbox sandbox
convert_one overlays-momentum momentum
convert_one overlays-gas gas
convert_one help help
convert_one inspect inspect -resize 75%
convert_one galton galton
for name in funnel hourglass ramp basketball; do
    convert_one "$name" "$name" -resize 60%
done
echo "wrote ${ONLY:-sandbox, overlays-momentum, overlays-gas, help, inspect, galton, funnel, hourglass, ramp and basketball} .png in $OUT"
