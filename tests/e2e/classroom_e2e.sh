#!/usr/bin/env bash
# End-to-end test of the classroom window: the real program in a virtual X display (Xvfb), driven
# with real X keys (xdotool), read through its log, its screenshots, the text F12 writes beside
# them, and its settings file.
#
#   tests/e2e/classroom_e2e.sh PATH/TO/particle-sandbox [OUTPUT_DIR]
#
#   1. Ctrl+T, Ctrl+plus five times                 -> the light theme at 200 %
#   2. F12                                          -> the picture's background is white, most of
#                                                      it light; its text lists the HUD, the
#                                                      message and the layout
#   3. the settings file                            -> written in $XDG_CONFIG_HOME, theme light,
#                                                      scale 2
#   4. Tab, A, Esc, A                               -> A goes to the panel while it has the keys
#                                                      (arrows stay), to the sandbox after Esc
#   5. Esc (quits), a new start                     -> the file is read: light at 200 % again
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/harness.sh"
e2e_begin classroom "$@"

start_xvfb "$OUT/xvfb.log" 1280x900x24 || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy
SETTINGS="$XDG_CONFIG_HOME/particle-sandbox/settings.json"

LOG="$OUT/stdout.log"
start_app "$BIN" --renderer software --window 1200x850 --paused --seed 7 --screenshot-dir "$OUT"
pass "window at $WX,$WY size ${WIDTH}x$HEIGHT"
[[ ! -e "$SETTINGS" ]] || fail "a settings file before any setting changed"

# --- 1. the light theme at 200 % with real keys --------------------------------------------
key ctrl+t
wait_log "Theme: light"
for _ in 1 2 3 4 5; do key ctrl+equal; done
wait_log "UI scale 200 %"
pass "Ctrl+T and Ctrl+plus: $(grep -c 'UI scale' "$LOG") scale steps to 200 %"

# --- 2. F12: the picture and its text ------------------------------------------------------
# pixel FILE X Y: "R G B" of one pixel.
pixel() {
    convert "$1" -format '%[fx:int(255*p{'"$2,$3"'}.r)] %[fx:int(255*p{'"$2,$3"'}.g)] %[fx:int(255*p{'"$2,$3"'}.b)]' info:
}
screenshot() {  # screenshot: F12, and PNG set to the file written
    local n
    n=$(grep -c "Saved screenshot" "$LOG" || true)
    key F12
    wait_count "Saved screenshot" $((n + 1))
    PNG=$(grep "Saved screenshot" "$LOG" | tail -1 | sed -E 's/.*Saved screenshot //')
    [[ -f "$PNG" ]] || fail "no picture at $PNG"
}
screenshot
read -r r g b <<<"$(pixel "$PNG" $((WIDTH - 4)) $((HEIGHT - 4)))"
((r == 255 && g == 255 && b == 255)) || fail "the bottom-right corner is $r $g $b, not white"
light=$(convert "$PNG" -colorspace Gray -format '%[fx:int(100*mean)]' info:)
((light >= 80)) || fail "the picture is $light % light on average: not the light theme"
TXT=${PNG%.png}.txt
grep -q "^HUD:" "$TXT" || fail "no HUD in $TXT"
# In its long words, or its short ones where the panel leaves the HUD too narrow for them.
grep -Eq "Kinetic energy|KE [0-9]" "$TXT" || fail "the HUD's energy is not in $TXT"
grep -q "UI scale 200 %" "$TXT" || fail "the message is not in $TXT"
grep -Eq "^  box [0-9]+ [0-9]+ [0-9]+ [0-9]+" "$TXT" || fail "no box in the layout of $TXT"
cp "$PNG" "$OUT/light-200.png"
pass "F12: a white background ($light % light), the text lists the HUD, the message, the box"

# --- 3. the settings file ------------------------------------------------------------------
[[ -f "$SETTINGS" ]] || fail "no settings file at $SETTINGS"
grep -q '"theme": "light"' "$SETTINGS" || fail "the file does not keep the theme: $(cat "$SETTINGS")"
grep -q '"scale": 2.0' "$SETTINGS" || fail "the file does not keep the scale: $(cat "$SETTINGS")"
pass "settings written to \$XDG_CONFIG_HOME/particle-sandbox/settings.json"

# --- 4. the keyboard: the panel's while it has it ----------------------------------------
n=$(grep -c "Arrows off" "$LOG" || true)
key Tab
key a
sleep 0.3
(($(grep -c "Arrows off" "$LOG" || true) == n)) || fail "A toggled the arrows while the panel had the keys"
shot panel-keys
key Escape
key a
wait_count "Arrows off" $((n + 1))
kill -0 "$APP_PID" || fail "the Esc that gave the keys back quit the program"
key a  # arrows on again, as the file keeps them
wait_log "Arrows on"
pass "Tab: A went to the panel; Esc: back to the sandbox, A toggles the arrows"

# --- 5. the next start reads the file ------------------------------------------------------
quit_by_esc
kill -0 "$APP_PID" 2>/dev/null && fail "still running after Esc, Enter"
APP_PID=""
mv "$LOG" "$OUT/first-run.log"
start_app "$BIN" --renderer software --window 1200x850 --paused --seed 7 --screenshot-dir "$OUT"
wait_log "Settings read from .*settings.json"
grep -q "UI scale 200 %" "$LOG" || fail "the second start is not at 200 %"
screenshot
read -r r g b <<<"$(pixel "$PNG" $((WIDTH - 4)) $((HEIGHT - 4)))"
((r == 255 && g == 255 && b == 255)) || fail "the second start's corner is $r $g $b, not white"
pass "the next start read the file: light, 200 %"
quit_by_esc
echo "classroom e2e: all passed ($OUT)"
