# Sourced by the end-to-end scripts (sandbox_e2e.sh, defects_e2e.sh, undo_e2e.sh, panel_e2e.sh,
# obstacles_e2e.sh, galton_e2e.sh, data_e2e.sh, tests/install/install_test.sh): e2e_begin, which
# the app's scripts start with (their arguments, output folder and fail()), pass(), the ERR trap that
# names the failing line, the clean-up at exit of the program under test (APP_PID) and of the X
# server (XVFB_PID), start_xvfb, and for the app's scripts start_app with the functions that
# drive and read it (they use LOG, OUT and the window variables start_app sets).
pass() { echo "ok: $*"; }

# Every deadline below is for a condition (a log line, a title, a window, an exit), never a fixed
# wait: a condition met returns at once, so a deadline costs only a failing run. They are
# E2E_PATIENCE (default 4) times what a quiet 2-core machine needs, so that a machine four times
# slower (a loaded CI runner) still passes; CTest's timeouts (tests/e2e/CMakeLists.txt) leave
# the same room.
E2E_PATIENCE=${E2E_PATIENCE:-4}
# patient SECONDS: SECONDS times the patience, whole seconds.
patient() { echo $(($1 * E2E_PATIENCE)); }

# need_test_tools: Xvfb, xdotool, ImageMagick, xclip and ffprobe, installed (scripts/install-deps.sh --test)
# when one is missing.
need_test_tools() {
    local here tool
    here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
    for tool in Xvfb xdpyinfo xdotool import convert xclip ffprobe; do
        if ! command -v "$tool" >/dev/null; then
            "$here/../../scripts/install-deps.sh" --test
            break
        fi
    done
}

