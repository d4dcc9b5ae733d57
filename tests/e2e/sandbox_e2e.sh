#!/usr/bin/env bash
# End-to-end test of particle-sandbox: the real program in a virtual X display (Xvfb), driven
# with real X input (xdotool), checked through its log, its window title and screenshots
# (ImageMagick).
#
#   tests/e2e/sandbox_e2e.sh PATH/TO/particle-sandbox [OUTPUT_DIR]
#
# It opens the built-in scene paused (so particles stay where the scene puts them), then:
#   0. bad command lines                               -> a clear message and a non-zero exit
#   1. grabs a particle and flings it downwards        -> logged release velocity points down,
#                                                         and it moves down when stepped
#   2. grabs another, presses A twice and Delete while  -> both toggles and the deletion logged,
#      holding                                             count drops
#   3. drags on empty space up and to the right         -> a new particle, which moves up-right
#   4. turns the wheel over the window                  -> zoom grows, the wall moves on screen
#   5. presses S                                        -> label text appears above particles
#   6. presses Ctrl+S                                   -> a scene file with the launched
#                                                         particle, moving up-right
#   7. presses V, L, L, K, D, steps, then V, K, D, L    -> the box refits beside the panels; the
#                                                         momentum view, trails, plots and
#                                                         speed histogram appear in their colours
#                                                         (logged, and named in the HUD), then
#                                                         go away
#   8. presses T three times                            -> substep, exact, discrete logged
#   9. presses R                                        -> the scene as loaded: 6 particles
#  10. clicks a particle                                -> selected (log), outlined (pixels)
#  11. Enter, types 2e1 (letters go to the prompt), Enter -> mass edited to 20 kg, E not seen;
#      Enter, -1, Enter, Esc                            -> refused with a message, cancelled
#  12. presses E, Shift+E, G, G, T T G G (exact), T     -> restitution and gravity logged,
#                                                         gravity on and off in exact mode
#  13. presses F12                                      -> a PNG of the window's size
#  14. presses R, clicks the edited particle again      -> its mass is the loaded 12 kg
#  14b. presses Right 16 times, then F                -> a marker points to the box, F fits
#  15. presses H, Esc; M, Esc; Esc                      -> help closed, a question about the
#                                                         unsaved change, then a clean exit
# Screenshots and the log are left in OUTPUT_DIR.
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/harness.sh"
e2e_begin sandbox "$@"

# --- 0. bad command lines fail clearly, before any window -------------------------------
set +e
"$BIN" --help >"$OUT/help.txt" 2>&1
help_status=$?
"$BIN" "$OUT/no-such-scene.json" >/dev/null 2>"$OUT/bad-scene.txt"
scene_status=$?
"$BIN" --window 12x >/dev/null 2>"$OUT/bad-window.txt"
window_status=$?
"$BIN" --bogus >/dev/null 2>"$OUT/bad-option.txt"
option_status=$?
"$BIN" --save-to "$OUT/no/such/dir/save.json" >/dev/null 2>"$OUT/bad-save-to.txt"
save_to_status=$?
set -e
((help_status == 0)) && grep -q -- "--save-to" "$OUT/help.txt" || fail "--help"
((scene_status != 0)) && grep -q "no-such-scene.json" "$OUT/bad-scene.txt" ||
    fail "a missing scene file: status $scene_status, message '$(cat "$OUT/bad-scene.txt")'"
((window_status == 2)) && grep -q -- "--window" "$OUT/bad-window.txt" ||
    fail "a bad --window: status $window_status"
((option_status == 2)) && grep -q -- "--bogus" "$OUT/bad-option.txt" ||
    fail "an unknown option: status $option_status, message '$(cat "$OUT/bad-option.txt")'"
((save_to_status == 2)) && grep -q "does not exist" "$OUT/bad-save-to.txt" ||
    fail "--save-to into a missing directory: status $save_to_status"
pass "bad command lines: $(head -1 "$OUT/bad-scene.txt")"

# --- a private X display ------------------------------------------------------------------
start_xvfb "$OUT/xvfb.log" || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy

# --- the renderer: without --renderer, OpenGL on a software rasteriser (Xvfb's llvmpipe)
# gives way to SDL's software renderer, and the program says so --------------------------------
bench=$("$BIN" --bench 50 --frames 3 2>&1) || fail "--bench without --renderer: $bench"
grep -q "renderer software" <<<"$bench" || fail "SDL's OpenGL renderer on llvmpipe kept: $bench"
pass "renderer chosen: $(grep -m1 'Renderer:' <<<"$bench")"

