#!/usr/bin/env bash
# End-to-end test of the control panel: the real program in a virtual X display (Xvfb), its
# panel's controls clicked and dragged with real X input (xdotool), the effects checked in the
# log, in a saved scene and in screenshots. The program runs with --log-controls, which logs
# where each control is ("[I] Control NAME at X Y", window points), so the script finds controls
# by name, not by fixed coordinates.
#
#   tests/e2e/panel_e2e.sh PATH/TO/particle-sandbox [OUTPUT_DIR]
#
#   1. the box is fitted beside the panel, never under it       (log: box top-left x >= 310)
#   2. clicks Walls, Gravity, Substeps                          -> logged; the HUD unchanged
#   3. drags the Restitution slider to its left end             -> one log line, e = 0 in the save
#   4. chooses the Launch tool, unticks "auto" radius, types     -> a new particle of 2.5 kg and
#      mass 2.5 and radius 0.2, launches with a drag                0.2 m
#   5. opens the Scene section, types a path, clicks Save        -> the full path logged; the file
#                                                                   holds the launched 2.5 kg,
#                                                                   0.2 m particle, walls off,
#                                                                   gravity 9.81, e = 0, substep
#   5b. turns the wheel over the preset list, past its end      -> no zoom of the view
#   6. clicks Play/Pause twice, Step                             -> time moves; Restart: the set-up
#   6b. Tab three times, Space, Space                            -> time starts and stops (Play),
#                                                                  no tooltip (the pointer still)
#   7. folds the panel (<<) and opens it again (>>)              -> the box refits each time
#   7b. Ctrl+N, xdotool type "10", Tab, "4", Tab, "0", Enter     -> a 10 m x 4 m box (the "4"
#                                                                   went into the width: 104)
#   7c. types in the description, Ctrl+S in the field, Enter     -> saved with the description
#   8. Esc                                                       -> exits (saved: nothing unsaved)
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/harness.sh"
e2e_begin panel "$@"

start_xvfb "$OUT/xvfb.log" 1100x900x24 || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy

LOG="$OUT/stdout.log"
start_app "$BIN" --renderer software --window 1000x800 --paused --seed 7 --log-controls \
    --save-to "$OUT/saved.json" --screenshot-dir "$OUT"
pass "window at $WX,$WY size ${WIDTH}x$HEIGHT"

box_left() { grep "\[I\] View: zoom" "$LOG" | tail -1 |
    sed -E 's/.*box top-left at \[([-0-9.]+), ([-0-9.]+)\].*/\1/'; }

wait_log "\[I\] Control Walls at"
# --- 1. the box beside the panel ---------------------------------------------------------
left=$(box_left)
awk -v l="$left" 'BEGIN { exit !(l >= 310) }' || fail "the box starts at x = $left, under the panel"
shot 1-panel
pass "box fitted beside the panel (top-left x = $left px)"

# --- 2. checkboxes and a mode button ------------------------------------------------------
click Walls
wait_log "Walls off"
click Gravity
wait_log "Gravity \[0, -9.81\] m/s²"  # down, y counting up
click "mode Substeps"
wait_log "Mode: substep x4"
pass "Walls, Gravity and Substeps clicked: $(grep -c 'Walls off\|Gravity \[0\|Mode: substep' "$LOG") effects logged"

# --- 3. a slider drag: one action ----------------------------------------------------------
read -r rx ry < <(ctl Restitution)
xdotool mousemove --sync "$rx" "$ry" sleep 0.1 mousedown 1 sleep 0.05 \
    mousemove $((rx - 40)) "$ry" sleep 0.05 mousemove $((rx - 120)) "$ry" sleep 0.05 \
    mousemove $((rx - 150)) "$ry" sleep 0.1 mouseup 1
sleep 0.3
(($(grep -c "\[I\] Restitution " "$LOG") == 1)) || fail "a slider drag logged $(grep -c "\[I\] Restitution " "$LOG") changes, not one"
pass "restitution slider dragged: $(grep "\[I\] Restitution " "$LOG")"

