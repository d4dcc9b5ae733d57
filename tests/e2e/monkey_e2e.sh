#!/usr/bin/env bash
# Random real input on the real window: the release program under Xvfb, driven by a seeded
# stream of X input (keys and chords, drags with either button, wheel turns, clicks and drags on
# the control panel's controls by name, text typed into whatever has the keyboard, window
# resizes), as a hand that does not know the program would. It fails on
#   - the program ending by a signal or with a non-zero status (an assertion, a crash),
#   - a sanitizer report or an uncaught exception in its standard error,
#   - a hang: the program not answering F12 (a screenshot, logged) within the probe's deadline,
#   - a saved scene that particle-sim cannot read back, or a settings file the program refuses.
# The program may quit on its own (Esc, the quit question answered): that is a user's action,
# and it is started again, on the settings it saved.
#
#   tests/e2e/monkey_e2e.sh PATH/TO/particle-sandbox PATH/TO/particle-sim [OUTPUT_DIR]
#
#   PSB_MONKEY_SEED=N      the stream of actions (default: from the clock; printed first)
#   PSB_MONKEY_SECONDS=S   how long to act (default 150)
#   PSB_MONKEY_SCENE=FILE  the scene opened (default the Galton board preset)
#
# Replaying a failure: the failing run prints its seed; the same seed gives the same actions in
# the same order (the program's own timing may still differ), and OUT/actions.log lists them,
# numbered, with the program's log beside them in OUT/stdout.log. See docs/testing.md.
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
source "$HERE/harness.sh"
SIM=${2:?usage: monkey_e2e.sh PATH/TO/particle-sandbox PATH/TO/particle-sim [OUTPUT_DIR]}
e2e_begin monkey "$1" "${3:-}"
SEED=${PSB_MONKEY_SEED:-$(date +%s)}
SECONDS_TO_ACT=${PSB_MONKEY_SECONDS:-150}
SCENE=${PSB_MONKEY_SCENE:-$ROOT/assets/scenes/09-galton-board.json}
echo "monkey: seed $SEED, ${SECONDS_TO_ACT} s (replay: PSB_MONKEY_SEED=$SEED)"
RANDOM=$SEED

WORK="$OUT/work"
rm -rf "$WORK" "$OUT/actions.log"
mkdir -p "$WORK"
LOG="$OUT/stdout.log"
: >"$LOG"
start_xvfb "$OUT/xvfb.log" 1400x1100x24 || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy

ACTIONS=0
STARTS=0
# A hang: F12 unanswered this long. A screenshot of the busiest state the monkey can reach (a
# dense pile in the exact mode, at the frame's event budget) takes about a second on a quiet
# machine; the deadline leaves room for a machine four times slower, and more.
PROBE_SECONDS=60

failed() {
    echo "monkey: failed at action $ACTIONS with seed $SEED" >&2
    echo "  replay: PSB_MONKEY_SEED=$SEED PSB_MONKEY_SECONDS=$SECONDS_TO_ACT $0 $BIN $SIM OUT" >&2
    echo "--- the last actions (OUT/actions.log):" >&2
    tail -n 15 "$OUT/actions.log" >&2 || true
    fail "$*"
}

check_stderr() {
    if grep -Eq "AddressSanitizer|LeakSanitizer|runtime error:|terminate called|Assertion .* failed" \
        "$OUT/stderr.log" 2>/dev/null; then
        failed "the program reported: $(grep -Em3 "AddressSanitizer|LeakSanitizer|runtime error:|terminate called|Assertion" "$OUT/stderr.log")"
    fi
}

launch() {
    STARTS=$((STARTS + 1))
    cat "$OUT/stderr.log" >>"$OUT/stderr-all.log" 2>/dev/null || true
    # Started in its own folder: every file the hand makes it write (saves, screenshots,
    # exports, videos) lands there.
    (cd "$WORK" && exec "$BIN" "$SCENE" --window 877x674 --seed "$SEED" --log-controls \
        --renderer software --screenshot-dir "$WORK" --save-to "$WORK/saved.json") \
        >>"$LOG" 2>"$OUT/stderr.log" &
    APP_PID=$!
    WID=$(timeout 60 xdotool search --sync --onlyvisible --pid "$APP_PID" --name "Particle Sandbox" |
        head -1) || failed "no window within 60 s (start $STARTS)"
    eval "$(xdotool getwindowgeometry --shell "$WID")"
    WX=$X
    WY=$Y
    xdotool windowfocus --sync "$WID" 2>/dev/null || true
    if grep -Eq "\[W\] .*[Ss]ettings" "$LOG"; then
        failed "the program refused the settings it saved itself: $(grep -E "\[W\] .*[Ss]ettings" "$LOG" | tail -1)"
    fi
}