# --- the program --------------------------------------------------------------------------
LOG="$OUT/stdout.log"
start_app "$BIN" --renderer software --window 600x600 --paused --seed 7 --save-to "$OUT/saved.json" \
    --screenshot-dir "$OUT"
pass "window $WID at $WX,$WY size ${WIDTH}x$HEIGHT"
# This script drives the keys and the mouse in the box (tests/e2e/panel_e2e.sh drives the
# control panel). A 600 px window is narrower than twice the panel: it opens folded, and says so.
wait_log "The control panel is folded in this narrow window"
read_view "$(grep "\[I\] View: zoom" "$LOG" | sed -n 1p)"
pass "fitted view: zoom $ZOOM px/m, box top-left at ($BX, $BY) px in the window"

wait_title "6 particles - PAUSED"
pass "title shows the count and PAUSED: $(title)"
key a  # arrows off: they share the particles' colours and would move the centroids
wait_log "Arrows off"
shot 0-start

# The built-in scene (psb::defaultScene): six particles in the upper half of the box.
# --- 1. fling: the 18 kg particle at (5.2, 1.6) m, yellow (255, 210, 110), downwards -------
# Drawn in the shade of its mass among the scene's (view/mass_shade.hpp): its fill is read at
# its centre, and must still be a yellow (red over green over blue).
FLUNG=$(fill_at "$OUT/0-start.png" "$(sx 5.2)" "$(sy 1.6)")
read -r fr fg fb <<<"$FLUNG"
((fr > 150 && fr > fg && fg > fb)) || fail "the 18 kg particle's fill ($FLUNG) is not a yellow"
read -r fx0 fy0 fn0 < <(centroid "$OUT/0-start.png" $FLUNG)
((fn0 > 500)) || fail "the yellow particle is not on screen ($fn0 pixels)"
drag "$(sx 5.2)" "$(sy 1.6)" 0 12 8
wait_log "Released particle"
line=$(grep "Released particle" "$LOG" | tail -1)
grep -q "Grabbed particle at \[5.20, 5.40\]" "$LOG" || fail "did not grab the yellow particle"
vx=$(sed -E 's/.*velocity \[([-0-9.]+), ([-0-9.]+)\].*/\1/' <<<"$line")
vy=$(sed -E 's/.*velocity \[([-0-9.]+), ([-0-9.]+)\].*/\2/' <<<"$line")
# The log counts y up, as the window does: down is vy < 0.
awk -v vx="$vx" -v vy="$vy" 'BEGIN { exit !(vy < -1 && -vy > 5 * (vx < 0 ? -vx : vx)) }' ||
    fail "fling velocity [$vx, $vy] does not point down: $line"
pass "grab and fling: $line"

# --- 2. delete while holding: the 8 kg particle at (2.5, 2.6) m ----------------------------
# While holding, other keys still work: A twice (arrows on, then off again), then Delete.
drag "$(sx 2.5)" "$(sy 2.6)" 3 3 3 \
    "key --window $WID a sleep 0.1 key --window $WID a sleep 0.1 key --window $WID Delete sleep 0.2"
wait_log "Deleted particle at \[[0-9.]+, [0-9.]+\] with x velocity [-0-9.]+ m/s, y velocity [-0-9.]+ m/s and mass 8.00 kg!"
wait_title "5 particles - PAUSED"
held=$(sed -n '/Grabbed particle at \[2.50, 4.40\]/,/Deleted particle/p' "$LOG")
grep -q "Arrows on" <<<"$held" && grep -q "Arrows off" <<<"$held" ||
    fail "keys pressed while holding were not handled: $held"
pass "keys while holding (A, A) handled; delete while holding: $(grep 'Deleted particle' "$LOG")"