# e2e_begin NAME "$@": the app's scripts' start. BIN and OUT from the script's arguments
# (PATH/TO/particle-sandbox [OUTPUT_DIR], OUT by default ./NAME-e2e-out), OUT emptied of an
# earlier run's pictures, texts, logs and saves, fail() (the message, the logs, where the output
# is, exit 1), and the test tools.
e2e_begin() {
    local name=$1
    shift
    BIN=${1:?usage: ${name}_e2e.sh PATH/TO/particle-sandbox [OUTPUT_DIR]}
    OUT=${2:-$(pwd)/${name}-e2e-out}
    mkdir -p "$OUT"
    rm -f "$OUT"/*.png "$OUT"/*.txt "$OUT"/*.log "$OUT"/*.json
    # The program's settings file in a folder of the test's own, fresh: never the user's.
    rm -rf "$OUT/config"
    export XDG_CONFIG_HOME="$OUT/config"
    fail() {
        echo "FAIL: $*" >&2
        show_logs
        if [[ -f "$OUT/stdout.log" ]]; then
            echo "--- stdout.log:" >&2
            tail -n 30 "$OUT/stdout.log" >&2 || true
        fi
        echo "(log, screenshots and saves in $OUT)" >&2
        exit 1
    }
    need_test_tools
}

XVFB_PID=""
APP_PID=""
cleanup() {
    [[ -n "$APP_PID" ]] && kill "$APP_PID" 2>/dev/null || true
    [[ -n "$XVFB_PID" ]] && kill "$XVFB_PID" 2>/dev/null || true
    wait 2>/dev/null || true
}
trap cleanup EXIT
trap '[[ $- == *e* ]] && echo "FAIL: line $LINENO: $BASH_COMMAND exited with $?" >&2' ERR

# start_xvfb LOG [SCREEN] starts a private X server (default screen 640x640x24), sets XVFB_PID
# and exports DISPLAY; returns 1 if none started.
# A random high display number, not Xvfb -displayfd: servers started at the same moment with
# -displayfd can end up sharing a display (and each other's input) on a busy machine.
start_xvfb() {
    local log=$1 screen=${2:-640x640x24} n
    XVFB_PID=""
    for _ in $(seq 30); do
        n=$((200 + RANDOM % 700))
        [[ -e /tmp/.X$n-lock || -e /tmp/.X11-unix/X$n ]] && continue
        Xvfb ":$n" -screen 0 "$screen" -nolisten tcp 2>"$log" &
        XVFB_PID=$!
        for _ in $(seq $((25 * E2E_PATIENCE))); do
            kill -0 "$XVFB_PID" 2>/dev/null || break
            xdpyinfo -display ":$n" >/dev/null 2>&1 && break
            sleep 0.05
        done
        if kill -0 "$XVFB_PID" 2>/dev/null && xdpyinfo -display ":$n" >/dev/null 2>&1; then
            export DISPLAY=":$n"
            return 0
        fi
        kill "$XVFB_PID" 2>/dev/null || true
        XVFB_PID=""
    done
    return 1
}

# show_logs: for a failure, the ends of $OUT's stderr.log and xvfb.log, and whether the program
# under test still runs.
show_logs() {
    local f
    for f in stderr.log xvfb.log; do
        [[ -s "$OUT/$f" ]] && { echo "--- $f:" >&2; tail -n 20 "$OUT/$f" >&2; }
    done
    if [[ -n "${APP_PID:-}" ]] && ! kill -0 "$APP_PID" 2>/dev/null; then
        echo "(the program is no longer running)" >&2
    fi
    return 0
}

# start_app BIN ARGS... runs the sandbox with its log in $LOG (stderr in $OUT/stderr.log) and
# waits for its window: sets APP_PID, WID, WX, WY, WIDTH, HEIGHT, and from the logged fitted
# view ZOOM (px/m), BX, BY (the box's top-left in the window), for sx and sy.
start_app() {
    "$@" >"$LOG" 2>"$OUT/stderr.log" &
    APP_PID=$!
    WID=$(timeout "$(patient 20)" xdotool search --sync --onlyvisible --pid "$APP_PID" --name "Particle Sandbox" |
        head -1) || {
        ps -o pid,stat,etime,wchan:30,args -p "$APP_PID" >&2 || true
        for t in /proc/"$APP_PID"/task/*; do echo "thread $t: $(cat "$t/wchan" 2>/dev/null)" >&2; done
        xdotool search --name "Particle Sandbox" >&2 || true
        fail "no window within $(patient 20) s (display $DISPLAY)"
    }
    [[ -n "$WID" ]] || fail "no window"
    eval "$(xdotool getwindowgeometry --shell "$WID")"  # X, Y, WIDTH, HEIGHT
    WX=$X
    WY=$Y
    xdotool windowfocus --sync "$WID" 2>/dev/null || true
    # The camera starts fitted to the box; the program logs the mapping it chose.
    for _ in $(seq $((100 * E2E_PATIENCE))); do grep -q "\[I\] View: zoom" "$LOG" && break; sleep 0.05; done
    read_view "$(grep "\[I\] View: zoom" "$LOG" | head -1)"
}
# read_view LINE: ZOOM, BX, BY from a logged "View: zoom ..." line.
read_view() {
    [[ -n "$1" ]] || fail "no view line in the log"
    read -r ZOOM BX BY < <(sed -E 's/.*zoom ([0-9.]+) px\/m, box top-left at \[([-0-9.]+), ([-0-9.]+)\].*/\1 \2 \3/' <<<"$1")
}
# Screen x, y (root window pixels) of world x, y metres.
sx() { awk -v w="$1" -v z="$ZOOM" -v o="$WX" -v b="$BX" 'BEGIN { printf "%d", o + b + w * z + 0.5 }'; }
sy() { awk -v w="$1" -v z="$ZOOM" -v o="$WY" -v b="$BY" 'BEGIN { printf "%d", o + b + w * z + 0.5 }'; }