# The program ended: by the hand's own quit (status 0) it starts again; otherwise a failure.
ended() {
    local status=0
    wait "$APP_PID" || status=$?
    APP_PID=""
    check_stderr
    if ((status != 0)); then
        ((status > 128)) && failed "the program was killed by signal $((status - 128))"
        failed "the program exited with status $status"
    fi
    echo "$ACTIONS quit (status 0): started again" >>"$OUT/actions.log"
    launch
}

alive() {
    kill -0 "$APP_PID" 2>/dev/null && return 0
    ended
    return 1
}

# probe: F12 must be answered (a screenshot saved, or a screenshot failure said) in time.
probe() {
    local before deadline
    before=$(grep -Ec "Saved screenshot|Screenshot failed" "$LOG" || true)
    deadline=$((SECONDS + PROBE_SECONDS))
    xdotool key --window "$WID" F12 2>/dev/null || true
    while (($(grep -Ec "Saved screenshot|Screenshot failed" "$LOG" || true) <= before)); do
        kill -0 "$APP_PID" 2>/dev/null || { ended; return; }
        ((SECONDS < deadline)) || failed "no answer to F12 within $PROBE_SECONDS s: a hang"
        sleep 0.2
    done
    rm -f "$WORK"/screenshot-*.png "$WORK"/screenshot-*.txt
}

pick() { # pick WORD...: one of the words
    local a=("$@")
    echo "${a[RANDOM % ${#a[@]}]}"
}
# Keys as a hand finds them: the sandbox's letters and digits, with Shift and Ctrl, the
# arrows, paging, Tab, Esc, Enter, Backspace, Delete and F-keys. F12 is the probe's.
KEYS=(space n s a v k d i j q g e t o l m f r h p c x u b w z y 0 1 2 3 4 5 6 7 8 9
    comma period bracketleft bracketright Left Right Up Down Prior Next Tab Escape Return
    BackSpace Delete F1 F3 plus minus equal)
MODS=("" "" "" "shift+" "ctrl+" "ctrl+shift+")