# --- 3. launch: drag on empty space at (1.0, 6.2) m, up and to the right -----------------
# The hand stops for 0.4 s before the release: the launch is the drag's vector (press to
# release), not the hand's last 100 ms, so the particle still leaves up and to the right.
drag "$(sx 1.0)" "$(sy 6.2)" 10 -10 8 "sleep 0.4"
wait_log "Launched particle at"
line=$(grep "Launched particle" "$LOG" | tail -1)
read -r px py vx vy < <(sed -E 's/.*at \[([-0-9.]+), ([-0-9.]+)\] with velocity \[([-0-9.]+), ([-0-9.]+)\].*/\1 \2 \3 \4/' <<<"$line")
# The press point, to within a screen pixel (under 2 cm at this zoom); the drag's 80 px up-right
# over the arrow time (1/3 s) is several m/s. The log counts y up from the floor of the 7 m box:
# 6.2 m down is 0.8 m up, and up is vy > 0.
awk -v x="$px" -v y="$py" -v vx="$vx" -v vy="$vy" \
    'BEGIN { exit !((x - 1.0) ^ 2 < 0.0009 && (y - 0.8) ^ 2 < 0.0009 && vx > 1 && vy > 1) }' ||
    fail "launch not at the press point or not up-right: $line"
wait_title "6 particles - PAUSED"
pass "launch: $line"
shot 1-launched
# A 10 kg launched particle is coloured (151, 200, 224), in the shade of its mass.
LAUNCHED=$(fill_at "$OUT/1-launched.png" "$(sx "$px")" "$(sy "$(awk -v y="$py" 'BEGIN { print 7 - y }')")")
read -r fr fg fb <<<"$LAUNCHED"
((fb > fr && fg > fr)) || fail "the launched particle's fill ($LAUNCHED) is not a light blue"
read -r lx0 ly0 ln0 < <(centroid "$OUT/1-launched.png" $LAUNCHED)
read -r fx1 fy1 fn1 < <(centroid "$OUT/1-launched.png" $FLUNG)
((ln0 > 200)) || fail "the launched particle is not on screen ($ln0 pixels)"
for _ in 1 2 3 4 5 6 7 8 9 10; do key n; done  # ten single steps while paused
shot 2-stepped
read -r lx1 ly1 ln1 < <(centroid "$OUT/2-stepped.png" $LAUNCHED)
read -r fx2 fy2 fn2 < <(centroid "$OUT/2-stepped.png" $FLUNG)
awk -v x0="$lx0" -v y0="$ly0" -v x1="$lx1" -v y1="$ly1" \
    'BEGIN { exit !(x1 - x0 > 5 && y0 - y1 > 5) }' ||
    fail "the launched particle did not move up-right: ($lx0,$ly0) -> ($lx1,$ly1)"
pass "launched particle moved from ($lx0, $ly0) to ($lx1, $ly1) px"
awk -v y0="$fy1" -v y1="$fy2" 'BEGIN { exit !(y1 - y0 > 5) }' ||
    fail "the flung particle did not move down: y $fy1 -> $fy2"
pass "flung particle moved down from y = $fy1 to $fy2 px"

# --- 4. wheel zoom about the cursor --------------------------------------------------------
# At the box's centre (the control panel takes the window's left part).
cx=$(sx 3.5)
cy=$(sy 3.5)
# A piece of the left wall (at least 2 px wide, just left of the box), halfway down: at least
# one column of it must be white.
wall="2x40+$((WX + ${BX%.*} - 2))+$((WY + ${BY%.*} + 230))"
before=$(white_in "$OUT/2-stepped.png" "$wall")
((before >= 35)) || fail "the left wall is not where the fitted camera puts it ($before px)"
xdotool mousemove --sync "$cx" "$cy"
for _ in 1 2 3; do xdotool click 4; sleep 0.1; done
wait_log "Zoom"
shot 3-zoomed
zooms=$(grep -c "\[I\] Zoom" "$LOG")
last_zoom=$(grep "\[I\] Zoom" "$LOG" | tail -1 | sed -E 's/.*Zoom ([0-9.]+).*/\1/')
awk -v z="$last_zoom" -v z0="$ZOOM" 'BEGIN { exit !(z > 1.4 * z0) }' ||
    fail "zoom $last_zoom after $zooms notches is not above 1.4 x $ZOOM"
after=$(white_in "$OUT/3-zoomed.png" "$wall")
((after < before / 4)) || fail "the wall did not move on screen when zooming ($before -> $after px)"
pass "wheel zoom: $zooms notches, zoom $ZOOM -> $last_zoom px/m, wall moved away"

