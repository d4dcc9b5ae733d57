#!/usr/bin/env bash
# The on-screen controls in a real window under Xvfb, driven with real X input (xdotool):
#   1. a click on the Play button             -> "pressed 1" (and the click is not passed on)
#   2. a click on the checkbox                -> "arrows on"
#   3. a drag along the slider to its left end -> restitution 0
#   4. a click beside the panel               -> "box click" (the controls let it through)
#   5. P                                      -> a PNG of the window, with the panel's colours
#
#   tests/app/gui/gui_window_e2e.sh PATH/TO/gui_window_check [OUTPUT_DIR]
set -euo pipefail

BIN=${1:?usage: gui_window_e2e.sh PATH/TO/gui_window_check [OUTPUT_DIR]}
OUT=${2:-$(pwd)/gui-window-out}
HERE=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$OUT"
rm -f "$OUT"/*.png "$OUT"/*.log
for tool in Xvfb xdpyinfo xdotool import convert; do
    command -v "$tool" >/dev/null || { "$HERE/../../../scripts/install-deps.sh" --test; break; }
done

# shellcheck source-path=SCRIPTDIR source=../../e2e/harness.sh
source "$HERE/../../e2e/harness.sh"
LOG="$OUT/stdout.log"
fail() {
    echo "FAIL: $*" >&2
    echo "--- log:" >&2
    cat "$LOG" "$OUT/stderr.log" >&2 2>/dev/null || true
    exit 1
}
wait_log() {  # wait_log REGEX
    local deadline=$((SECONDS + 10))
    until grep -Eq "$1" "$LOG"; do
        ((SECONDS < deadline)) || fail "timed out waiting for /$1/"
        sleep 0.05
    done
}

start_xvfb "$OUT/xvfb.log" 640x480x24 || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy

"$BIN" "$OUT/window.png" >"$LOG" 2>"$OUT/stderr.log" &
APP_PID=$!
WID=$(timeout 20 xdotool search --sync --onlyvisible --pid "$APP_PID" --name "GUI check" | head -1) ||
    fail "no window within 20 s"
eval "$(xdotool getwindowgeometry --shell "$WID")"  # X, Y, WIDTH, HEIGHT
xdotool windowfocus --sync "$WID" 2>/dev/null || true
wait_log "^button "
read -r BX BY < <(sed -nE 's/^button ([0-9]+) ([0-9]+)$/\1 \2/p' "$LOG")
read -r SX0 SX1 SY < <(sed -nE 's/^slider ([0-9]+) ([0-9]+) ([0-9]+)$/\1 \2 \3/p' "$LOG")
pass "window $WID at $X,$Y; Play at $BX,$BY; slider from $SX0 to $SX1 at y $SY"

click() {  # click X Y (window pixels)
    xdotool mousemove $((X + $1)) $((Y + $2))
    sleep 0.2
    xdotool click 1
    sleep 0.2
}

click "$BX" "$BY"
wait_log "^pressed 1$"
grep -q "^box click" "$LOG" && fail "the click on Play also reached the box"
pass "Play clicked once, not passed on"

# The checkbox is the next row under the button: its square sits at the panel's left margin.
click $((BX - 45)) $((BY + 32))
wait_log "^arrows on$"
pass "checkbox turned on"

xdotool mousemove $((X + SX1 - 5)) $((Y + SY))
sleep 0.2
xdotool mousedown 1
for dx in 20 40 60 80 100 120 140; do
    xdotool mousemove $((X + SX1 - 5 - dx)) $((Y + SY))
    sleep 0.05
done
xdotool mouseup 1
wait_log "^restitution 0\.000000$"
pass "slider dragged to 0"

click 350 150
wait_log "^box click 350 150$"
pass "a click beside the panel reaches the box"

xdotool mousemove $((X + BX)) $((Y + BY))  # hover: the button's hovered colour, a tooltip
sleep 1
xdotool key --window "$WID" p
wait_log "^saved "
[[ -s "$OUT/window.png" ]] || fail "no PNG"
import -window root "$OUT/screen.png"
size=$(identify -format "%wx%h" "$OUT/window.png")
[[ "$size" == "480x320" ]] || fail "PNG is $size, not 480x320"
# The hovered Play button is ImGui's dark style's light blue (0.26, 0.59, 0.98).
button=$(convert "$OUT/window.png" -crop 1x1+$((BX - 55))+$((BY - 12)) -format "%[fx:int(255*r)] %[fx:int(255*g)] %[fx:int(255*b)]" info:)
read -r r g b <<<"$button"
((b > 200 && r < 100 && g > 120)) || fail "the hovered Play button is not light blue: $button"
# The box outline drawn by SDL beside the panel is still there.
edge=$(convert "$OUT/window.png" -crop 1x1+250+150 -format "%[fx:int(255*r)]" info:)
((edge >= 190)) || fail "the box outline is gone: $edge"
pass "window image $size, hovered button ($button), box outline kept"

xdotool key --window "$WID" Escape
for _ in $(seq 50); do kill -0 "$APP_PID" 2>/dev/null || break; sleep 0.1; done
kill -0 "$APP_PID" 2>/dev/null && fail "did not exit on Esc"
wait "$APP_PID" || fail "exit status $?"
APP_PID=""
pass "exits on Esc"
