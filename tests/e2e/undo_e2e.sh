#!/usr/bin/env bash
# End-to-end test of undo and step back: the real program in a virtual X display (Xvfb),
# driven with real X input (xdotool), checked through the scenes it saves (Ctrl+S), its log,
# its window title and screenshots.
#
#   tests/e2e/undo_e2e.sh PATH/TO/particle-sandbox [OUTPUT_DIR]
#
# On the built-in scene, paused:
#   1. saves (A); grabs a particle and deletes it while holding; Ctrl+Z     -> saved B = A
#   2. launches a particle on empty space; Ctrl+Z; saves (C)                 -> C = A
#      Ctrl+Shift+Z; saves (D)                                                -> D = A + the launch
#   3. in the discrete and the exact mode: runs, pauses, single-steps 4 times, saves (E),
#      steps 6 more, Shift+Left 6 times, saves (F)                             -> F = E, bit for bit
#      (a screenshot shows the HUD's "Viewing ... s back"), Shift+Right      -> one frame on
#   4. Space from the past                                                    -> carries on
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/harness.sh"
e2e_begin undo "$@"

start_xvfb "$OUT/xvfb.log" || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy
LOG="$OUT/stdout.log"
start_app "$BIN" --renderer software --window 600x600 --paused --seed 7 \
    --save-to "$OUT/save.json" --screenshot-dir "$OUT"

saves=0
# save NAME: Ctrl+S, then the file it wrote copied to OUT/NAME.json
save() {
    key ctrl+s
    # The first save asks for a name (the scene has no file yet): Enter takes --save-to's.
    if ((saves == 0)); then
        wait_log "Save as: type a file name"
        press_until Return "Saved [0-9]+ particles? to "
    fi
    saves=$((saves + 1))
    wait_count "Saved [0-9]+ particles? to " "$saves" 8
    local file
    file=$(grep -E "Saved [0-9]+ particles? to " "$LOG" | tail -1 | sed -E 's/.* to (.*)$/\1/')
    [[ -s "$file" ]] || fail "the save '$file' is missing"
    cp "$file" "$OUT/$1.json"
}
# The particles of a saved scene, one line each (positions, velocities, mass, radius, colour).
particles() { grep '"mass":' "$OUT/$1.json" | sed 's/},$/}/'; }  # without the list's commas
same() { diff <(particles "$1") <(particles "$2") >/dev/null; }

wait_title "6 particles - PAUSED"

# --- 1. undo a deletion ---------------------------------------------------------------------
save A
drag "$(sx 2.5)" "$(sy 2.6)" 3 3 3 "key --window $WID Delete sleep 0.2"
wait_title "5 particles - PAUSED"
key ctrl+z
wait_log "Undone: delete particle"
wait_title "6 particles - PAUSED"
save B
same A B || fail "after undoing the deletion the scene differs: $(diff <(particles A) <(particles B))"
pass "Ctrl+Z undid a deletion: the saved scene is the one before it, particle for particle"

# --- 2. undo and redo a launch ------------------------------------------------------------------
drag "$(sx 1.0)" "$(sy 6.2)" 10 -10 8 "sleep 0.2"
wait_log "Launched particle at"
wait_title "7 particles - PAUSED"
key ctrl+z
wait_log "Undone: launch particle"
wait_title "6 particles - PAUSED"
save C
same A C || fail "after undoing the launch the scene differs"
key ctrl+shift+z
wait_log "Redone: launch particle"
wait_title "7 particles - PAUSED"
save D
added=$(diff <(particles A) <(particles D) | grep -c '^>' || true)
removed=$(diff <(particles A) <(particles D) | grep -c '^<' || true)
((added == 1 && removed == 0)) ||
    fail "after the redo the save is not the first one plus the launched particle ($added, $removed)"
pass "Ctrl+Z undid a launch (save = the scene before it); Ctrl+Shift+Z brought it back"
shot 1-redone

# --- 3. step back, in the discrete and the exact mode ------------------------------------------
step_back_check() {  # step_back_check MODE-NAME
    key space  # run half a second: a history with collisions and keyframes
    sleep 0.5
    key space
    wait_title "PAUSED"
    for _ in 1 2 3 4; do key n; done
    save "E-$1"
    for _ in 1 2 3 4 5 6; do key n; done
    save "G-$1"
    same "E-$1" "G-$1" && fail "$1: six steps changed nothing (nothing moves?)"
    for _ in 1 2 3 4 5 6; do key shift+Left; done
    save "F-$1"
    same "E-$1" "F-$1" ||
        fail "$1: six frames back is not the state saved then: $(diff <(particles "E-$1") <(particles "F-$1") | head -4)"
    shot "2-past-$1"
    key shift+Right
    save "H-$1"
    same "E-$1" "H-$1" && fail "$1: Shift+Right did not move on"
    pass "$1: six Shift+Left after six steps give the saved state bit for bit; Shift+Right moves on"
}
step_back_check discrete
key t
wait_log "\[I\] Mode: substep"
key t
wait_log "\[I\] Mode: exact$"
step_back_check exact

# --- 4. carry on from the past -----------------------------------------------------------------
key shift+Left
key space
wait_log "Resumed from [0-9.]+ s: the later frames are forgotten"
sleep 0.3
key space
pass "Space in the past carries on from there: $(grep 'Resumed from' "$LOG" | tail -1)"
shot 3-carried-on

kill "$APP_PID" 2>/dev/null || true
wait "$APP_PID" 2>/dev/null || true
APP_PID=""
echo "undo e2e: all passed (output in $OUT)"