# --- 4. launch with a chosen mass and radius -------------------------------------------------
# The Tools section is closed at first; Physics and Show are folded to make room for it.
click "section Physics"
click "section Show"
click "section Tools"
click "tool Launch"
wait_log "Left mouse: launch"
click "auto radius"
wait_log "New particles: 12 kg, radius [0-9.]+ m$"  # the default scene's typical particle
type_into "launch mass" 2.5
wait_log "New particles: 2.5 kg"
type_into "launch radius" 0.2
wait_log "New particles: 2.5 kg, radius 0.2 m$"
grep -q "Control launch mass" "$LOG" || fail "no mass field"
# From the centre of the box (a particle or not: the Launch tool always launches).
view=$(grep "\[I\] View: zoom" "$LOG" | tail -1)
read_view "$view"
lx=$(awk -v z="$ZOOM" -v o="$WX" -v b="$BX" 'BEGIN { printf "%d", o + b + 1.0 * z }')
ly=$(awk -v z="$ZOOM" -v o="$WY" -v b="$BY" 'BEGIN { printf "%d", o + b + 6.0 * z }')
xdotool mousemove --sync "$lx" "$ly" sleep 0.3
shot 4-preview
chain=(mousedown 1 sleep 0.1)
for i in 1 2 3 4 5 6; do chain+=(mousemove $((lx + 8 * i)) $((ly - 8 * i)) sleep 0.015); done
shot 4-dragging
xdotool "${chain[@]}" mouseup 1
wait_log "Launched particle"
pass "launched: $(grep 'Launched particle' "$LOG" | tail -1)"

# --- 5. save to a typed path ------------------------------------------------------------------
# Save As: a dialog with the proposed name selected; typing replaces it, Enter saves.
click "section Scene"
click "Save As"
wait_log "Save as: type a file name"
sleep 0.3
shot 5-save-as-dialog
xdotool type --delay 30 "$OUT/panel-save.json"
sleep 0.3
key Return
wait_log "Saved 7 particles to $OUT/panel-save.json"
S="$OUT/panel-save.json"
[[ -s "$S" ]] || fail "no file at $S"
grep -q '"mass": 2.5, "radius": 0.2' "$S" || fail "the launched 2.5 kg, 0.2 m particle is not in the save: $(grep mass "$S" | tail -2)"
grep -q '"walls": false' "$S" || fail "walls not off in the save"
grep -q '"gravity": \[0.0, 9.81\]' "$S" || fail "gravity not 9.81 in the save: $(grep gravity "$S")"
grep -q '"restitution": 0.0' "$S" || fail "restitution not 0 in the save: $(grep restitution "$S")"
grep -q '"mode": "substep", "dt": [0-9.e-]*, "substeps": 4' "$S" || fail "mode not substep x4 in the save: $(grep solver "$S")"
shot 5-saved
pass "saved with the panel: $(grep -m1 'Saved 7' "$LOG")"

# --- 5b. the wheel over the preset list scrolls it, never the view ---------------------------
# The pointer comes from the box and turns the wheel at once, well past the list's end.
first=$(grep -m1 -F "[I] Control preset " "$LOG" | sed -E 's/.*Control (preset .*) at [0-9]+ [0-9]+$/\1/')
read -r lx ly < <(ctl "$first")
zooms=$(grep -c "\] Zoom " "$LOG" || true)
xdotool mousemove --sync $((WX + 700)) $((WY + 400)) sleep 0.3 mousemove "$lx" "$ly" \
    click --repeat 25 --delay 15 5
sleep 0.5
xdotool click --repeat 10 --delay 15 4
sleep 0.5
after=$(grep -c "\] Zoom " "$LOG" || true)
((after == zooms)) || fail "the wheel over the preset list zoomed the view: $(grep '\] Zoom ' "$LOG" | tail -1)"
shot 5b-presets-wheel
pass "35 wheel clicks over the preset list, none reached the view"

# --- 6. time controls ------------------------------------------------------------------------
click "Play/Pause"
wait_log "Resumed"
sleep 0.5
click "Play/Pause"
wait_log "\] Paused"
click Step
click Restart
# The launch (an edit) before Play made the set-up: Restart keeps the launched particle.
wait_log "Restarted: back to the set-up as Play last started it \(7 particles"
pass "Play, Pause, Step and Restart"

