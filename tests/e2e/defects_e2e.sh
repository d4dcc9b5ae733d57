#!/usr/bin/env bash
# End-to-end checks of the window defects a new user met (issue 13's 1, 3, 4, 5, 7 and 10), and
# of the presets' keys: the real program in a virtual X display (Xvfb) at 800x600, driven with
# real X input (xdotool). F12 writes a screenshot and, beside it, the text on screen with the
# rectangles of the box and the panels (NAME.txt), which is what the checks read; the pictures
# are left in OUTPUT_DIR to be looked at.
#
#   tests/e2e/defects_e2e.sh PATH/TO/particle-sandbox [OUTPUT_DIR]
#
#   1. S (labels) in the built-in scene        -> labels drawn, none across the walls, none over
#                                                 the HUD or the messages (layout rectangles)
#   3. paused, drags the yellow disc into the  -> the HUD's overlap reading is the overlap on
#      orange one and holds it there             screen (tens of cm), not 0
#   4. a message shown                         -> the message band lies below the box's floor,
#                                                 and the floor's wall is drawn whole
#   5. paused                                  -> no frame rate read as a rate of a few frames
#                                                 per second; the paused line says so
#   7. a launch dragged across the whole box   -> the preview and a message say it was capped
#  10. a scene too heavy for x8, at x8         -> the HUD shows the speed reached beside x8
#   +  keys 0 and Shift+1 open presets 10, 11  -> opened paused, the message names the key
#   +  600x600, key 9, C (panel open), C again -> the bins chart folds away while the panel is
#                                                 open (the HUD says so), and comes back
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/harness.sh"
e2e_begin defects "$@"

start_xvfb "$OUT/xvfb.log" 1024x768x24 || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy
LOG="$OUT/stdout.log"

start_app "$BIN" --renderer software --window 800x600 --paused --seed 7 \
    --save-to "$OUT/saved.json" --screenshot-dir "$OUT"
wait_title "6 particles - PAUSED"
pass "window ${WIDTH}x$HEIGHT, box at ($BX, $BY), $ZOOM px/m"

# --- 5. paused: the frame-rate line means something ------------------------------------------
sleep 1.5  # long enough for a sleeping loop's rate to fall to a few frames per second
snap 5-paused
hud=$(section 5-paused HUD)
[[ -n "$hud" ]] || fail "no HUD text in the screenshot's text"
if grep -Eiq "([0-9.]+) *fps|fps *([0-9.]+)" <<<"$hud"; then
    rate=$(grep -Eio "[0-9.]+ *fps|fps *[0-9.]+" <<<"$hud" | head -1 | grep -Eo "[0-9.]+")
    awk -v r="$rate" 'BEGIN { exit !(r >= 20) }' || fail "paused, the HUD reads $rate fps: $hud"
fi
grep -iq "paused" <<<"$hud" || fail "paused, the HUD does not say so: $hud"
pass "paused HUD: $(head -1 <<<"$hud")"

# --- 1. labels readable: drawn, clear of the walls, the HUD and the messages ----------------
key s
wait_log "Labels on"
snap 1-labels
labels=$(grep "^Labels:" "$OUT/1-labels.txt") || fail "no label count"
drawn=$(sed -E 's/Labels: ([0-9]+) drawn.*/\1/' <<<"$labels")
((drawn >= 3)) || fail "only $drawn labels drawn of 6: $labels"
read -r bx by bw bh < <(rect 1-labels box)
# The label text is white; the box's walls are white too, drawn 2 px outside the box. Inside
# the box, white pixels are label text (the discs are coloured); outside it, above, below and
# beside, nothing white but the walls and the panels.
inside=$(white_in "$OUT/1-labels.png" "$((bw - 4))x$((bh - 4))+$((bx + 2))+$((by + 2))")
((inside > 200)) || fail "labels on, but only $inside white pixels inside the box"
read -r hx hy hw hh < <(rect 1-labels hud)
read -r mx my mw mh < <(rect 1-labels messages)
gap=$((by - 3 - hy - hh))
((gap > 0)) || fail "no room between the HUD ($hy + $hh) and the box ($by)"
# A label may stand above the box, joined to its ball by a line (white, across the wall); one
# across the wall would darken the wall under its background. The top wall, two rows drawn just
# outside the box, is white all along.
top=$(white_in "$OUT/1-labels.png" "${bw}x2+$bx+$((by - 2))")
((top == 2 * bw)) || fail "the top wall is white in $top of $((2 * bw)) pixels: a label across it"
pass "labels: $labels, $inside text pixels, none across the top wall"

