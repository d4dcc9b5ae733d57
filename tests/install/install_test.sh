#!/usr/bin/env bash
# Installs a built tree as a user or a packager would, and checks the result from the outside:
#
#   tests/install/install_test.sh BUILD_DIR [OUTPUT_DIR]     (BUILD_DIR: a whole build, app included)
#
#   1. cmake --install into a staging prefix: every file where desktops, man and CMake look
#   2. the desktop entry passes desktop-file-validate; its Exec and Icon exist in the prefix
#   3. both man pages render without groff warnings and name every option --help lists
#   4. from another directory: --version on both programs, the runner on an installed preset
#   5. the sandbox under Xvfb on an installed preset for a few frames, screenshot checked,
#      Esc quits with status 0; then the prefix moved elsewhere still finds its assets
#   6. examples/ and every public header built against the installed CMake package alone
#   7. cpack makes the .deb packages; lintian finds no error; the dependencies are sane
#   8. the .deb installed with apt into a clean Debian root (mmdebstrap), no source tree in
#      sight: both programs run there (skip with PSB_SKIP_CLEAN_ROOT=1, e.g. offline)
# The staging prefix, the screenshot, the packages and the logs are left in OUTPUT_DIR.
set -euo pipefail

BUILD=$(cd "${1:?usage: install_test.sh BUILD_DIR [OUTPUT_DIR]}" && pwd)
OUT=${2:-$BUILD/install-test}
HERE=$(cd "$(dirname "$0")" && pwd)
SRC=$(cd "$HERE/../.." && pwd)
rm -rf "$OUT"
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
STAGE=$OUT/stage
VERSION=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$BUILD/CMakeCache.txt")
[[ -n $VERSION ]] || { echo "FAIL: no project version in $BUILD/CMakeCache.txt" >&2; exit 1; }

fail() { echo "FAIL: $*" >&2; echo "(logs in $OUT)" >&2; exit 1; }
source "$SRC/tests/e2e/harness.sh"

# --- 1. the staging install ---------------------------------------------------------------
cmake --install "$BUILD" --prefix "$STAGE" >"$OUT/install.log"
expected=(
    bin/particle-sandbox bin/particle-sim
    share/particle-sandbox/fonts/DejaVuSans.ttf share/particle-sandbox/fonts/DejaVuSansMono.ttf
    share/particle-sandbox/scenes/01-original.json share/applications/particle-sandbox.desktop
    share/icons/hicolor/scalable/apps/particle-sandbox.svg
    share/man/man1/particle-sandbox.1.gz share/man/man1/particle-sim.1.gz
    share/doc/particle-sandbox/README.md share/doc/particle-sandbox/LICENSE
    share/doc/particle-sandbox/LICENSE-DejaVu.txt share/doc/particle-sandbox/copyright
    share/doc/particle-sandbox/changelog.gz share/doc/particle-sandbox/docs/scenes.md
    include/particle_sandbox/world.hpp
)
for size in 16 22 24 32 48 64 128 256 512; do
    expected+=("share/icons/hicolor/${size}x$size/apps/particle-sandbox.png")
done
for f in "${expected[@]}"; do [[ -f $STAGE/$f ]] || fail "not installed: $f"; done
[[ -n $(find "$STAGE" -path '*/cmake/ParticleSandbox/ParticleSandboxConfig.cmake') ]] ||
    fail "no ParticleSandboxConfig.cmake"
[[ -n $(find "$STAGE" -name 'libparticle_sandbox_core.a') ]] || fail "no core library"
scenes=$(find "$SRC/assets/scenes" -name '*.json' | wc -l)
installed_scenes=$(find "$STAGE/share/particle-sandbox/scenes" -name '*.json' | wc -l)
((scenes == installed_scenes)) || fail "$installed_scenes of $scenes preset scenes installed"
for size in 16 22 24 32 48 64 128 256 512; do
    got=$(identify -format '%wx%h' "$STAGE/share/icons/hicolor/${size}x$size/apps/particle-sandbox.png")
    [[ $got == "${size}x$size" ]] || fail "the ${size}x$size icon is $got"
