#!/usr/bin/env bash
# End-to-end test of video recording: the real program in a virtual X display (Xvfb), driven
# with real X input (xdotool); each video it writes is read back with ffprobe, its frames
# counted and its size and rate checked, and a frame of it looked at.
#
#   tests/e2e/video_e2e.sh PATH/TO/particle-sandbox [OUTPUT_DIR]
#
#   1. Ctrl+R                           -> "Recording video (MP4, WxH, 60 frames/s) to PATH",
#                                          the REC mark on the screen (F12's text and pixels)
#   2. about 2 s running, Ctrl+R        -> "Saved video PATH: S s, N frames, WxH"; ffprobe
#                                          reads N H.264 frames of WxH at 60/s, about S s long;
#                                          the REC mark is not in the video
#   3. the Video section: GIF, with the panel, Record video, about 1.5 s, Stop video
#                                       -> a GIF of the whole window, at most 640 px wide,
#                                          25 frames a second, with its frames all there
#   4. --record webm at launch, Esc     -> quitting completes the WebM (VP8); no part file left
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/harness.sh"
e2e_begin video "$@"
rm -rf "$OUT/videos"
mkdir -p "$OUT/videos"

# probe FILE FIELD: one field of the video stream, frames counted by decoding them.
probe() {
    ffprobe -v error -count_frames -select_streams v:0 \
        -show_entries "stream=$2" -of default=nw=1:nk=1 "$1"
}

start_xvfb "$OUT/xvfb.log" 1100x900x24 || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy
LOG="$OUT/stdout.log"
start_app "$BIN" --renderer software --window 1000x800 --log-controls --screenshot-dir "$OUT/videos"
wait_log "\[I\] Control section Video at"
pass "window at $WX,$WY size ${WIDTH}x$HEIGHT"

# --- 1. Ctrl+R records, and the screen says so -------------------------------------------------
key ctrl+r
wait_log "Recording video \(MP4, [0-9]+x[0-9]+, [0-9]+ frames/s\) to $OUT/videos/.*\.mp4: Ctrl\+R stops"
sleep 0.5
snap 1-recording
section 1-recording Recording | grep -q "^REC 0:0[0-9] MP4 - Ctrl+R stops" ||
    fail "no REC mark on the screen: $(section 1-recording Recording)"
# The mark is drawn: its red dot is in the window's top-right corner (below the HUD when the
# HUD reaches the corner).
red=$(convert "$OUT/1-recording.png" -crop "300x120+$((WIDTH - 300))+0" +repage \
    -fill black +opaque "rgb(235,60,50)" -fill white -opaque "rgb(235,60,50)" \
    -format "%[fx:int(mean*w*h+0.5)]" info:)
((red > 10)) || fail "the REC mark's red dot is not drawn ($red pixels)"
pass "Ctrl+R records; the screen shows '$(section 1-recording Recording)'"

# --- 2. Ctrl+R stops: the file is whole and what it says ----------------------------------------
sleep 2
key ctrl+r
wait_log "Saved video $OUT/videos/.*\.mp4: [0-9.]+ s, [0-9]+ frames, [0-9]+x[0-9]+"
saved=$(grep "Saved video" "$LOG" | tail -1)
read -r file seconds frames size < <(sed -E 's/.*Saved video (.*): ([0-9.]+) s, ([0-9]+) frames, ([0-9x]+).*/\1 \2 \3 \4/' <<<"$saved")
[[ -f "$file" ]] || fail "no file at $file"
[[ -e "$file.part" ]] && fail "the part file is left: $file.part"
[[ "$(probe "$file" codec_name)" == h264 ]] || fail "not H.264: $(probe "$file" codec_name)"
[[ "$(probe "$file" r_frame_rate)" =~ ^(60|[0-9]+)/1$ ]] || fail "rate $(probe "$file" r_frame_rate)"
read_frames=$(probe "$file" nb_read_frames)
((read_frames == frames)) || fail "ffprobe reads $read_frames frames, the app said $frames"
w=$(probe "$file" width)
h=$(probe "$file" height)
[[ "${w}x$h" == "$size" ]] || fail "ffprobe reads ${w}x$h, the app said $size"
# About 2.5 s. The window keeps the display's 60 Hz when the machine lets it; a loaded one
# draws fewer frames, and then the message says how many a second the video has.
awk -v s="$seconds" -v n="$frames" 'BEGIN { exit !(s > 2 && s < 6 && n > 20 * s) }' ||
    fail "$frames frames in $seconds s"
