#!/usr/bin/env bash
# End-to-end checks of the lab bench's measuring instruments (docs/app-instruments.md, "Ruler and grid",
# "Stopwatch", "Gas instruments"): the real program in a virtual X display (Xvfb), driven with
# real X input (xdotool), read through its log and the text F12 writes beside each screenshot.
#
#   tests/e2e/lab_e2e.sh PATH/TO/particle-sandbox [OUTPUT_DIR]
#
#   the ramp preset, 900x800:
#   Q, then the ruler's ends dragged onto a ramp   -> the ruler reads the ramp's 20 degrees and
#                                                     the length between the two points
#   Shift+G                                        -> the grid is drawn (its colour), its squares
#                                                     the round size the zoom asks for
#   U, Space, 1.5 s, Space                         -> the stopwatch reads the simulated time
#   the gas preset (key 4), run 6 s of simulated time
#                                                  -> the pressure measured on the walls is the
#                                                     hard-disc value within 3 standard errors
#                                                     and 2 %, well above the ideal gas's
#   Squeeze                                        -> the box's area x 0.9, the ideal gas's
#                                                     pressure / 0.9 (the same temperature)
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/harness.sh"
e2e_begin lab "$@"
ROOT=$(cd "$HERE/../.." && pwd)

start_xvfb "$OUT/xvfb.log" 1024x900x24 || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy
LOG="$OUT/stdout.log"

start_app "$BIN" --renderer software --window 900x800 --seed 7 --log-controls --screenshot-dir "$OUT" \
    "$ROOT/assets/scenes/12-ramp.json"
wait_title "3 particles - PAUSED"
pass "window ${WIDTH}x$HEIGHT, box at ($BX, $BY), $ZOOM px/m"

# --- the ruler laid along the top ramp: (0, 0.5) to (4, 1.9559), 20 degrees -----------------------
# Its ends start across the middle of the 4 m x 3.9 m box, at (1, 1.95) and (3, 1.95). Drag each
# onto the ramp's face at 20 % and 80 % of its length.
key q
wait_log "\[I\] Ruler on"
move_end() {  # move_end FROM_X FROM_Y TO_X TO_Y (metres)
    local x0 y0 x1 y1 chain
    x0=$(sx "$1") y0=$(sy "$2") x1=$(sx "$3") y1=$(sy "$4")
    chain=(mousemove --sync "$x0" "$y0" sleep 0.1 mousedown 1 sleep 0.1)
    for i in 1 2 3 4 5 6 7 8; do
        chain+=(mousemove $((x0 + (x1 - x0) * i / 8)) $((y0 + (y1 - y0) * i / 8)) sleep 0.02)
    done
    xdotool "${chain[@]}" sleep 0.1 mouseup 1
    sleep 0.2
}
move_end 1 1.95 0.8 0.79118
wait_count "\[I\] Ruler: " 1
move_end 3 1.95 3.2 1.66472
wait_count "\[I\] Ruler: " 2
snap ruler
ruler=$(section ruler Ruler)
[[ -n "$ruler" ]] || fail "the screenshot's text has no Ruler section"
read -r len deg < <(sed -E 's/^([0-9.]+) m, ([0-9.]+)°.*/\1 \2/' <<<"$ruler")
# 0.6 of the ramp's 4.2567 m, to a pixel at each end.
awk -v l="$len" -v d="$deg" -v z="$ZOOM" 'BEGIN {
    tol = 2.0 / z
    exit !(l > 2.5540 - tol && l < 2.5540 + tol && d > 19.7 && d < 20.3) }' ||
    fail "the ruler along the ramp reads '$ruler', not 2.55 m at 20.0 degrees"
grep -q "particle" <<<"$(section ruler HUD)" || fail "no HUD"
[[ $(title) == *"3 particles - PAUSED"* ]] || fail "the ruler's drags changed the scene: $(title)"
pass "the ruler along the ramp: $ruler"

# --- the grid ------------------------------------------------------------------------------------
key shift+g
wait_log "\[I\] Grid on"
snap grid
# Squares of a round size at least 60 pixels wide at the zoom the window chose.
read -r step < <(awk -v z="$ZOOM" 'BEGIN {
    least = 60 / z; p = 10 ^ int(log(least) / log(10) - (least < 1))
    if (p >= least) { print p; exit }
    if (2 * p >= least) { print 2 * p; exit }
    if (5 * p >= least) { print 5 * p; exit }
    print 10 * p }')
