# Sourced by the end-to-end scripts (sandbox_e2e.sh, tests/install/install_test.sh), which
# define fail() themselves: pass(), the ERR trap that names the failing line, the clean-up at
# exit of the program under test (APP_PID) and of the X server (XVFB_PID), start_xvfb, and drag.
pass() { echo "ok: $*"; }

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
        for _ in $(seq 100); do
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
