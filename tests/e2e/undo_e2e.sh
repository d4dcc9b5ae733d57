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

BIN=${1:?usage: undo_e2e.sh PATH/TO/particle-sandbox [OUTPUT_DIR]}
OUT=${2:-$(pwd)/undo-e2e-out}
HERE=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$OUT"
rm -f "$OUT"/*.png "$OUT"/*.log "$OUT"/*.json

fail() {
    echo "FAIL: $*" >&2
    for f in stderr.log xvfb.log; do
        [[ -s "$OUT/$f" ]] && { echo "--- $f:" >&2; tail -n 20 "$OUT/$f" >&2; }
    done
    echo "--- stdout.log:" >&2
    tail -n 30 "$OUT/stdout.log" >&2 || true
    echo "(log, saves and screenshots in $OUT)" >&2
    exit 1
}
source "$HERE/harness.sh"

start_xvfb "$OUT/xvfb.log" || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy
LOG="$OUT/stdout.log"
"$BIN" --renderer software --window 600x600 --paused --seed 7 --save-to "$OUT/save.json" \
    --screenshot-dir "$OUT" >"$LOG" 2>"$OUT/stderr.log" &
APP_PID=$!
WID=$(timeout 20 xdotool search --sync --onlyvisible --pid "$APP_PID" --name "Particle Sandbox" |
    head -1) || fail "no window within 20 s"
eval "$(xdotool getwindowgeometry --shell "$WID")"  # X, Y, WIDTH, HEIGHT
WX=$X
WY=$Y
xdotool windowfocus --sync "$WID" 2>/dev/null || true

wait_log() {  # wait_log REGEX [COUNT]: until COUNT (default 1) lines match
    local deadline=$((SECONDS + 8))
    while (($(grep -Ec "$1" "$LOG" || true) < ${2:-1})); do
        ((SECONDS < deadline)) || fail "timed out waiting for log line /$1/ (${2:-1} times)"
        sleep 0.05
    done
}
wait_title() {
    local deadline=$((SECONDS + 8))
    until xdotool getwindowname "$WID" | grep -Eq "$1"; do
        ((SECONDS < deadline)) || fail "title '$(xdotool getwindowname "$WID")' never matched /$1/"
        sleep 0.05
    done
}
key() { xdotool key --window "$WID" "$@"; sleep 0.15; }
shot() { sleep 0.3; import -window root "$OUT/$1.png"; }
saves=0
# save NAME: Ctrl+S, then the file it wrote copied to OUT/NAME.json
save() {
    key ctrl+s
    saves=$((saves + 1))
    wait_log "Saved [0-9]+ particles? to " "$saves"
    local file
    file=$(grep -E "Saved [0-9]+ particles? to " "$LOG" | tail -1 | sed -E 's/.* to (.*)$/\1/')
    [[ -s "$file" ]] || fail "the save '$file' is missing"
    cp "$file" "$OUT/$1.json"
}
# The particles of a saved scene, one line each (positions, velocities, mass, radius, colour).
particles() { grep '"mass":' "$OUT/$1.json"; }
same() { diff <(particles "$1") <(particles "$2") >/dev/null; }
wait_log "\[I\] View: zoom"
read -r ZOOM BX BY < <(grep "\[I\] View: zoom" "$LOG" | head -1 |
    sed -E 's/.*zoom ([0-9.]+) px\/m, box top-left at \[([-0-9.]+), ([-0-9.]+)\].*/\1 \2 \3/')
sx() { awk -v w="$1" -v z="$ZOOM" -v o="$WX" -v b="$BX" 'BEGIN { printf "%d", o + b + w * z + 0.5 }'; }
sy() { awk -v w="$1" -v z="$ZOOM" -v o="$WY" -v b="$BY" 'BEGIN { printf "%d", o + b + w * z + 0.5 }'; }
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
(($(particles D | wc -l) == 7)) && (($(grep -c '"mass": 10.0,' "$OUT/D.json") == 1)) ||
    fail "after the redo the save does not hold the launched 10 kg particle"
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