legend=$(section grid Grid)
read -r shown < <(sed -E 's/^Grid: ([0-9.]+) (m|mm) squares.*/\1 \2/' <<<"$legend" |
    awk '{ print ($2 == "mm") ? $1 / 1000 : $1 }')
awk -v a="$shown" -v b="$step" 'BEGIN { exit !(a > 0.999 * b && a < 1.001 * b) }' ||
    fail "the grid's squares are not $step m at $ZOOM px/m: $legend"
read -r _ _ n < <(centroid "$OUT/grid.png" 55 66 84)  # the dark theme's grid (view/palette.cpp)
((n > 500)) || fail "only $n pixels of the grid's colour on screen"
pass "the grid: $(section grid Grid), $n pixels of its lines"

# --- the stopwatch on simulated time ---------------------------------------------------------------
key u
wait_log "\[I\] Stopwatch started"
key space
wait_log "\[I\] Resumed"
sleep 1.5
press_until space "\[I\] Paused"
snap stopwatch
hud=$(section stopwatch HUD)
read -r t < <(head -1 <<<"$hud" | sed -E 's/^Time ([0-9.]+) s.*/\1/')
read -r w < <(grep -o "Stopwatch [0-9.]* s" <<<"$hud" | sed -E 's/Stopwatch ([0-9.]+) s/\1/')
[[ -n "$w" ]] || fail "the HUD shows no stopwatch: $hud"
awk -v t="$t" -v w="$w" 'BEGIN { exit !(t > 0.2 && w - t < 0.01 && t - w < 0.01) }' ||
    fail "the stopwatch reads $w s where the simulated time is $t s"
pass "the stopwatch reads $w s at t = $t s"

# --- the gas: the pressure measured on the walls ----------------------------------------------------
key 4
wait_title "4000 particles - PAUSED"
key space
wait_log "\[I\] Resumed"
t=0
for _ in $(seq 60); do
    sleep 2
    snap gas
    t=$(section gas HUD | head -1 | sed -E 's/^Time ([0-9.]+) s.*/\1/')
    awk -v t="$t" 'BEGIN { exit !(t >= 6.0) }' && break
done
gas=$(section gas Gas)
measured=$(grep "^Pressure, measured:" <<<"$gas") || fail "no measured pressure at t = $t s: $gas"
read -r p dp < <(sed -E 's/^Pressure, measured: ([0-9.]+) ± ([0-9.]+) N\/m.*/\1 \2/' <<<"$measured")
read -r hd < <(grep "hard discs:" <<<"$gas" | sed -E 's/.*hard discs: ([0-9.]+) N\/m.*/\1/')
read -r ideal < <(grep "ideal gas:" <<<"$gas" | sed -E 's/.*ideal gas: ([0-9.]+) N\/m.*/\1/')
awk -v p="$p" -v dp="$dp" -v h="$hd" -v i="$ideal" 'BEGIN {
    d = p - h; if (d < 0) d = -d
    exit !(dp > 0 && d <= 3 * dp + 0.02 * h && p > 1.2 * i) }' ||
    fail "measured $p ± $dp N/m against hard discs $hd N/m and ideal gas $ideal N/m: $gas"
grep -q "^Pressure plot: " <<<"$gas" || fail "no pressure plot line: $gas"
pass "the gas at t = $t s: measured $p ± $dp N/m, hard discs $hd N/m, ideal gas $ideal N/m"

# --- Squeeze: the box's area x 0.9 at the same temperature, the ideal gas's pressure / 0.9 ----------
click "Squeeze"
wait_log "\[I\] Box .* the area x0.9, the particles moved with it"
snap squeezed
read -r ideal2 < <(section squeezed Gas | grep "ideal gas:" | sed -E 's/.*ideal gas: ([0-9.]+) N\/m.*/\1/')
awk -v a="$ideal" -v b="$ideal2" 'BEGIN { r = b / a; exit !(r > 1.10 && r < 1.125) }' ||
    fail "squeezed, the ideal gas's pressure went from $ideal to $ideal2 N/m, not / 0.9"
pass "squeezed: the ideal gas's pressure $ideal -> $ideal2 N/m"

key Escape  # the squeeze is unsaved: the quit dialog; D discards
quit_with d 2>/dev/null || true
if kill -0 "$APP_PID" 2>/dev/null; then fail "the program did not quit"; fi
echo "PASS"
