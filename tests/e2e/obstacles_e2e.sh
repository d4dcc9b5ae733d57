#!/usr/bin/env bash
# End-to-end test of the obstacle tools: the real program in a virtual X display (Xvfb), driven
# with real X input (xdotool); panel controls found by name (--log-controls).
#
#   tests/e2e/obstacles_e2e.sh PATH/TO/particle-sandbox [OUTPUT_DIR]
#
#   1. chooses the Wall tool in the panel, drags in the box      -> a wall logged, drawn (grey);
#                                                                   while drawn, its slope shown
#   2. chooses the Peg tool (pressed as the pointer arrives),    -> the tool, no refusal from
#      clicks in the box                                            the world; a peg logged
#   3. Ctrl+S                                                    -> the saved scene has the wall
#                                                                   and the peg where they were
#                                                                   drawn (within a pixel)
#   4. Ctrl+Z, Ctrl+S                                            -> the peg is gone from the save
#   5. the Select tool, a click on the wall, a drag of it,       -> the wall is selected, moved,
#      Delete, Ctrl+Z                                                removed, and comes back
#   6. Esc, Esc                                                  -> asks (the move is unsaved), exits
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/harness.sh"
e2e_begin obstacles "$@"

start_xvfb "$OUT/xvfb.log" 1100x900x24 || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy
LOG="$OUT/stdout.log"
start_app "$BIN" --renderer software --window 1000x800 --paused --seed 7 --log-controls \
    --save-to "$OUT/saved.json" --screenshot-dir "$OUT"
pass "window at $WX,$WY size ${WIDTH}x$HEIGHT, zoom $ZOOM px/m"
wait_log "\[I\] Control section Tools at"

# World metres of a window point: the inverse of sx / sy (window, not root, pixels).
wx() { awk -v p="$1" -v z="$ZOOM" -v b="$BX" 'BEGIN { printf "%.6f", (p - b) / z }'; }
wy() { awk -v p="$1" -v z="$ZOOM" -v b="$BY" 'BEGIN { printf "%.6f", (p - b) / z }'; }
# near A B: |A - B| within a pixel and a half (in metres).
near() { awk -v a="$1" -v b="$2" -v z="$ZOOM" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1.5 / z) }'; }
# The last saved file, from its log line.
saved() { grep -E "Saved [0-9]+ particles to " "$LOG" | tail -1 | sed -E 's/.* to (.*)$/\1/'; }
# count FILE TYPE: how many obstacles of TYPE ("peg", "segment") the scene FILE has (one a line);
# numbers FILE TYPE: the numbers of the first one's line.
count() { grep -cF "\"type\": \"$2\"" "$1" || true; }
numbers() {
    grep -F "\"type\": \"$2\"" "$1" | head -1 | grep -oE -- '-?[0-9][0-9.]*(e[-+]?[0-9]+)?' | tr '\n' ' '
    echo
}

# --- 1. a wall, dragged ------------------------------------------------------------------------
click "section Physics"
click "section Show"
click "section Tools"
click "tool Wall"
wait_log "Left mouse: a drag draws a wall"
x0=$(sx 1.0)
y0=$(sy 5.0)
n=10
dx=$(awk -v z="$ZOOM" 'BEGIN { printf "%d", 0.3 * z }')
dy=$(awk -v z="$ZOOM" 'BEGIN { printf "%d", 0.05 * z }')
# Drawn slowly, with a screenshot of the preview while the button is down.
chain=(mousemove --sync "$x0" "$y0" sleep 0.2 mousedown 1 sleep 0.1)
for ((i = 1; i <= n; i++)); do chain+=(mousemove "$((x0 + i * dx))" "$((y0 + i * dy))" sleep 0.03); done
xdotool "${chain[@]}"
shot 1-wall-preview
# The Wall tool's protractor: the length and slope beside the wall being drawn.
snap 1-wall-angle
angle=$(section 1-wall-angle "Wall tool")
read -r deg < <(sed -E 's/^.*, ([0-9.]+)°$/\1/' <<<"$angle")
awk -v d="$deg" -v dx="$dx" -v dy="$dy" 'BEGIN {
    e = atan2(dy, dx) * 45 / atan2(1, 1); exit !(d > e - 0.3 && d < e + 0.3) }' ||
    fail "the wall being drawn reads '$angle', not its slope of atan($dy/$dx)"
xdotool mouseup 1
wait_log "Added obstacle 0: wall from"
# The ends as the window saw them (window pixels).
ax=$(wx $((x0 - WX)))
ay=$(wy $((y0 - WY)))
bx=$(wx $((x0 + n * dx - WX)))
by=$(wy $((y0 + n * dy - WY)))
shot 1-wall
pass "wall drawn: $(grep 'Added obstacle 0' "$LOG")"

