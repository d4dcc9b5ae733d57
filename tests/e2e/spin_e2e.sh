#!/usr/bin/env bash
# End-to-end checks of discs that turn (docs/app-instruments.md, "Discs that turn"): the ramp preset in the
# real program in a virtual X display (Xvfb), driven with real X input (xdotool), read through
# its log, the places --log-controls gives, the screenshots' pixels and the text F12 writes
# beside each screenshot.
#
#   tests/e2e/spin_e2e.sh PATH/TO/particle-sandbox [OUTPUT_DIR]
#
#   1000x800, the ramp (a ball, a disc and a disc that cannot turn), run for about 0.7 s:
#   the screenshot               -> the ball and the disc show their spin marks (a dark quarter),
#                                   the disc that cannot turn none; the Readouts list the rotational energy
#   I, a click on ball 1's row   -> the values table's text lists omega: the ball and the disc
#                                   roll (omega r = their speed), the disc that cannot turn has
#                                   omega 0
#   C (the panel folded)         -> the inspector reads the ball's angular velocity in rad/s and
#                                   rev/min, and its rotational kinetic energy
#   C, the Show section's Spin   -> the spin marks are gone
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/harness.sh"
e2e_begin spin "$@"

start_xvfb "$OUT/xvfb.log" 1024x900x24 || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy
LOG="$OUT/stdout.log"

start_app "$BIN" --renderer software --window 1000x800 --seed 7 --log-controls \
    --screenshot-dir "$OUT" "$HERE/../../assets/scenes/12-ramp.json"
wait_title "3 particles - PAUSED"
pass "window ${WIDTH}x$HEIGHT, box at ($BX, $BY), $ZOOM px/m"

# Pixels of a colour in a screenshot (exact, as the renderer draws an opaque mark).
count() { convert "$OUT/$1.png" -depth 8 txt:- | grep -c "#$2" || true; }
# The marks' colours (render/spin_mark.cpp: a light disc's hue at a third): the ball's, the
# disc's and the would-be mark of the disc that cannot turn.
BALL_MARK=1E354D
DISC_MARK=4D1E17
FIXED_MARK=493F1E

key space
wait_log "\[I\] Resumed"
sleep 0.7
press_until space "\[I\] Paused"
xdotool mousemove --sync $((WX + WIDTH - 5)) $((WY + HEIGHT - 5))  # no launch preview
snap run
ball=$(count run "$BALL_MARK")
disc=$(count run "$DISC_MARK")
fixed=$(count run "$FIXED_MARK")
((ball > 20)) || fail "the ball shows no spin mark ($ball pixels of #$BALL_MARK)"
((disc > 20)) || fail "the disc shows no spin mark ($disc pixels of #$DISC_MARK)"
((fixed == 0)) || fail "the disc that cannot turn shows a mark ($fixed pixels)"
pass "spin marks: the ball $ball pixels, the disc $disc, the disc that cannot turn none"
grep -q "\[I\] Control readout Rotational energy at" "$LOG" ||
    fail "the Readouts do not list the rotational energy"
grep -q "\[I\] Control readout Angular momentum at" "$LOG" ||
    fail "the Readouts do not list the angular momentum"
pass "the Readouts list the rotational energy and the angular momentum"

# --- the values table: omega for each, rolling for the ball and the disc --------------------------
key i
wait_log "\[I\] Values table on"
sleep 0.5
click "values row 1"  # selects ball 1 (for the inspector below)
snap values
values=$(section values Values)
grep -qF $'vy (m/s)\t\xcf\x89 (rad/s)\tpx' <<<"$(head -1 <<<"$values")" ||
    fail "the values table has no omega column after vy: $(head -1 <<<"$values")"
# Rolling: omega r = |v| (r = 0.12 m), to the table's three figures.
for n in 1 2; do
    row=$(grep -P "^$n\t" <<<"$values") || fail "no row for particle $n: $values"
    # With y up (the default) omega is counterclockwise-positive: rolling to the right, it is
    # negative (clockwise).
    awk -F'\t' -v n="$n" '{ v = sqrt($4 * $4 + $5 * $5); w = -$6 * 0.12 * ($4 < 0 ? -1 : 1);
        if (v < 0.5 || w < 0.99 * v || w > 1.01 * v) { print "particle " n ": omega r " w " m/s against speed " v " m/s"; exit 1 } }' <<<"$row" ||
        fail "particle $n does not roll: $row"
done
row=$(grep -P "^3\t" <<<"$values")
[[ "$(cut -f6 <<<"$row")" == "0" ]] || fail "the disc that cannot turn turns: $row"
pass "values: the ball and the disc roll (omega r = v), the disc that cannot turn has omega 0"

# --- the inspector, the panel folded --------------------------------------------------------------
key c
sleep 0.4
snap inspector
inspector=$(section inspector Inspector)
[[ "$(head -1 <<<"$inspector")" == "Particle 1" ]] || fail "the inspector is not ball 1's: $inspector"
line=$(grep "^angular velocity" <<<"$inspector") ||
    fail "the inspector shows no angular velocity: $inspector"
# Rolling to the right, with y up (the default): clockwise, negative.
read -r w rpm < <(sed -E 's/^angular velocity (-?[0-9.]+) rad\/s = (-?[0-9.]+) rev\/min$/\1 \2/' <<<"$line")
awk -v w="$w" -v r="$rpm" 'BEGIN { exit !(r < 0 && w < 0 && (r - w * 60 / 6.2831853) ^ 2 < (0.01 * r) ^ 2) }' ||
    fail "rev/min is not rad/s x 60 / 2 pi: $line"
# In joules with the prefix its size takes (below 1 J it reads "994 mJ rotation").
grep -Eq " [0-9.]+ (m|k)?J rotation$" <<<"$inspector" ||
    fail "no rotational energy in the inspector: $inspector"
grep -q "inertia factor  k = 0.4" <<<"$inspector" || fail "the ball's k is not 0.4: $inspector"
pass "inspector: $line"

# --- the Spin checkbox hides the marks ----------------------------------------------------------------
key c  # the panel back
sleep 0.3
click "Spin"
wait_log "\[I\] Spin marks off"
snap hidden
(($(count hidden "$BALL_MARK") == 0)) || fail "the ball's mark is still drawn with Spin off"
pass "the Spin checkbox hides the spin marks"

quit_by_esc  # nothing was edited: Esc asks whether to quit, Enter quits
if kill -0 "$APP_PID" 2>/dev/null; then fail "the program did not quit"; fi
echo "PASS"
