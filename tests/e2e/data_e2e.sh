#!/usr/bin/env bash
# End-to-end test of data out: the real program in a virtual X display (Xvfb) on a two-ball
# scene, driven with real X input (xdotool); the CSV files it exports are parsed, and the text it
# copies is read back from the X clipboard (xclip).
#
#   tests/e2e/data_e2e.sh PATH/TO/particle-sandbox [OUTPUT_DIR]
#
#   1. X starts recording                      -> logged, the HUD says REC (F12's text)
#   2. Space, about 1.5 s, Space; X stops       -> logged with the samples and collisions
#   3. the Data section's Export collisions     -> collisions.csv: one pair, 2 -> -2.5 m/s and
#                                                  -1 -> 0.5 m/s, impulse -4.5 N s (1-D textbook)
#   4. Export trajectories                      -> t = 0 rows at x = 3 and 6 m, times increasing
#   5. a typed name, Export values              -> "lesson.csv" with both balls, signed vx
#   6. Copy values                              -> the clipboard holds the same, tab-separated
#   7. Export time series                       -> starts at t = 0, the kinetic energy 3.5 J in
#                                                  every row (e = 1)
#   8. Esc                                      -> exits
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/harness.sh"
e2e_begin data "$@"
rm -rf "$OUT/exports"
mkdir -p "$OUT/exports"

# 1 kg at 2 m/s from x = 3 m and 3 kg at -1 m/s from x = 6 m, no walls, exact mode: they touch
# at t = 2/3 s and leave at -2.5 and 0.5 m/s.
SCENE="$OUT/two-balls.json"
cat >"$SCENE" <<'EOF'
{"version": 1, "name": "Two balls",
 "world": {"width": 10, "height": 10, "walls": false, "restitution": 1},
 "solver": {"dt": 0.01, "mode": "exact"},
 "particles": [
   {"x": 3, "y": 5, "vx": 2, "vy": 0, "mass": 1, "radius": 0.5},
   {"x": 6, "y": 5, "vx": -1, "vy": 0, "mass": 3, "radius": 0.5}]}
EOF

start_xvfb "$OUT/xvfb.log" 1100x900x24 || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy
LOG="$OUT/stdout.log"
start_app "$BIN" "$SCENE" --renderer software --window 1000x800 --paused --log-controls \
    --screenshot-dir "$OUT/exports"
wait_log "\[I\] Control section Data at"
pass "window at $WX,$WY size ${WIDTH}x$HEIGHT"

# --- 1. recording, and its mark on screen ----------------------------------------------------
key x
wait_log "Recording all 2 particles every 1 step"
snap 1-recording
grep -q "REC (X stops)" "$OUT/1-recording.txt" || fail "the HUD does not say REC: $(head -3 "$OUT/1-recording.txt")"
pass "X records, the HUD says: $(grep -m1 -o 'Time.*REC (X stops)' "$OUT/1-recording.txt")"

# --- 2. run through the collision --------------------------------------------------------------
key space
sleep 1.5
key space
wait_log "Paused"
key x
wait_log "Recording stopped: [0-9]+ samples, 1 collision"
pass "$(grep 'Recording stopped' "$LOG" | tail -1 | sed -E 's/^\[I\] //')"

# --- 3. the collision log (y up, the default: the y columns say so) ------------------------------------------------------------------------
# Room for the Data section: fold the sections above it.
for s in Physics Show Readouts; do click "section $s"; done
click "section Data"
wait_log "\[I\] Control Export collisions at"
click "Export collisions"
wait_log "Exported 1 row of collisions to $OUT/exports/collisions.csv"
C="$OUT/exports/collisions.csv"
head -1 "$C" | grep -q '^time_s,particle,with,other,vx_before_m_per_s,vy_up_before_m_per_s,vx_after_m_per_s,vy_up_after_m_per_s,other_vx_before_m_per_s,other_vy_up_before_m_per_s,other_vx_after_m_per_s,other_vy_up_after_m_per_s,impulse_x_N_s,impulse_y_up_N_s$' ||
    fail "collisions.csv header: $(head -1 "$C")"