# --- 4. the message band below the floor -----------------------------------------------------
[[ -n "$mx" ]] || fail "no message band while a message is shown"
((my >= by + bh + 2)) || fail "the messages ($mx $my $mw $mh) cover the box ($bx $by $bw $bh)"
floor=$(white_in "$OUT/1-labels.png" "${bw}x3+$bx+$((by + bh))")
((floor >= bw)) || fail "the floor's wall is not drawn whole under the messages ($floor px)"
pass "messages at y $my, below the floor at y $((by + bh)); the floor drawn ($floor px)"
key s

# --- 3. a disc dragged into another while paused shows its overlap ---------------------------
# The yellow disc (5.2, 1.6) m, r 0.45 m, onto the orange one (6.0, 3.3) m, r 0.375 m, held.
xdotool mousemove --sync "$(sx 5.2)" "$(sy 1.6)" sleep 0.1 mousedown 1 sleep 0.1
for k in 1 2 3 4 5 6; do
    xdotool mousemove "$(sx "$(awk -v k=$k 'BEGIN { print 5.2 + 0.1 * k }')")" \
        "$(sy "$(awk -v k=$k 'BEGIN { print 1.6 + 0.233 * k }')")" sleep 0.03
done
snap 3-overlap-held
xdotool mouseup 1
hud=$(section 3-overlap-held HUD)
line=$(grep -i "overlap" <<<"$hud") || fail "no overlap reading in the HUD: $hud"
value=$(grep -Eio "overlap[^0-9]*[0-9.]+ *(mm|cm|m)" <<<"$line" | head -1)
[[ -n "$value" ]] || fail "no overlap figure in '$line'"
metres=$(awk -v v="$value" 'BEGIN {
    n = v; sub(/^[^0-9]*/, "", n); x = n + 0;
    if (v ~ /mm$/) x /= 1000; else if (v ~ /cm$/) x /= 100;
    print x }')
awk -v m="$metres" 'BEGIN { exit !(m > 0.1) }' ||
    fail "dragged 0.3 m deep into another disc, the HUD reads '$line'"
pass "overlap while paused: '$line'"

# --- 7. a capped launch says so --------------------------------------------------------------
key r
wait_log "Restarted: back to the scene as it opened"
# From near the left wall across the box to near the right wall, low in the (empty) lower half:
# 6.4 m of drag over a 1/3 s arrow is 19 m/s, over the cap of 2 box widths per second (14 m/s).
xdotool mousemove --sync "$(sx 0.3)" "$(sy 6.2)" sleep 0.1 mousedown 1 sleep 0.1
for k in 1 2 3 4 5 6 7 8; do
    xdotool mousemove "$(sx "$(awk -v k=$k 'BEGIN { print 0.3 + 0.8 * k }')")" "$(sy 6.2)" sleep 0.03
done
snap 7-capped-preview
xdotool mouseup 1
wait_log "[Cc]apped"
sleep 0.2
snap 7-capped-launched
grep -iq "capped" "$OUT/7-capped-launched.txt" ||
    fail "the capped launch is not shown: $(section 7-capped-launched Messages)"
pass "capped launch: $(grep -i -m1 "capped" "$LOG")"

