#!/usr/bin/env bash
# The web build: the sandbox as a static page (docs/web.md).
#   scripts/web.sh build          install what is missing, build the page into build/web/
#   scripts/web.sh serve [PORT]   serve build/web/ on localhost (default port 8080)
#   scripts/web.sh test           build, then test the page in headless Chromium (tests/web/)
#   scripts/web.sh bench N...     the page's frame-time benchmark in headless Chromium, N particles
# The libraries built for WebAssembly are kept outside the checkout, in
# ${XDG_CACHE_HOME:-~/.cache}/particle-sandbox/web-deps-KEY (PSB_WEB_DEPS names another folder),
# KEY a digest of the scripts that fetch and build them, Emscripten's version and the Debian
# release: a fresh clone reuses them, a change to any of those builds them anew (delete the folder
# to rebuild them). The program's CMake tree is build/web-cmake/.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
cache=${XDG_CACHE_HOME:-$HOME/.cache}
[[ $cache == /* ]] || cache=$HOME/.cache
deps_key() {
  {
    cat scripts/web/fetch-sources.sh scripts/web/build-deps.sh
    emcc --version 2>/dev/null | head -n 1
    . /etc/os-release && echo "${VERSION_CODENAME:-}"
  } | sha256sum | cut -c1-12
}
tree=$root/build/web-cmake
out=$root/build/web

# Emscripten's tools run on Node.js and need Debian's node-acorn; a node from elsewhere does not
# look in Debian's module folder by itself.
export NODE_PATH=${NODE_PATH:+$NODE_PATH:}/usr/share/nodejs

build() {
  scripts/install-deps.sh --web
  deps=${PSB_WEB_DEPS:-$cache/particle-sandbox/web-deps-$(deps_key)}
  echo "Libraries for WebAssembly: $deps"
  scripts/web/fetch-sources.sh "$deps"
  scripts/web/build-deps.sh "$deps"
  # No video recording in the page (it would need FFmpeg built for WebAssembly).
  emcmake cmake -S . -B "$tree" -DCMAKE_BUILD_TYPE=Release -DPSB_WEB_DEPS="$deps" \
    -DPSB_BUILD_TESTS=OFF -DPSB_BUILD_BENCH=OFF -DPSB_WARNINGS_AS_ERRORS=ON -DPSB_VIDEO=OFF \
    --no-warn-unused-cli >/dev/null
  cmake --build "$tree" -j"$(nproc)" --target particle-sandbox
  mkdir -p "$out"
  for f in index.html particle-sandbox.js particle-sandbox.wasm particle-sandbox.data; do
    cp -p "$tree/src/app/$f" "$out/$f"
  done
  echo "The page: $out (scripts/web.sh serve)"
  ls -l "$out" | awk 'NR > 1 { printf "  %-24s %9d bytes\n", $9, $5 }'
}

case "${1:-}" in
  build) build ;;
  serve)
    [[ -f $out/index.html ]] || { echo "error: no page in $out: scripts/web.sh build" >&2; exit 1; }
    exec python3 scripts/web/serve.py "$out" "${2:-8080}"
    ;;
  test)
    build
    # The desktop runner reads back the scene the page saves.
    if [[ -z ${PSB_SIM:-} ]]; then
      cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release >/dev/null
      cmake --build build/release -j"$(nproc)" --target particle-sim
      export PSB_SIM=$root/build/release/src/cli/particle-sim
    fi
    exec tests/web/run.sh
    ;;
  bench)
    shift
    [[ $# -gt 0 ]] || { echo "usage: scripts/web.sh bench N..." >&2; exit 2; }
    build
    exec tests/web/run.sh bench "$@"
    ;;
  *)
    sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//' >&2
    exit 2
    ;;
esac