# --- 5. labels ----------------------------------------------------------------------------
key f  # fit again
side=$(awk -v z="$ZOOM" 'BEGIN { printf "%d", 7 * z - 12 }')  # inside the walls
inner="${side}x${side}+$((WX + ${BX%.*} + 6))+$((WY + ${BY%.*} + 6))"
shot 4-fitted
plain=$(white_in "$OUT/4-fitted.png" "$inner")
key s
wait_log "Labels on"
shot 5-labels
labelled=$(white_in "$OUT/5-labels.png" "$inner")
((labelled > plain + 300)) || fail "S did not show labels ($plain -> $labelled white px)"
pass "S shows labels ($plain -> $labelled white pixels)"

# --- 6. save ------------------------------------------------------------------------------
# The built-in scene has no file: Ctrl+S asks for a name, proposing --save-to; Enter saves.
key ctrl+s
wait_log "Save as: type a file name, Enter saves, Esc cancels \(folder /"
shot 6-save-as
press_until Return "Saved 6 particles to /.*/saved.json"  # the full path
[[ -s "$OUT/saved.json" ]] || fail "Ctrl+S wrote no file"
# One particle per line. The launched one is the scene's typical particle (the median: 12 kg,
# 0.3 m), in the launch colour of that size (120 + 135 t, 200, 255 - 135 t at t = 0.9 / 3.9).
launched=$(grep '"mass": 12.0, "radius": 0.3, "color": \[151, 200, 223\]' "$OUT/saved.json") ||
    fail "no launched particle in the saved scene"
# The scene's name and description are saved with it.
grep -q '"description": "A handful of particles in a 7 m box' "$OUT/saved.json" ||
    fail "the saved scene lost the scene's description"
read -r svx svy < <(sed -E 's/.*"vx": ([-0-9.e+]+), "vy": ([-0-9.e+]+),.*/\1 \2/' <<<"$launched")
awk -v vx="$svx" -v vy="$svy" 'BEGIN { exit !(vx > 1 && vy < -1) }' ||
    fail "saved launched particle does not move up-right: $launched"
((  $(grep -c '"mass":' "$OUT/saved.json") == 6 )) || fail "saved scene does not hold 6 particles"
first_save=$(md5sum <"$OUT/saved.json")
# The scene now belongs to the file the user named: Ctrl+S writes it again, without asking.
key ctrl+s
wait_count "Saved 6 particles to /.*/saved.json" 2
# Save As proposes a free name beside it, never the file itself.
key ctrl+shift+s
wait_count "Save as: type a file name" 2
press_until Return "Saved 6 particles to /.*/saved-2.json"
[[ -s "$OUT/saved-2.json" && $(md5sum <"$OUT/saved.json") == "$first_save" ]] ||
    fail "Save As did not keep the first save"
pass "Ctrl+S asked for a name and saved; launched particle: vx $svx, vy $svy m/s; Ctrl+S wrote it again; Save As went beside it"

# --- 7. analysis overlays ----------------------------------------------------------------
# Pixels of one exact colour (hex, as ImageMagick prints it) in the window.
color_in() {
    convert "$1" -crop "${WIDTH}x${HEIGHT}+${WX}+${WY}" +repage -depth 8 txt:- | grep -ci "$2" ||
        true
}
YELLOW="#FFFF00" CYAN="#00E6FF" PLOT_RED="#FF5A5A" BARS="#4682E6"
key s  # labels off
wait_log "Labels off"
shot 6-before-overlays
for c in $YELLOW $PLOT_RED $BARS; do
    (($(color_in "$OUT/6-before-overlays.png" "$c") == 0)) || fail "$c on screen before any overlay"
done
# V alone first: in this small window the panels cover much of the box.
key v
wait_log "Momentum view on"
for _ in 1 2 3 4 5 6 7 8 9 10; do key n; done  # steps: samples for the path and the plots
shot 7-momentum
yellow=$(color_in "$OUT/7-momentum.png" "$YELLOW")
cyan=$(color_in "$OUT/7-momentum.png" "$CYAN")
((yellow > 30 && cyan > 10)) || fail "V: total momentum $yellow, centre of mass $cyan px"
key l
key l
views=$(grep -c "\[I\] View: zoom" "$LOG")
key k
key d
wait_log "Speed distribution on"
# The panels sit beside the box: the fitted view made room for their column at the right.
wait_count "\[I\] View: zoom" $((views + 2))
read -r z2 bx2 < <(grep "\[I\] View: zoom" "$LOG" | tail -1 |
    sed -E 's/.*zoom ([0-9.]+) px\/m, box top-left at \[([-0-9.]+), .*/\1 \2/')