wait_log() {  # wait_log REGEX [SECONDS]: SECONDS on a quiet machine (times the patience)
    local deadline=$((SECONDS + $(patient "${2:-5}")))
    while ! grep -Eq "$1" "$LOG"; do
        ((SECONDS < deadline)) || fail "timed out waiting for log line /$1/"
        sleep 0.05
    done
}
wait_count() {  # wait_count REGEX N [SECONDS]: until N lines match
    local deadline=$((SECONDS + $(patient "${3:-5}")))
    while (($(grep -Ec "$1" "$LOG" || true) < $2)); do
        ((SECONDS < deadline)) || fail "timed out waiting for $2 log lines /$1/"
        sleep 0.05
    done
}
# A dialog takes its keys from the frame after the one it appears in; a loaded machine may not
# have drawn that frame when the log says the dialog opened, and the key is then not taken.
# press_until KEY REGEX: KEY, again every 3 s, until one more log line matches REGEX.
press_until() {
    local n
    n=$(grep -Ec "$2" "$LOG" || true)
    for _ in 1 2 3 4 5; do
        xdotool key --window "$WID" "$1" 2>/dev/null || true
        sleep 0.15  # as key() does: the frame after the key has closed what it closes
        for _ in $(seq $((30 * E2E_PATIENCE))); do
            (($(grep -Ec "$2" "$LOG" || true) > n)) && return 0
            sleep 0.1
        done
    done
    fail "no log line /$2/ after pressing $1 five times"
}
# quit_with KEY: KEY, again every 2 s, until the program has exited (the window may be gone
# before xdotool sends the key's release: that error is expected).
quit_with() {
    for _ in 1 2 3 4 5 6; do
        kill -0 "$APP_PID" 2>/dev/null || return 0
        xdotool key --window "$WID" "$1" 2>/dev/null || true
        for _ in $(seq $((20 * E2E_PATIENCE))); do
            kill -0 "$APP_PID" 2>/dev/null || return 0
            sleep 0.1
        done
    done
}
# quit_by_esc: Esc asks whether to quit (nothing unsaved: "Quit Particle Sandbox? Enter quits, Esc
# stays") and Enter answers Quit, each again until taken (a dialog takes its keys from the frame
# after the one it appears in), until the program has exited.
quit_by_esc() {
    local n
    for _ in 1 2 3 4 5 6; do
        kill -0 "$APP_PID" 2>/dev/null || return 0
        n=$(grep -c "Quit Particle Sandbox?" "$LOG" || true)
        xdotool key --window "$WID" Escape 2>/dev/null || true
        for _ in $(seq $((30 * E2E_PATIENCE))); do
            (($(grep -c "Quit Particle Sandbox?" "$LOG" || true) > n)) && break
            sleep 0.1
        done
        (($(grep -c "Quit Particle Sandbox?" "$LOG" || true) > n)) || continue
        quit_with Return
        return 0
    done
}
title() { xdotool getwindowname "$WID"; }
# wait_exit: until the program under test has ended (5 s on a quiet machine, times the patience).
wait_exit() {
    for _ in $(seq $((100 * E2E_PATIENCE))); do kill -0 "$APP_PID" 2>/dev/null || return 0; sleep 0.05; done
}
wait_title() {  # wait_title REGEX
    local deadline=$((SECONDS + $(patient 5)))
    until title | grep -Eq "$1"; do
        ((SECONDS < deadline)) || fail "title '$(title)' never matched /$1/"
        sleep 0.05
    done
}
key() { xdotool key --window "$WID" "$@"; sleep 0.15; }
shot() { sleep 0.3; import -window root "$OUT/$1.png"; }

