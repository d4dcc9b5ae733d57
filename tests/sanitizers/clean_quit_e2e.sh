#!/usr/bin/env bash
# The sandbox built with the sanitizers, under a real X server: it opens its window, runs, and a
# clean quit (Esc) exits 0 with no sanitizer report. A sanitizer build reports leaks at exit,
# and system libraries keep a few allocations for the process's life (libdbus from SDL_Init,
# Mesa's GLX): tests/sanitizers/lsan.supp names those libraries, never our code. Their stacks
# go through a driver without frame pointers, so only the slow unwinder sees the library
# (fast_unwind_on_malloc=0; docs/testing.md).
#   tests/sanitizers/clean_quit_e2e.sh PATH/TO/particle-sandbox [OUTPUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=../e2e/harness.sh
source "$here/../e2e/harness.sh"
e2e_begin clean_quit "$@"
LOG=$OUT/stdout.log
start_xvfb "$OUT/xvfb.log" 800x600x24 || fail "no X server"
export ASAN_OPTIONS="detect_leaks=1:fast_unwind_on_malloc=0:exitcode=23"
export LSAN_OPTIONS="suppressions=$here/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
start_app "$BIN" --window 800x600
pass "the window opened"
# Some time running, a launch drag in the box, then quit.
sleep 1
xdotool mousemove "$(sx 2)" "$(sy 2)" mousedown 1 mousemove "$(sx 3)" "$(sy 3)" mouseup 1
sleep 1
# SDL may have replaced the window it first mapped (a GL visual): the window that is there now.
WID=$(xdotool search --onlyvisible --pid "$APP_PID" --name "Particle Sandbox" | tail -1)
key Escape  # the launch is unsaved: Esc asks in a dialog, D discards and quits
wait_log "Unsaved changes to .*: Save, Discard or Cancel"
# The dialog takes its keys from the frame after the one it appears in, and a sanitizer build
# under load draws a frame in a good part of a second: D again until it is taken.
status=0
quit_with d
for _ in $(seq 200); do kill -0 "$APP_PID" 2>/dev/null || break; sleep 0.1; done
kill -0 "$APP_PID" 2>/dev/null && fail "still running 20 s after Esc"
wait "$APP_PID" || status=$?
APP_PID=""
if grep -Eq 'Sanitizer|runtime error|leaked in' "$OUT/stderr.log"; then
  fail "a sanitizer report at exit: $(grep -E 'SUMMARY|runtime error' "$OUT/stderr.log" | head -3)"
fi
[[ $status -eq 0 ]] || fail "exit status $status after Esc"
pass "a clean quit exits 0 with no sanitizer report"
