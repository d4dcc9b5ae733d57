#!/usr/bin/env bash
# End-to-end checks of the lab bench's instruments (docs/app-instruments.md, "Last collision card"): the
# real program in a virtual X display (Xvfb), driven with real X input (xdotool), read through
# its log, the places --log-controls gives and the text F12 writes beside each screenshot.
#
#   tests/e2e/instruments_e2e.sh PATH/TO/particle-sandbox [OUTPUT_DIR]
#
#   800x800, a 1 kg ball at 2 m/s meeting a 3 kg ball at -1 m/s (e = 1, the exact mode):
#   J, Space, then Space after the collision -> the Last collision section is in the window,
#                                               and the card reads the textbook's velocities,
#                                               momenta and energy, before and after, and its
#                                               momenta diagram adds them up tip to tail
#   a click on the 3 kg ball                 -> the card follows it: the 3 kg ball first
#   I, then 2 typed into ball 1's mass cell   -> the values table lists both balls' signed
#                                               values and the totals (p -1.00 kg m/s, 3.50 J),
#                                               then ball 1 is 2 kg and the total mass 5.00 kg
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/harness.sh"
e2e_begin instruments "$@"

start_xvfb "$OUT/xvfb.log" 1024x900x24 || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy
LOG="$OUT/stdout.log"

cat >"$OUT/head-on.json" <<'JSON'
{"version": 4, "name": "Head-on", "description": "1 kg at 2 m/s meets 3 kg at -1 m/s",
 "world": {"width": 10.0, "height": 4.0, "walls": true, "gravity": [0, 0], "restitution": 1.0},
 "solver": {"mode": "exact", "dt": 0.016666666666666666},
 "particles": [{"x": 2, "y": 2, "vx": 2, "vy": 0, "mass": 1, "radius": 0.4},
               {"x": 7, "y": 2, "vx": -1, "vy": 0, "mass": 3, "radius": 0.6}]}
JSON

start_app "$BIN" --renderer software --window 800x800 --seed 7 --log-controls \
    --screenshot-dir "$OUT" "$OUT/head-on.json"
wait_title "2 particles - PAUSED"
pass "window ${WIDTH}x$HEIGHT, box at ($BX, $BY), $ZOOM px/m"

# --- the card, after the collision at t = 4/3 s ---------------------------------------------------
key j
wait_log "\[I\] Last collision card on"
key space
wait_log "\[I\] Resumed"
sleep 1.8
press_until space "\[I\] Paused"
sleep 0.6
# The card does not scroll the panel to itself (nothing moves under a pointer on its own): the
# wheel over the panel brings it up, as a student scrolls down to it.
read -r x y < <(ctl "section Last collision")
for _ in $(seq 40); do
    ((y - WY > 0 && y - WY < 150)) && break
    xdotool mousemove --sync $((WX + 150)) $((WY + 400)) click 5
    sleep 0.2
    read -r x y < <(ctl "section Last collision")
done
xdotool mousemove --sync $((WX + 900)) $((WY + 700))
sleep 0.3
((y - WY > 0 && y - WY < HEIGHT - 60)) || fail "the Last collision section is at y $((y - WY))"
snap card
card=$(section card "Last collision")
[[ -n "$card" ]] || fail "the screenshot's text has no Last collision section"
expect() {
    grep -qF -- "$1" <<<"$card" || fail "the card does not read '$1': $card"
}
expect "Particles 1 and 2 at t = 1.33 s"
expect "v 1: (2.00, 0) m/s -> (-2.50, 0) m/s"
expect "v 2: (-1.00, 0) m/s -> (0.500, 0) m/s"
expect "p 2: (-3.00, 0) kg m/s -> (1.50, 0) kg m/s"
expect "total p: (-1.00, 0) kg m/s -> (-1.00, 0) kg m/s"
expect "kinetic energy: 3.50 J -> 3.50 J"
expect "Total momentum kept"
expect "Momenta before: p 1 (2.00, 0) + p 2 (-3.00, 0) = total p (-1.00, 0) kg m/s"
expect "Momenta after: p 1 (-2.50, 0) + p 2 (1.50, 0) = total p (-1.00, 0) kg m/s"
pass "the card reads the textbook collision: $(sed -n 2p <<<"$card")"

# --- a click on the 3 kg ball: the card follows it -------------------------------------------------
# Where the 3 kg ball is now: 7 - 4/3 m at the collision, then 0.5 m/s for the time since (the
# HUD's first line in the screenshot's text).
read -r t < <(section card HUD | head -1 | sed -E 's/^Time ([0-9.]+) s.*/\1/')
bx=$(awk -v t="$t" 'BEGIN { printf "%.3f", 7.0 - 4.0 / 3.0 + 0.5 * (t - 4.0 / 3.0) }')
xdotool mousemove --sync "$(sx "$bx")" "$(sy 2.0)" sleep 0.1 click 1
wait_log "\[I\] Selected particle 2 at"
snap follows
card=$(section follows "Last collision")
expect "Particles 2 and 1 at t = 1.33 s"
expect "Impulse on 2: (4.50, 0) N s"
pass "selected, the 3 kg ball comes first: $(head -1 <<<"$card")"

# --- the values table: read, then a mass typed into a cell ----------------------------------------
key i
wait_log "\[I\] Values table on"
sleep 0.5
snap values
values=$(section values Values)
grep -qP "^total\t\t\t\t\t-1.00\t0\t3.50\t4.00$" <<<"$values" ||
    fail "the values table's totals are not p = (-1.00, 0), 3.50 J, 4.00 kg: $values"
grep -qP "^2\t[0-9.]+\t2.00\t0.500\t0\t1.50\t0\t0.375\t3.00$" <<<"$values" ||
    fail "ball 2's row is not v = (0.5, 0), p = (1.5, 0): $values"
pass "the values table: $(tail -1 <<<"$values" | tr '\t' ' ')"
# An 800-pixel window shows the table's first columns: it scrolls sideways (wheel sideways over
# it) to the mass, as a user would.
read -r tx ty < <(ctl "values 1 x")
for ((turn = 0; turn < 20; turn++)); do
    read -r mx _ < <(ctl "values 1 mass")
    ((mx < WX + 760)) && break
    xdotool mousemove "$tx" "$ty" sleep 0.1 click 6  # no --sync: the pointer may be there
    sleep 0.2
done
((mx < WX + 760)) || fail "the values table does not scroll to its mass column (at $mx)"
type_into "values 1 mass" 2
wait_log "\[I\] Edited particle 1: mass 2 kg"
snap edited
grep -qP "^total\t.*\t5.00$" <<<"$(section edited Values)" ||
    fail "after the edit the total mass is not 5.00 kg: $(section edited Values)"
pass "a mass typed into the table: $(section edited Values | tail -1 | tr '\t' ' ')"

key Escape  # unsaved changes (the mass): the quit dialog; D discards
wait_log "Unsaved changes to .*: Save, Discard or Cancel"
quit_with d
if kill -0 "$APP_PID" 2>/dev/null; then fail "the program did not quit"; fi
echo "PASS"