done
# The changelog's latest entry is this version (a version bump needs its entry).
top=$(zcat "$STAGE/share/doc/particle-sandbox/changelog.gz" | head -1)
[[ $top == "particle-sandbox ($VERSION) "* ]] || fail "changelog.gz starts '$top', not version $VERSION"
# The README's links into docs/ resolve in the installed copy.
while read -r link; do
    [[ -e $STAGE/share/doc/particle-sandbox/$link ]] || fail "README links $link, not installed"
done < <(grep -o '](docs/[^)#]*' "$SRC/README.md" | sed 's/^](//' | sort -u)
pass "installed ${#expected[@]} checked files, $installed_scenes scenes, 9 icon sizes"

# --- 2. the desktop entry -----------------------------------------------------------------
desktop=$STAGE/share/applications/particle-sandbox.desktop
desktop-file-validate "$desktop" >"$OUT/desktop-file-validate.log" 2>&1 ||
    fail "desktop-file-validate: $(cat "$OUT/desktop-file-validate.log")"
[[ ! -s $OUT/desktop-file-validate.log ]] || fail "desktop-file-validate: $(cat "$OUT/desktop-file-validate.log")"
exec_name=$(sed -n 's/^Exec=\([^ ]*\).*/\1/p' "$desktop")
icon_name=$(sed -n 's/^Icon=//p' "$desktop")
[[ -x $STAGE/bin/$exec_name ]] || fail "Exec=$exec_name is not in bin/"
[[ -f $STAGE/share/icons/hicolor/48x48/apps/$icon_name.png ]] || fail "Icon=$icon_name not found"
pass "desktop entry valid: Exec=$exec_name, Icon=$icon_name"

# --- 3. the man pages ---------------------------------------------------------------------
for prog in particle-sandbox particle-sim; do
    page=$STAGE/share/man/man1/$prog.1.gz
    LC_ALL=C.UTF-8 MANWIDTH=80 man --warnings -E UTF-8 -l "$page" >"$OUT/$prog.1.txt" 2>"$OUT/$prog.man.err" ||
        fail "man $prog: $(cat "$OUT/$prog.man.err")"
    [[ ! -s $OUT/$prog.man.err ]] || fail "man $prog warns: $(cat "$OUT/$prog.man.err")"
    grep -q "^NAME" "$OUT/$prog.1.txt" || fail "man $prog has no NAME section"
    # Every long option the program lists is documented.
    "$STAGE/bin/$prog" --help >"$OUT/$prog.help.txt"
    for opt in $(grep -oE -- '--[a-z][a-z-]*' "$OUT/$prog.help.txt" | sort -u); do
        grep -qE -- "(^|[^a-z-])$opt([^a-z-]|$)" "$OUT/$prog.1.txt" ||
            fail "man $prog does not document $opt"
    done
done
pass "man pages render cleanly and document every option"

# --- 4. the installed programs, from another directory -------------------------------------
elsewhere=$OUT/elsewhere
mkdir -p "$elsewhere"
cd "$elsewhere"
version_re="^(particle-sandbox|particle-sim) ${VERSION//./\\.}( \\(git [0-9a-f]{12}(-dirty)?\\))?$"
for prog in particle-sandbox particle-sim; do
    v=$("$STAGE/bin/$prog" --version)
    [[ $v =~ $version_re && $v == "$prog "* ]] || fail "$prog --version says '$v'"
done
pass "--version: $v"
cradle=$STAGE/share/particle-sandbox/scenes/02-newtons-cradle.json
"$STAGE/bin/particle-sim" "$cradle" --duration 2 --report report.json --timeseries ts.csv \
    2>"$OUT/particle-sim.err" || fail "particle-sim on an installed preset: $(cat "$OUT/particle-sim.err")"
grep -Eq '"collisions": [1-9]' report.json || fail "the cradle run reports no collisions"
[[ $(wc -l <ts.csv) -gt 2 ]] || fail "no time series"
pass "particle-sim ran the installed Newton's cradle: $(grep -o '"collisions": [0-9]*' report.json)"

# --- 5. the sandbox under Xvfb ------------------------------------------------------------
start_xvfb "$OUT/xvfb.log" 640x560x24 || fail "could not start Xvfb"
export SDL_AUDIODRIVER=dummy
export XDG_CONFIG_HOME="$OUT/config"  # the settings file, if written: not the user's
env -u PSB_ASSETS_DIR "$STAGE/bin/particle-sandbox" \
    "$STAGE/share/particle-sandbox/scenes/03-billiards-break.json" --renderer software \
    --window 600x500 --screenshot-dir "$elsewhere" >"$OUT/sandbox.log" 2>"$OUT/sandbox.err" &