if awk -v s="$seconds" -v n="$frames" 'BEGIN { exit !(n < 0.9 * 60 * s) }'; then
    grep -q "frames a second of [0-9]*: the window drew no faster" <<<"$saved" ||
        fail "$frames frames in $seconds s, and the message does not say the rate: $saved"
fi
ffmpeg -v error -y -sseof -0.5 -i "$file" -frames:v 1 "$OUT/2-video-frame.png"
vred=$(convert "$OUT/2-video-frame.png" -crop "300x120+$((w - 300))+0" +repage \
    -fuzz 8% -fill black +opaque "rgb(235,60,50)" -fill white -opaque "rgb(235,60,50)" \
    -format "%[fx:int(mean*w*h+0.5)]" info:)
((vred < 5)) || fail "the REC mark is in the video ($vred red pixels)"
pass "$(sed -E 's/^\[I\] //' <<<"$saved"); ffprobe reads $read_frames H.264 frames of ${w}x$h"

# --- 3. the Video section: a GIF of the whole window --------------------------------------------
for s in Time Physics Show Readouts; do click "section $s"; done
click "section Video"
wait_log "\[I\] Control Record video at"
click "video format"
sleep 0.3
# The combo's list opens below it: MP4, WebM, GIF, one line each.
read -r fx fy < <(ctl "video format")
xdotool mousemove --sync "$fx" "$((fy + 3 * 22))" sleep 0.2 click 1
sleep 0.3
click "video with panel"
click "Record video"
wait_log "Recording video \(GIF, ${WIDTH}x$HEIGHT, 25 frames/s\) to $OUT/videos/.*\.gif"
sleep 1.5
click "Record video"
wait_log "Saved video $OUT/videos/.*\.gif: [0-9.]+ s, [0-9]+ frames, 640x[0-9]+"
saved=$(grep "Saved video" "$LOG" | tail -1)
read -r gif gseconds gframes gsize < <(sed -E 's/.*Saved video (.*): ([0-9.]+) s, ([0-9]+) frames, ([0-9x]+).*/\1 \2 \3 \4/' <<<"$saved")
[[ "$(probe "$gif" codec_name)" == gif ]] || fail "not a GIF: $(probe "$gif" codec_name)"
((gframes == $(probe "$gif" nb_read_frames))) || fail "the GIF's frames: $(probe "$gif" nb_read_frames) of $gframes"
[[ "$(probe "$gif" width)x$(probe "$gif" height)" == "$gsize" ]] || fail "the GIF's size"
awk -v s="$gseconds" -v n="$gframes" 'BEGIN { exit !(n > 10 * s) }' ||
    fail "$gframes GIF frames in $gseconds s"
ffmpeg -v error -y -i "$gif" -vf "select=eq(n\,$((gframes / 2)))" -frames:v 1 "$OUT/3-gif-frame.png"
pass "$(sed -E 's/^\[I\] //' <<<"$saved")"

# --- 4. --record at launch; quitting completes the file ----------------------------------------
quit_by_esc
wait_exit
kill -0 "$APP_PID" 2>/dev/null && fail "Esc, Enter did not quit"
APP_PID=""
LOG="$OUT/stdout-webm.log"
start_app "$BIN" --renderer software --window 800x600 --screenshot-dir "$OUT/videos" --record webm
wait_log "Recording video \(WebM, "
sleep 1.5
quit_by_esc
wait_exit
kill -0 "$APP_PID" 2>/dev/null && fail "Esc, Enter did not quit while recording"
APP_PID=""
wait_log "Saved video $OUT/videos/.*\.webm: [0-9.]+ s, [0-9]+ frames"
webm=$(grep "Saved video" "$LOG" | tail -1 | sed -E 's/.*Saved video (.*): [0-9.]+ s.*/\1/')
[[ "$(probe "$webm" codec_name)" == vp8 ]] || fail "not VP8: $(probe "$webm" codec_name)"
(($(probe "$webm" nb_read_frames) > 30)) || fail "the WebM has $(probe "$webm" nb_read_frames) frames"
compgen -G "$OUT/videos/*.part" >/dev/null && fail "part files left: $(ls "$OUT"/videos/*.part)"
pass "--record webm, Esc: $(grep "Saved video" "$LOG" | tail -1 | sed -E 's/^\[I\] //')"