# --- 6b. the keyboard alone: Tab to Play, Space, Space -------------------------------------------
# Tab gives the panel the keys; three Tabs (fold button, the Time section, Play) reach Play, each
# a quick tap (xdotool presses and releases between two frames). Space starts time; the cursor
# stays on the button, now Pause, and a second Space stops it; Esc gives the keys back.
# The pointer rests in the box meanwhile: a tooltip shows only under a real hover, never because
# the keyboard is on a control (Play's tooltip stood at the pointer, over the values table).
xdotool mousemove --sync $((WX + WIDTH - 60)) $((WY + HEIGHT / 2))
sleep 0.3
lines=$(wc -l <"$LOG")
resumed=$(grep -c "Resumed" "$LOG")
paused=$(grep -c "\] Paused" "$LOG")
key Tab Tab Tab
sleep 0.8  # past the tooltips' half-second delay, on Play
key space
wait_count "Resumed" $((resumed + 1))
sleep 0.8
key space
wait_count "\] Paused" $((paused + 1))
sleep 0.8
shot 6b-keyboard-pause
keyed=$(tail -n +$((lines + 1)) "$LOG" | grep "^\[I\] Tooltip " | grep -v "Tooltip none$" || true)
[[ -z "$keyed" ]] || fail "a tooltip with the pointer still, from the keyboard alone: $keyed"
key Escape
sleep 0.3
kill -0 "$APP_PID" 2>/dev/null || fail "Esc with the panel's cursor shown quit the program"
pass "Tab, Tab, Tab, Space, Space: started and stopped time from the keyboard"

# --- 7. fold and open ---------------------------------------------------------------------------
before=$(box_left)
click "fold panel"
sleep 0.3
folded=$(box_left)
awk -v a="$folded" -v b="$before" 'BEGIN { exit !(a < b) }' || fail "folding did not give the box room ($before -> $folded)"
shot 7-folded
click "open panel"
sleep 0.3
opened=$(box_left)
awk -v a="$opened" 'BEGIN { exit !(a >= 310) }' || fail "opened again, the box starts at $opened"
pass "fold and open: box left edge $before -> $folded -> $opened px"

# --- 7b. text typed quicker than a frame, with Tab between, reaches the fields in order ---------
key ctrl+n
wait_log "Control dialog width at"
sleep 0.3
xdotool type --delay 12 "10"
xdotool key Tab
xdotool type --delay 12 "4"
xdotool key Tab
xdotool type --delay 12 "0"
xdotool key Return
wait_log "New scene: an empty box 10(\.0+)? m x 4(\.0+)? m, no gravity"
pass "typed 10, Tab, 4, Tab, 0: $(grep -o 'New scene: an empty box [^,]*' "$LOG" | tail -1)"

# --- 7c. Ctrl+S while typing the description keeps it, then saves ---------------------------
grep -qF "[I] Control description at " "$LOG" || click "section Scene"
click description
xdotool type --delay 20 "Typed in e2e"
xdotool key ctrl+s  # still in the field: the description is kept first, then Save As asks
wait_log "Save as: type a file name"
sleep 0.3
xdotool key Return
wait_log "Saved 0 particles to /.*\.json"
saved=$(grep -o "Saved 0 particles to /.*\.json" "$LOG" | tail -1 | sed 's/Saved 0 particles to //')
grep -q '"description": ".*Typed in e2e"' "$saved" ||
    fail "Ctrl+S in the field did not keep the description: $(grep description "$saved")"
pass "Ctrl+S in the description's field: kept, then saved to $saved"

# --- 8. leaving -------------------------------------------------------------------------------
xdotool mousemove $((WX + 700)) $((WY + 400))
# Saved in step 5 and only run since: nothing unsaved, Esc asks whether to quit and Enter quits
# (the window may be gone before xdotool sends the key's release: quit_with expects that).
quit_by_esc
wait_exit
kill -0 "$APP_PID" 2>/dev/null && fail "still running after Esc, Enter"
APP_PID=""
pass "Esc asked, Enter quit"
echo "PASS: panel e2e ($OUT)"