# --- 2. a peg, clicked ---------------------------------------------------------------------------
# The Peg button pressed the moment the pointer arrives from the box (no frame in between): the
# click is the panel's, and the world's Wall tool never sees it.
read -r tx ty < <(ctl "tool Peg")
xdotool mousemove --sync "$(sx 3.0)" "$(sy 3.0)" sleep 0.3 mousemove "$tx" "$ty" click 1
wait_log "Left mouse: a click places a peg"
sleep 0.3
if grep -E "No (wall|peg) |Nothing placed" "$LOG"; then
    fail "a click on the Peg button reached the world"
fi
pass "one click on the Peg button chose the tool and nothing else"
px=$(sx 5.5)
py=$(sy 5.0)
xdotool mousemove --sync "$px" "$py" sleep 0.2 mousedown 1 sleep 0.05 mouseup 1
wait_log "Added obstacle 1: peg at"
cx=$(wx $((px - WX)))
cy=$(wy $((py - WY)))
shot 2-peg
pass "peg placed: $(grep 'Added obstacle 1' "$LOG")"

# --- 3. saved with the scene ------------------------------------------------------------------
xdotool mousemove $((WX + 900)) $((WY + 700))
key ctrl+s  # no file yet: Save As, proposing --save-to; Enter saves
wait_log "Save as: type a file name"
press_until Return "Saved 6 particles to .*saved.json"
S=$(saved)
[[ -s "$S" ]] || fail "no file at $S"
grep -q '"version": 2' "$S" || fail "a scene with obstacles is not version 2: $(grep version "$S")"
(($(count "$S" segment) == 1)) || fail "not one segment in the save: $(grep -F '"type"' "$S")"
(($(count "$S" peg) == 1)) || fail "not one peg in the save: $(grep -F '"type"' "$S")"
read -r sax say sbx sby thick < <(numbers "$S" segment)
near "$sax" "$ax" && near "$say" "$ay" && near "$sbx" "$bx" && near "$sby" "$by" ||
    fail "the wall is saved from [$sax, $say] to [$sbx, $sby], drawn from [$ax, $ay] to [$bx, $by]"
read -r spx spy radius < <(numbers "$S" peg)
near "$spx" "$cx" && near "$spy" "$cy" || fail "the peg is saved at [$spx, $spy], placed at [$cx, $cy]"
awk -v t="$thick" -v r="$radius" 'BEGIN { exit !(t > 0 && r > 0) }' || fail "sizes $thick, $radius"
pass "saved: wall [$sax, $say] - [$sbx, $sby] thickness $thick m, peg [$spx, $spy] radius $radius m"

# --- 4. undo the peg --------------------------------------------------------------------------------
key ctrl+z
wait_log "Undone: place peg"
key ctrl+s  # the scene belongs to saved.json now: written again
wait_count "Saved 6 particles to .*saved.json" 2
S2=$(saved)
(($(count "$S2" peg) == 0)) || fail "the peg undone is still saved in $S2"
(($(count "$S2" segment) == 1)) || fail "the wall is gone from $S2"
shot 4-undone
pass "Ctrl+Z removed the peg: $S2 has the wall only"

# --- 5. select the wall and delete it; undo ------------------------------------------------------
click "tool Select"
wait_log "Left mouse: select particles and obstacles"
mx=$(sx 2.5)
my=$(awk -v a="$y0" -v b="$((y0 + n * dy))" 'BEGIN { printf "%d", (a + b) / 2 }')
xdotool mousemove --sync "$mx" "$my" sleep 0.2 mousedown 1 sleep 0.05 mouseup 1
wait_log "Selected obstacle 0: wall"
shot 5-selected
# Dragged half a metre down with the Select tool: moved.
drag "$mx" "$my" 0 "$(awk -v z="$ZOOM" 'BEGIN { printf "%d", 0.05 * z }')" 10
wait_log "Moved obstacle 0: wall from"
shot 5-moved
key Delete
wait_log "Removed obstacle 0: wall"
shot 5-deleted
key ctrl+z
wait_log "Undone: remove wall"
pass "wall selected, moved ($(grep 'Moved obstacle 0' "$LOG" | sed 's/.*: wall/wall/')), deleted and brought back"

xdotool mousemove $((WX + 900)) $((WY + 700))
key Escape  # the move is unsaved: Esc asks in a dialog; D discards and quits
wait_log "Unsaved changes to .*: Save, Discard or Cancel"
quit_with d
kill -0 "$APP_PID" 2>/dev/null && fail "still running after Esc"
APP_PID=""
echo "PASS: obstacles e2e ($OUT)"