box_right=$(awk -v z="$z2" -v b="$bx2" 'BEGIN { printf "%d", b + 7 * z + 0.5 }')
# The column: two fifths of what the folded panel's 34 px strip leaves, 220 to 330 px, + margin.
column=$(awk -v w="$WIDTH" 'BEGIN { c = int(0.4 * (w - 34)); if (c < 220) c = 220; if (c > 330) c = 330; print c + 8 }')
((box_right <= WIDTH - column)) || fail "with K and D on the box reaches x = $box_right of $WIDTH"
pass "K, D: the box refits to end at x = $box_right, the panels beside it"
for want in "Trails: selected" "Trails: all" "Plots on"; do
    grep -q "$want" "$LOG" || fail "no '$want' in the log"
done
for _ in 1 2 3 4 5 6 7 8 9 10; do key n; done
shot 7-overlays
plot=$(color_in "$OUT/7-overlays.png" "$PLOT_RED")
bars=$(color_in "$OUT/7-overlays.png" "$BARS")
((plot > 20)) || fail "K: $plot px of the energy plot's colour"
((bars > 200)) || fail "D: $bars px of histogram bars"
pass "V, L, K, D: total momentum $yellow px, centre of mass $cyan px, energy plot $plot px, bars $bars px"
key v
key k
key d
wait_log "Speed distribution off"
shot 8-overlays-off
for c in $YELLOW $PLOT_RED $BARS; do
    n=$(color_in "$OUT/8-overlays-off.png" "$c")
    ((n == 0)) || fail "$c still on screen ($n px) after V, K, D off"
done
pass "V, K, D again hide their overlays"
key l  # trails: all -> off, so that later pixel checks see no trails
wait_log "Trails: off"

# --- 8. stepping modes ----------------------------------------------------------------------
key t
wait_log "\[I\] Mode: substep x4"
key t
wait_log "\[I\] Mode: exact"
key t
wait_log "\[I\] Mode: discrete"
pass "T cycles the modes: $(grep -o 'Mode: [a-z0-9 ]*' "$LOG" | paste -sd, -)"

# --- 9. reset to the scene as loaded ------------------------------------------------------
key r
wait_log "\[I\] Restarted: back to .* \(6 particles"
wait_title "6 particles - PAUSED"
pass "R restarts: $(grep 'Restarted: ' "$LOG" | tail -1)"

# --- 10. select: a click on the 12 kg particle at (1.5, 1.2) m -------------------------------
# One xdotool chain, so that the press and release are well within a click's 0.3 s.
xdotool mousemove --sync "$(sx 1.5)" "$(sy 1.2)" sleep 0.1 click 1
# The log counts y up from the floor as the window does (7 m box: 1.2 m down is 5.8 m up).
wait_log "\[I\] Selected particle [0-9]+ at \[1.50, 5.80\] m with velocity \[1.80, -1.20\] m/s, mass 12 kg, radius 0.3 m"
shot 6-selected
read -r _ _ outline < <(centroid "$OUT/6-selected.png" 255 230 0)
((outline > 50)) || fail "no selection outline on screen ($outline pixels)"
pass "click selects: $(grep 'Selected particle' "$LOG" | tail -1) (outline $outline px)"

# --- 11. edit its mass through the prompt ---------------------------------------------------
key Return
wait_log "\[I\] Editing particle"
# "2e1" is 20; its E must reach the prompt, not lower the restitution.
xdotool type --window "$WID" --delay 50 "2e1"
key Return
# The message is shown in the window, so with y up (the default) vy reads upward: the log's
# y-down 1.20 is -1.2.
wait_log "\[I\] Edited particle [0-9]+: mass 20 kg, radius 0.3 m, velocity \[1.8,.*-1.2\] m/s"
grep -q "Restitution" "$LOG" && fail "a letter typed into the prompt toggled a control"
key Return
xdotool type --window "$WID" --delay 50 " -1"  # a leading space: xdotool would take -1 for an option
key Return
wait_log "\[W\] Edit refused: mass: must be > 0 kg, got -1"
key Escape
wait_log "\[I\] Edit cancelled"
sleep 0.3
kill -0 "$APP_PID" 2>/dev/null || fail "Esc in the edit prompt quit the program"
pass "edit: $(grep 'Edited particle' "$LOG" | tail -1); refusal and Esc handled"