APP_PID=$!
WID=$(timeout 20 xdotool search --sync --onlyvisible --pid "$APP_PID" --name "Particle Sandbox" |
    head -1) || fail "no window within 20 s: $(tail -5 "$OUT/sandbox.err")"
sleep 1.5  # some frames of the break
import -window "$WID" "$OUT/installed-sandbox.png"
xdotool windowfocus --sync "$WID" 2>/dev/null || true
# Nothing unsaved: Esc asks whether to quit, Enter quits.
LOG="$OUT/sandbox.log"
quit_by_esc
status=0
wait "$APP_PID" || status=$?
APP_PID=""
((status == 0)) || fail "the installed sandbox exited with $status: $(tail -5 "$OUT/sandbox.err")"
# The picture: the HUD's white text at the top right of the control panel (the fonts were
# found), and the billiard balls' colours in the box.
hud_white=$(convert "$OUT/installed-sandbox.png" -crop 280x60+320+0 -fuzz 10% -fill black \
    +opaque white -format '%[fx:int(mean*w*h)]' info:)
colours=$(convert "$OUT/installed-sandbox.png" -format '%k' info:)
((hud_white > 100)) || fail "no HUD text in the screenshot ($hud_white white pixels)"
((colours > 20)) || fail "the screenshot has only $colours colours"
pass "sandbox ran from $elsewhere on an installed preset: $hud_white HUD pixels, $colours colours, Esc -> 0"

# A moved prefix still finds its own assets (relative to the executable, not a fixed path).
mv "$STAGE" "$OUT/moved"
footer=$(cd / && "$OUT/moved/bin/particle-sandbox" --help | tail -1)
mv "$OUT/moved" "$STAGE"
[[ $footer == *"$OUT/moved/share/particle-sandbox" ]] || fail "moved install reads assets from: $footer"
pass "a moved prefix reads its own assets: ${footer##* }"
cd "$OUT"

# --- 6. the CMake package: the example and every public header -----------------------------
cmake -S "$SRC/examples" -B "$OUT/example" -DCMAKE_PREFIX_PATH="$STAGE" \
    -DCMAKE_BUILD_TYPE=Release >"$OUT/example.log" 2>&1 || fail "example configure: $(tail "$OUT/example.log")"
cmake --build "$OUT/example" >>"$OUT/example.log" 2>&1 || fail "example build: $(tail "$OUT/example.log")"
"$OUT/example/head-on-collision" >"$OUT/example.out" || fail "example: $(cat "$OUT/example.out")"
pass "examples/ built against the installed package: $(sed -n 2p "$OUT/example.out")"
cmake -S "$HERE/headers" -B "$OUT/headers" -DCMAKE_PREFIX_PATH="$STAGE" \
    >"$OUT/headers.log" 2>&1 || fail "header check configure: $(tail "$OUT/headers.log")"
cmake --build "$OUT/headers" -j2 >>"$OUT/headers.log" 2>&1 ||
    fail "a public header does not compile on its own: $(grep -m5 -B2 error "$OUT/headers.log")"
pass "every installed public header compiles on its own: $(grep -c '^#include' "$OUT/headers/all_headers.txt") headers"

# --- 7. the .deb packages -----------------------------------------------------------------
(cd "$BUILD" && cpack -G DEB -B "$OUT/deb" >"$OUT/cpack.log" 2>&1) || fail "cpack: $(tail "$OUT/cpack.log")"
deb=$(ls "$OUT"/deb/particle-sandbox_"$VERSION"_*.deb)
devdeb=$(ls "$OUT"/deb/libparticle-sandbox-dev_"$VERSION"_*.deb)
depends=$(dpkg-deb -f "$deb" Depends)
for lib in libc6 libstdc++6 libsdl2-2.0-0 libsdl2-ttf-2.0-0; do
    [[ $depends == *"$lib "* ]] || fail "the .deb does not depend on $lib: $depends"
