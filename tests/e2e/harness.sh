# Sourced by the end-to-end scripts (sandbox_e2e.sh, tests/install/install_test.sh), which
# define fail() themselves: pass(), the ERR trap that names the failing line, the clean-up at
# exit of the program under test (APP_PID) and of the X server (XVFB_PID), and start_xvfb.
pass() { echo "ok: $*"; }

# need_test_tools: Xvfb, xdotool and ImageMagick, installed (scripts/install-deps.sh --test)
# when one is missing.
need_test_tools() {
    local here tool
    here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
    for tool in Xvfb xdpyinfo xdotool import convert; do
        if ! command -v "$tool" >/dev/null; then
            "$here/../../scripts/install-deps.sh" --test
            break
        fi
    done
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