# --- presets: keys 0 and Shift+1 reach presets 10 and 11, opened paused -----------------------
key 0
wait_log "Preset 10 of [0-9]+ \(key 0\), paused"
key shift+1
wait_log "Preset 11 of [0-9]+ \(key Shift\+1\), paused"
snap presets-11
pass "$(grep -m1 "Preset 11 of" "$LOG" | sed -E 's/^\[I\] //')"

# --- 10. a time speed the steps cannot reach is shown as reached -----------------------------
# 20000 discs with 32 substeps a frame: one simulated second costs seconds here, so x8 is far
# beyond reach.
cat >"$OUT/heavy.json" <<'EOF'
{
  "name": "Heavy",
  "description": "Twenty thousand small discs with 32 substeps a frame: too slow for x8.",
  "version": 1,
  "world": {"width": 7, "height": 7, "walls": true, "gravity": [0, 0], "restitution": 1.0, "friction": 0.0},
  "solver": {"mode": "substep", "dt": 0.016666666666666666, "substeps": 32, "broadphase": "auto"},
  "generate": {"count": 20000, "radius": 0.01, "mass": 1, "temperature": 0.1, "seed": 2}
}
EOF
kill "$APP_PID" 2>/dev/null || true
wait "$APP_PID" 2>/dev/null || true
LOG="$OUT/stdout-heavy.log"
SNAPS=0
start_app "$BIN" --renderer software --window 800x600 --no-arrows --seed 7 \
    --screenshot-dir "$OUT" "$OUT/heavy.json"
wait_log "Opened heavy.json: .*, paused: Space starts it"  # a scene named on the command line
key space
wait_log "Resumed"
key period
key period
key period
wait_log "Time speed x8"
sleep 2.5
snap 10-speed-reached
hud=$(section 10-speed-reached HUD)
reached=$(grep -Eo "x[0-9.]+ of x8" <<<"$hud" | head -1) ||
    fail "at x8 asked the HUD does not show what is reached: $hud"
r=$(sed -E 's/x([0-9.]+) of x8/\1/' <<<"$reached")
awk -v r="$r" 'BEGIN { exit !(r < 8) }' || fail "reached $r of x8"
pass "time speed: $(grep -E "x[0-9.]+ of x8" <<<"$hud" | head -1)"
kill "$APP_PID" 2>/dev/null || true
wait "$APP_PID" 2>/dev/null || true
APP_PID=""

# --- 600x600, the Galton board, the control panel opened with C ----------------------------------
# The bins chart beside the box while the panel is folded; with the panel open it would cover
# the board: it folds away, and the HUD says so. C again brings it back.
SNAPS=0
start_app "$BIN" --renderer software --window 600x600 --paused --seed 7 --screenshot-dir "$OUT"
key 9
wait_log "Galton board"
snap 11-galton-600
[[ -n "$(rect 11-galton-600 bins)" ]] || fail "no bins chart at 600x600 with the panel folded"
key c
snap 12-galton-600-panel
read -r bx by bw bh < <(rect 12-galton-600-panel box)
chart=$(rect 12-galton-600-panel bins)
[[ -z "$chart" ]] || fail "the bins chart ($chart) is laid out beside a box at $bx,$by ${bw}x$bh"
# (A HUD too narrow for its long lines says it in its short words: "Charts: no room".)
section 12-galton-600-panel HUD | grep -Eq "Charts folded away|Charts: no room" ||
    fail "the HUD does not say the charts are folded: $(section 12-galton-600-panel HUD)"
key c
snap 13-galton-600-folded-again
[[ -n "$(rect 13-galton-600-folded-again bins)" ]] || fail "the bins chart did not come back"
pass "600x600: the bins chart folds away while the panel is open, and says so"
kill "$APP_PID" 2>/dev/null || true
wait "$APP_PID" 2>/dev/null || true
APP_PID=""
echo "PASS"
