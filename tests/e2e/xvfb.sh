# shellcheck shell=bash
# Sourced by the end-to-end scripts: start_xvfb LOGFILE starts a private Xvfb on a random free
# display, exports DISPLAY and sets XVFB_PID (the caller kills it). Returns 1 when none starts.
# A random high display number, not Xvfb -displayfd: servers started at the same moment with
# -displayfd can end up sharing a display (and each other's input) on a busy machine.
start_xvfb() {
    local log=$1 n
    XVFB_PID=""
    for _ in $(seq 30); do
        n=$((200 + RANDOM % 700))
        [[ -e /tmp/.X$n-lock || -e /tmp/.X11-unix/X$n ]] && continue
        Xvfb ":$n" -screen 0 640x480x24 -nolisten tcp 2>"$log" &
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