# Seen from the 1 kg ball (particle 1), whichever the row names first.
awk -F, 'NR == 2 {
    if ($3 != "particle") exit 1
    if ($2 == 1) { u = $5; v = $7; ou = $9; ov = $11; j = $13 } else { u = $9; v = $11; ou = $5; ov = $7; j = -$13 }
    ok = (u == 2 && v == -2.5 && ou == -1 && ov == 0.5 && j == -4.5 && $1 > 0.666 && $1 < 0.668)
    exit !ok }' "$C" || fail "the collision is not the textbook one: $(sed -n 2p "$C")"
pass "collisions.csv: $(sed -n 2p "$C")"

# --- 4. trajectories ---------------------------------------------------------------------------
click "Export trajectories"
wait_log "Exported [0-9]+ rows of trajectories to $OUT/exports/trajectories.csv"
T="$OUT/exports/trajectories.csv"
head -1 "$T" | grep -q '^time_s,particle,x_m,y_up_m,vx_m_per_s,vy_up_m_per_s$' || fail "trajectories.csv header: $(head -1 "$T")"
sed -n 2,3p "$T" | tr '\n' ' ' | grep -q '^0,1,3,5,2,0 0,2,6,5,-1,0 $' || fail "the first rows: $(sed -n 2,3p "$T")"
awk -F, 'NR > 1 { if ($1 < last) exit 1; last = $1; if ($1 > 1 && $2 == 1 && $5 != -2.5) exit 1 }' "$T" ||
    fail "times out of order, or particle 1 not at -2.5 m/s after the collision"
pass "trajectories.csv: $(($(wc -l <"$T") - 1)) rows up to t = $(tail -1 "$T" | cut -d, -f1) s"

# --- 5. a typed name -----------------------------------------------------------------------------
click "export name"
xdotool type --delay 30 "lesson"
sleep 0.3
click "Export values"
wait_log "Exported 2 rows of values to $OUT/exports/lesson.csv"
V="$OUT/exports/lesson.csv"
head -1 "$V" | grep -q '^particle,x_m,y_up_m,vx_m_per_s,vy_up_m_per_s,px_kg_m_per_s,py_up_kg_m_per_s,kinetic_energy_J,mass_kg,radius_m$' ||
    fail "lesson.csv header: $(head -1 "$V")"
awk -F, 'NR == 2 && !($1 == 1 && $4 == -2.5 && $6 == -2.5 && $9 == 1) { exit 1 }
         NR == 3 && !($1 == 2 && $4 == 0.5 && $6 == 1.5 && $9 == 3) { exit 1 }' "$V" ||
    fail "lesson.csv values: $(cat "$V")"
pass "lesson.csv: $(sed -n 2p "$V")"

# --- 6. copy ---------------------------------------------------------------------------------------
click "Copy values"
wait_log "Copied 2 rows of values to the clipboard"
xclip -o -selection clipboard >"$OUT/clipboard.txt" 2>"$OUT/xclip.err" || fail "xclip: $(cat "$OUT/xclip.err")"
tr '\t' ',' <"$OUT/clipboard.txt" | diff -q - "$V" >/dev/null ||
    fail "the clipboard is not the values table, tab-separated: $(head -2 "$OUT/clipboard.txt")"
grep -q $'\t' "$OUT/clipboard.txt" || fail "the clipboard has no tabs"
shot 6-data
pass "the clipboard holds the values, tab-separated"

# --- 7. the time series --------------------------------------------------------------------------
click "Export time series"
wait_log "Exported [0-9]+ rows of time series to $OUT/exports/lesson-2.csv"
S="$OUT/exports/lesson-2.csv"
head -1 "$S" | grep -q '^time_s,kinetic_energy_J,' || fail "time series header: $(head -1 "$S")"
awk -F, 'NR == 2 && $1 != 0 { exit 1 } NR > 1 && ($2 < 3.4999999 || $2 > 3.5000001) { exit 1 }' "$S" ||
    fail "the time series does not start at 0 with 3.5 J throughout: $(sed -n 2,4p "$S")"
pass "time series: $(($(wc -l <"$S") - 1)) rows from t = 0, kinetic energy 3.5 J throughout"

# --- 8. leave ------------------------------------------------------------------------------------
# Nothing unsaved: Esc asks whether to quit, Enter quits.
quit_by_esc
wait_exit
if kill -0 "$APP_PID" 2>/dev/null; then fail "Esc, Enter did not quit"; fi
wait "$APP_PID" && status=0 || status=$?
APP_PID=""
((status == 0)) || fail "exit status $status"
pass "Esc quits with status 0"