# The control panel, for a program run with --log-controls ("[I] Control NAME at X Y", window
# points): ctl NAME gives the screen point "x y" of the control called NAME, from its latest log
# line; click NAME clicks it; type_into NAME TEXT types into a field.
ctl() {
    local line
    line=$(grep -F "[I] Control $1 at " "$LOG" | tail -1) || fail "no control '$1' in the log"
    read -r cx cy < <(sed -E 's/.* at ([0-9]+) ([0-9]+)$/\1 \2/' <<<"$line")
    echo "$((WX + cx)) $((WY + cy))"
}
click() {  # click NAME: move away (no tooltip left), there, wait for a frame, press, release
    local x y
    read -r x y < <(ctl "$1")
    xdotool mousemove --sync $((WX + 900)) $((WY + 700)) sleep 0.15 \
        mousemove --sync "$x" "$y" sleep 0.15 mousedown 1 sleep 0.1 mouseup 1
    sleep 0.3  # the layout may change: the log gets the new places
}
type_into() {  # type_into NAME TEXT: click the field (which selects its text), type, Enter
    click "$1"
    xdotool type --delay 30 "$2"
    xdotool keydown Return sleep 0.1 keyup Return
    sleep 0.3
}
# Drag with the left button from screen point (x0,y0) in n moves of (dx,dy), 15 ms apart, as
# one xdotool command chain so that process start-up under load cannot stretch the timing (the
# app releases a particle at rest if the hand paused for 100 ms). An optional 6th argument is a
# further chain (e.g. a key press) run while the button is still down.
drag() {
    local x=$1 y=$2 dx=$3 dy=$4 n=$5 hold=${6:-}
    local chain=(mousemove --sync "$x" "$y" sleep 0.1 mousedown 1 sleep 0.1)
    for ((i = 1; i <= n; i++)); do
        chain+=(mousemove "$((x + i * dx))" "$((y + i * dy))" sleep 0.015)
    done
    # shellcheck disable=SC2206
    [[ -n "$hold" ]] && chain+=($hold)
    chain+=(mouseup 1)
    xdotool "${chain[@]}"
    sleep 0.2
}

# Centroid "x y count" of the pixels of colour R,G,B (±6 per channel) in a screenshot.
centroid() {
    convert "$1" -depth 8 txt:- | awk -v r="$2" -v g="$3" -v b="$4" -F'[ ,:()]+' '
        NR > 1 {
            # "x,y: (R,G,B) ..." -> fields x y R G B
            if ($3 >= r - 6 && $3 <= r + 6 && $4 >= g - 6 && $4 <= g + 6 && $5 >= b - 6 && $5 <= b + 6) {
                sx += $1; sy += $2; n++
            }
        }
        END { if (n) printf "%.1f %.1f %d\n", sx / n, sy / n, n; else print "0 0 0" }'
}
# fill_at PNG X Y: "r g b" of the screenshot's pixel at root point (X, Y) (a disc's centre: its
# fill, in the shade of its mass among the scene's).
fill_at() {
    convert "$1" -crop "1x1+$2+$3" -depth 8 txt:- |
        sed -nE '2s/^[^(]*\(([0-9]+),([0-9]+),([0-9]+).*/\1 \2 \3/p'
}
# Pure white pixels inside a rectangle "WxH+X+Y" of a screenshot.
white_in() {
    convert "$1" -crop "$2" +repage -depth 8 txt:- | grep -c "#FFFFFF" || true
}

# snap NAME: F12, then the screenshot and its text as OUT/NAME.png and OUT/NAME.txt.
SNAPS=0
snap() {
    sleep 0.3
    key F12
    SNAPS=$((SNAPS + 1))
    wait_count "\[I\] Saved screenshot " "$SNAPS"
    local png
    png=$(grep "Saved screenshot" "$LOG" | tail -1 | sed -E 's/.*Saved screenshot (.*)$/\1/')
    mv "$png" "$OUT/$1.png"
    mv "${png%.png}.txt" "$OUT/$1.txt"
}
# rect NAME FILE: "x y w h" of a layout rectangle in a screenshot's text (empty if not drawn).
rect() { awk -v n="$2" '$1 == n && NF == 5 { print $2, $3, $4, $5 }' "$OUT/$1.txt"; }
# section NAME FILE: the lines of one section of a screenshot's text.
section() { awk -v s="$2:" '/^[A-Za-z]/ { on = ($0 == s) } on && /^  / { print substr($0, 3) }' "$OUT/$1.txt"; }
