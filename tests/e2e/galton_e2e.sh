#!/usr/bin/env bash
# End-to-end test of the Galton board's histogram: the real program in a virtual X display
# (Xvfb), driven with real X input (xdotool); what the screen says is read from the F12 text.
#
#   tests/e2e/galton_e2e.sh PATH/TO/particle-sandbox [OUTPUT_DIR]
#
#   1. opens preset 09 (paused)            -> the bins panel is there, on by default: 0 landed,
#                                             1000 still to drop, "too few balls yet"; the
#                                             dropper's spout is drawn, "dropper: 1000 balls left";
#                                             the 9 counted bins of the 15 channels are marked
#                                             on the board in the bars' orange
#   2. Space, a few seconds, F12 (again    -> balls have landed: the counts add up to the
#      until ten have landed)
#                                             number the legend says, landed + not yet in the
#                                             bins + still to drop = 1000 = what the dropper
#                                             says it released and has left, the bars are drawn
#                                             (orange in the panel), the legend names the
#                                             binomial and the normal curve, with a verdict
#   3. the Show section's checkbox off     -> the panel is gone from the screen and its text
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/harness.sh"
e2e_begin galton "$@"

start_xvfb "$OUT/xvfb.log" 1300x900x24 || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy
LOG="$OUT/stdout.log"
start_app "$BIN" --renderer software --window 1200x850 --paused --seed 7 --log-controls \
    --screenshot-dir "$OUT"

# Bar-coloured pixels (kBinBarColor, 230 160 60) inside a layout rectangle "x y w h".
bars_in() {
    local x y w h
    read -r x y w h <<<"$2"
    convert "$1" -crop "${w}x${h}+$((WX + x))+$((WY + y))" +repage -depth 8 txt:- |
        grep -c "#E6A03C" || true
}

# --- 1. the preset, before it runs -------------------------------------------------------------
key 9
wait_log "Preset 9 of"
snap 1-opened
box=$(rect 1-opened bins)
[[ -n "$box" ]] || fail "no bins panel on opening the Galton board: $(cat "$OUT/1-opened.txt")"
section 1-opened Bins |
    grep -q "^bars: balls in bins 0 to 8, marked on the board (0 landed, 1000 still to drop)$" ||
    fail "legend before the run: $(section 1-opened Bins)"
section 1-opened Bins | grep -q "^too few balls yet to compare with the curve$" ||
    fail "no 'too few' verdict before the run"
section 1-opened Droppers | grep -q "^dropper: 1000 balls left$" ||
    fail "no dropper in the screen text: $(cat "$OUT/1-opened.txt")"
# The spout's colour (150 165 185) on the board.
spout=$(convert "$OUT/1-opened.png" -depth 8 txt:- | grep -c "#96A5B9" || true)
[[ "$spout" -gt 30 ]] || fail "only $spout spout-coloured pixels: no dropper drawn"
# The nine bins counted of the fifteen channels, marked on the board in the bars' colour (no
# ball is on the board yet, and the balls share that colour).
read -r bx by bw bh < <(rect 1-opened box)
marks=$(bars_in "$OUT/1-opened.png" "$bx $by $bw $bh")
[[ "$marks" -gt 1000 ]] || fail "only $marks bar-coloured pixels on the board: the bins are not marked"
pass "opened: bins panel at $box, $(section 1-opened Bins | head -1), spout $spout pixels, bins marked ($marks pixels)"

# --- 2. run it ----------------------------------------------------------------------------------
# Until balls have landed (a loaded machine steps the thousand balls slower than real time),
# pausing for each look so that the text and the picture are of one state.
for ((look = 1; look <= 8; look++)); do
    key space
    sleep 4
    key space
    snap 2-running
    legend=$(section 2-running Bins)
    landed=$(sed -nE 's/^bars: balls in bins [0-9]+ to [0-9]+, marked on the board \(([0-9]+) landed.*/\1/p' <<<"$legend")
    [[ -n "$landed" && "$landed" -ge 10 ]] && break
done
[[ -n "$landed" && "$landed" -gt 0 ]] || fail "no balls landed after $((4 * look)) s: $legend"
sum=$(grep "^counts:" <<<"$legend" | tr ' ' '\n' | grep -E '^[0-9]+$' | paste -sd+ | bc)
[[ "$sum" == "$landed" ]] || fail "the counts add up to $sum, the legend says $landed landed"
falling=$(sed -nE 's/^bars: .* ([0-9]+) not yet in the bins.*/\1/p' <<<"$legend")
todrop=$(sed -nE 's/^bars: .* ([0-9]+) still to drop.*/\1/p' <<<"$legend")
left=$(section 2-running Droppers | sed -nE 's/^dropper: ([0-9]+) balls? left$/\1/p')
[[ -n "$todrop" && "$todrop" == "$left" ]] ||
    fail "the legend says ${todrop:-none} still to drop, the dropper ${left:-nothing}"
[[ $((landed + ${falling:-0} + todrop)) -eq 1000 ]] ||
    fail "landed $landed + not yet in the bins ${falling:-0} + still to drop $todrop != 1000"
grep -qE "^dots: binomial, [0-9]+ rows, p = 1/2$" <<<"$legend" || fail "no binomial line: $legend"
grep -qE "^line: normal curve \(mean [0-9.]+, spread [0-9.]+ bins\)$" <<<"$legend" ||
    fail "no normal curve line: $legend"
grep -qE "^((close to|far from) the curve: chi-squared [0-9.e+]+ [<>] [0-9.]+|too few balls yet to compare with the curve)" <<<"$legend" ||
    fail "no verdict in words: $legend"
pixels=$(bars_in "$OUT/2-running.png" "$(rect 2-running bins)")
[[ "$pixels" -gt 500 ]] || fail "only $pixels bar-coloured pixels in the bins panel"
pass "$landed landed (counts add up), ${falling:-0} falling, $todrop still to drop; $pixels bar pixels; $(sed -n 4p <<<"$legend")"

# --- 3. switched off in the Show section (open by default) ---------------------------------------
# The velocity arrows share the bars' orange and a fast ball's arrow can reach past the box into
# the panel's place: they go first, so that only the bars could colour it.
click "Velocity arrows"
click "Bin counts against the bell curve"
snap 3-off
[[ -z "$(rect 3-off bins)" ]] || fail "the bins panel is still laid out after switching it off"
[[ -z "$(section 3-off Bins)" ]] || fail "the screen text still lists the bins"
pixels=$(bars_in "$OUT/3-off.png" "$(rect 2-running bins)")
[[ "$pixels" -lt 50 ]] || fail "$pixels bar-coloured pixels where the panel was"
pass "switched off: no panel, no text"

xdotool mousemove $((WX + 1100)) $((WY + 800))
# Running a preset is no edit: Esc asks whether to quit, Enter quits.
quit_by_esc
wait_exit
kill -0 "$APP_PID" 2>/dev/null && fail "still running after Esc, Enter"
APP_PID=""
echo "PASS: galton e2e ($OUT)"