act() {
    local x y n kind w h chain k
    ACTIONS=$((ACTIONS + 1))
    eval "$(xdotool getwindowgeometry --shell "$WID" 2>/dev/null)" || return 0
    WX=$X
    WY=$Y
    w=$WIDTH
    h=$HEIGHT
    kind=$((RANDOM % 100))
    if ((kind < 30)); then
        k="$(pick "${MODS[@]}")$(pick "${KEYS[@]}")"
        # Ctrl+R records a video (heavy, and tested elsewhere): rarely.
        [[ $k == ctrl+r && $((RANDOM % 5)) -ne 0 ]] && k=r
        echo "$ACTIONS key $k" >>"$OUT/actions.log"
        xdotool key --window "$WID" "$k" 2>/dev/null || true
    elif ((kind < 50)); then
        # A drag with the left (fling, launch, a slider) or right button (pan).
        local b=$(((RANDOM % 4 == 0) ? 3 : 1))
        x=$((WX + RANDOM % w))
        y=$((WY + RANDOM % h))
        n=$((2 + RANDOM % 12))
        local dx=$((RANDOM % 61 - 30)) dy=$((RANDOM % 61 - 30))
        echo "$ACTIONS drag button $b from $((x - WX)) $((y - WY)) by $dx $dy x $n" >>"$OUT/actions.log"
        chain=(mousemove "$x" "$y" mousedown "$b")
        for ((i = 1; i <= n; i++)); do chain+=(mousemove $((x + i * dx)) $((y + i * dy)) sleep 0.01); done
        ((RANDOM % 6 == 0)) && chain+=(sleep 0.2)  # held still: let go at rest
        chain+=(mouseup "$b")
        xdotool "${chain[@]}" 2>/dev/null || true
    elif ((kind < 60)); then
        x=$((WX + RANDOM % w))
        y=$((WY + RANDOM % h))
        local wheel=$((4 + RANDOM % 2)) clicks=$((1 + RANDOM % 4))
        echo "$ACTIONS wheel $wheel x $clicks at $((x - WX)) $((y - WY))" >>"$OUT/actions.log"
        xdotool mousemove "$x" "$y" click --repeat "$clicks" "$wheel" 2>/dev/null || true
    elif ((kind < 85)); then
        # A control of the panel by name, from its latest place in the log: a click, or a
        # short drag (a slider).
        local line name cx cy controls=()
        mapfile -t controls < <(grep -E "\[I\] Control .* at [0-9-]+ [0-9-]+$" "$LOG" | tail -n 200)
        ((${#controls[@]} > 0)) || return 0
        line=${controls[RANDOM % ${#controls[@]}]}
        name=$(sed -E 's/.*\[I\] Control (.*) at [0-9-]+ [0-9-]+$/\1/' <<<"$line")
        read -r cx cy < <(sed -E 's/.* at ([0-9-]+) ([0-9-]+)$/\1 \2/' <<<"$line")
        x=$((WX + cx))
        y=$((WY + cy))
        if ((RANDOM % 4 == 0)); then
            local dx=$((RANDOM % 81 - 40))
            echo "$ACTIONS slide '$name' by $dx" >>"$OUT/actions.log"
            xdotool mousemove "$x" "$y" mousedown 1 mousemove $((x + dx / 2)) "$y" sleep 0.02 \
                mousemove $((x + dx)) "$y" mouseup 1 2>/dev/null || true
        else
            echo "$ACTIONS click '$name'" >>"$OUT/actions.log"
            xdotool mousemove "$x" "$y" click 1 2>/dev/null || true
        fi
    elif ((kind < 93)); then
        # Text, for whatever has the keyboard (a field, a dialog, the edit prompt), then
        # sometimes Enter or Tab.
        local text
        text=$(pick "2" "-1" "0" "1e9" "nan" "0.5" "abc" "10" "1e-300" "../x" "a b" "3.25" "")
        echo "$ACTIONS type '$text'" >>"$OUT/actions.log"
        [[ -n "$text" ]] && xdotool type --window "$WID" --delay 10 -- "$text" 2>/dev/null || true
        case $((RANDOM % 3)) in
            0) xdotool key --window "$WID" Return 2>/dev/null || true ;;
            1) xdotool key --window "$WID" Tab 2>/dev/null || true ;;
        esac
    else
        w=$((400 + RANDOM % 1000))
        h=$((300 + RANDOM % 800))
        echo "$ACTIONS resize to ${w}x$h" >>"$OUT/actions.log"
        xdotool windowsize "$WID" "$w" "$h" 2>/dev/null || true
    fi
    sleep 0.0$((RANDOM % 10))
}

launch
end=$((SECONDS + SECONDS_TO_ACT))
while ((SECONDS < end)); do
    alive || continue
    act
    ((ACTIONS % 25 == 0)) && alive && probe
    check_stderr
done
alive && probe
check_stderr
kill -0 "$APP_PID" 2>/dev/null && quit_by_esc
kill -0 "$APP_PID" 2>/dev/null && quit_with Return
if kill -0 "$APP_PID" 2>/dev/null; then
    kill "$APP_PID"
    wait "$APP_PID" 2>/dev/null || true
    APP_PID=""
else
    ended_status=0
    wait "$APP_PID" || ended_status=$?
    APP_PID=""
    ((ended_status == 0)) || failed "the program exited with status $ended_status at the end"
fi
check_stderr

# Every scene the hand saved reads back.
saved=0
while IFS= read -r -d '' f; do
    saved=$((saved + 1))
    "$SIM" "$f" --duration 0.01 --report /dev/null 2>"$OUT/sim.err" ||
        failed "a saved scene does not read back: $f: $(cat "$OUT/sim.err")"
done < <(find "$WORK" -name '*.json' -print0)
pass "$ACTIONS random actions in $SECONDS s, $STARTS start(s), $saved saved scene(s) read back (seed $SEED)"