done
dpkg-deb -c "$deb" >"$OUT/deb-contents.txt"
grep -q './usr/bin/particle-sandbox$' "$OUT/deb-contents.txt" || fail "no /usr/bin/particle-sandbox in $deb"
# The Python module's package, where the tree builds the module (PSB_BUILD_PYTHON).
pydeb=$(ls "$OUT"/deb/python3-particle-sandbox_"$VERSION"_*.deb 2>/dev/null || true)
if [[ -n $pydeb ]]; then
    [[ $(dpkg-deb -f "$pydeb" Depends) == *python3-numpy* ]] ||
        fail "$(basename "$pydeb") does not depend on python3-numpy: $(dpkg-deb -f "$pydeb" Depends)"
    dpkg-deb -c "$pydeb" >"$OUT/pydeb-contents.txt"
    grep -q '/usr/lib/python3/dist-packages/particle_sandbox/_core\..*\.so$' "$OUT/pydeb-contents.txt" ||
        fail "no compiled module in $(basename "$pydeb")"
fi
# shellcheck disable=SC2086 # $pydeb: no word when there is no such package
lintian --fail-on error --allow-root "$deb" "$devdeb" $pydeb >"$OUT/lintian.log" 2>&1 ||
    fail "lintian: $(grep -E '^E:' "$OUT/lintian.log" || tail "$OUT/lintian.log")"
pass "$(basename "$deb") (Depends: $depends), lintian: $(grep -c '^E:' "$OUT/lintian.log" || true) errors, $(grep -c '^W:' "$OUT/lintian.log" || true) warnings"

# --- 8. the .deb in a clean Debian root ---------------------------------------------------
if [[ ${PSB_SKIP_CLEAN_ROOT:-0} == 1 ]]; then
    echo "skipped: the clean-root install (PSB_SKIP_CLEAN_ROOT=1)"
    exit 0
fi
suite=$(. /etc/os-release && echo "$VERSION_CODENAME")
root=$OUT/clean-root
# Inside the root apt resolves the packages' dependencies from Debian alone; then the programs
# run with nothing from this machine but the two packages (no source tree, no build tree).
cat >"$OUT/clean-root-check.sh" <<'CHECK'
set -e
particle-sim --version
particle-sim /usr/share/particle-sandbox/scenes/02-newtons-cradle.json --duration 1 --report /tmp/r.json
grep -q '"collisions"' /tmp/r.json
echo "particle-sim ran the cradle"
particle-sandbox --version
particle-sandbox --help | tail -1
cd /tmp
SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy particle-sandbox --bench 200 --frames 10
find /usr/lib -name ParticleSandboxConfig.cmake | grep -q .
CHECK
debs=("$deb" "$devdeb")
if [[ -n $pydeb ]]; then
    debs+=("$pydeb")
    cat >>"$OUT/clean-root-check.sh" <<'CHECK'
python3 -c "import particle_sandbox as ps; w = ps.World(ps.load_scene('/usr/share/particle-sandbox/scenes/02-newtons-cradle.json')); w.run(1.0); print('particle_sandbox ran the cradle:', w)"
CHECK
fi
in_root=()
for d in "${debs[@]}"; do in_root+=("/tmp/$(basename "$d")"); done
mmdebstrap --variant=apt --mode=root \
    --customize-hook="copy-in ${debs[*]} $OUT/clean-root-check.sh /tmp" \
    --customize-hook="chroot \"\$1\" apt-get install -y --no-install-recommends ${in_root[*]}" \
    --customize-hook="chroot \"\$1\" sh /tmp/clean-root-check.sh >$OUT/clean-root.out 2>&1" \
    "$suite" "$root" >"$OUT/mmdebstrap.log" 2>&1 ||
    fail "clean root: $(tail -5 "$OUT/mmdebstrap.log"; cat "$OUT/clean-root.out" 2>/dev/null)"
rm -rf "$root"
grep -q "read from /usr/share/particle-sandbox" "$OUT/clean-root.out" ||
    fail "in the clean root the sandbox does not read /usr/share/particle-sandbox: $(cat "$OUT/clean-root.out")"
if [[ -n $pydeb ]]; then
    grep -q "particle_sandbox ran the cradle" "$OUT/clean-root.out" ||
        fail "in the clean root the Python module does not run: $(cat "$OUT/clean-root.out")"
fi
pass "installed with apt in a clean $suite root; both programs run there${pydeb:+, and the Python module}"