# --- 12. restitution and gravity ------------------------------------------------------------
key e
wait_log "\[I\] Restitution 0.95"
key shift+e
wait_log "\[I\] Restitution 1.00"
key g
wait_log "\[I\] Gravity \[0, -9.81\] m/s²"  # Earth's, not scaled by the box
# T with gravity on always moves on: substep, then exact (which has gravity too).
last_mode() { grep -E '\] Mode: ' "$LOG" | tail -1; }
key t
wait_count "\] Mode: substep" 2
modes=$(grep -c '\] Mode: ' "$LOG")
key t
wait_count "\] Mode: " $((modes + 1))
last_mode | grep -q "Mode: exact" ||
    fail "T with gravity on in substep: $(last_mode)"
pass "T with gravity on: $(grep -E '\] Mode: ' "$LOG" | tail -2 | paste -sd, -)"
for _ in 1 2 3; do last_mode | grep -q "Mode: discrete" && break; key t; done
key g
wait_log "\[I\] Gravity off"
modes=$(grep -c '\] Mode: ' "$LOG")
key t
key t
wait_count "\] Mode: " $((modes + 2))
last_mode | grep -q "Mode: exact" || fail "T T did not reach exact: $(last_mode)"
key g
wait_count "Gravity \[0, -9.81\] m/s²" 2
key g
wait_count "\[I\] Gravity off" 2
key t
wait_count "\] Mode: discrete" 3
pass "E, Shift+E, G, T with gravity, G in exact mode"

# --- 13. screenshot -------------------------------------------------------------------------
key F12
wait_log "\[I\] Saved screenshot "
png=$(grep "Saved screenshot" "$LOG" | tail -1 | sed -E 's/.*Saved screenshot (.*)$/\1/')
[[ -s "$png" ]] || fail "F12 wrote no file at '$png'"
[[ $(basename "$png") =~ ^particle-sandbox-[0-9]{8}-[0-9]{6}(-[0-9]+)?\.png$ ]] ||
    fail "screenshot name $(basename "$png")"
size=$(identify -format "%wx%h" "$png")
[[ "$size" == "${WIDTH}x$HEIGHT" ]] || fail "screenshot is $size, the window ${WIDTH}x$HEIGHT"
pass "F12: $(basename "$png"), $size"

# --- 14. R again undoes the edit ------------------------------------------------------------
key r
wait_count "Restarted: back to" 2
xdotool mousemove --sync "$(sx 1.5)" "$(sy 1.2)" sleep 0.1 click 1
wait_count "Selected particle" 2
grep "Selected particle" "$LOG" | tail -1 | grep -q "mass 12 kg" ||
    fail "after R the particle is not as loaded: $(grep 'Selected particle' "$LOG" | tail -1)"
pass "R restores the edited particle's 12 kg"

# --- 14b. pan the box off screen: a marker at the edge points to it; F brings it back ----------
for _ in $(seq 16); do xdotool key --window "$WID" Right; done
shot 9-panned-away
marker=$(color_in "$OUT/9-panned-away.png" "#FFE600")
((marker > 30)) || fail "no marker for the off-screen box ($marker px)"
key f
shot 9-fitted-again
((  $(white_in "$OUT/9-fitted-again.png" "$wall") >= 35 )) || fail "F did not bring the box back"
pass "box off screen: a $marker px marker points to it; F fits it again"

# --- 15. quit -----------------------------------------------------------------------------
# Esc closes the help first; with unsaved changes it asks in a dialog, where Esc is Cancel and
# D discards the changes and quits.
key h
key Escape
sleep 0.3
kill -0 "$APP_PID" 2>/dev/null || fail "Esc with the help open quit the program"
key m
wait_log "Spawned particle"
key Escape
wait_log "\[W\] Unsaved changes to .*: Save, Discard or Cancel"
shot 15-quit-dialog
press_until Escape "Quit cancelled"
sleep 0.3
kill -0 "$APP_PID" 2>/dev/null || fail "Esc with unsaved changes quit without asking"
pass "Esc closes the help, then asks before losing unsaved changes; Esc again cancels"
key Escape
wait_count "Unsaved changes to .*: Save, Discard or Cancel" 2
quit_with d
if kill -0 "$APP_PID" 2>/dev/null; then fail "Esc did not quit"; fi
wait "$APP_PID" && status=0 || status=$?
APP_PID=""
((status == 0)) || fail "exit status $status"
grep -q "Exiting" "$LOG" || fail "no exit line in the log"
pass "Esc quits with status 0"
echo "PASS"
