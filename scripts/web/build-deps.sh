#!/usr/bin/env bash
# Builds the web build's libraries for WebAssembly from the Debian source packages that
# fetch-sources.sh put in DIR/src: SDL2 (no threads), FreeType and SDL2_ttf (static, no
# HarfBuzz, no compressed fonts), installed into DIR/prefix; Dear ImGui is compiled by the
# project's own CMake from DIR/src/imgui-*. The header-only libraries (Eigen, nlohmann-json,
# CLI11, Boost, stb) are the machine's Debian -dev packages, linked into DIR/prefix/include so
# that the compiler never sees /usr/include (whose C library is not Emscripten's).
# Each library is built once: a stamp file in DIR/prefix skips it on the next run.
#   scripts/web/build-deps.sh DIR
set -euo pipefail
dir=$(realpath -m "$1")
src=$dir/src
prefix=$dir/prefix
work=$dir/build
jobs=$(nproc)
mkdir -p "$prefix/include" "$work"

one() {  # the one directory matching a glob
  local matches=("$@")
  [[ ${#matches[@]} -eq 1 && -d ${matches[0]} ]] || {
    echo "error: expected one source directory, found: ${matches[*]}" >&2
    exit 1
  }
  echo "${matches[0]}"
}

cmake_lib() {  # NAME SOURCE_DIR CMAKE_ARGS...
  local name=$1 source=$2
  shift 2
  [[ -f $prefix/.built-$name ]] && return 0
  echo "Building $name for WebAssembly" >&2
  rm -rf "$work/$name"
  emcmake cmake -S "$source" -B "$work/$name" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_FIND_ROOT_PATH="$prefix" \
    -DCMAKE_PREFIX_PATH="$prefix" -DBUILD_SHARED_LIBS=OFF "$@" >"$work/$name.log"
  cmake --build "$work/$name" -j"$jobs" >>"$work/$name.log"
  cmake --install "$work/$name" >>"$work/$name.log"
  touch "$prefix/.built-$name"
}

cmake_lib sdl2 "$(one "$src"/libsdl2-[0-9]*/)" \
  -DSDL_SHARED=OFF -DSDL_STATIC=ON -DSDL_THREADS=OFF -DSDL_TEST=OFF
cmake_lib freetype "$(one "$src"/freetype-[0-9]*/)" \
  -DFT_DISABLE_ZLIB=ON -DFT_DISABLE_BZIP2=ON -DFT_DISABLE_PNG=ON -DFT_DISABLE_HARFBUZZ=ON \
  -DFT_DISABLE_BROTLI=ON
cmake_lib sdl2-ttf "$(one "$src"/libsdl2-ttf-[0-9]*/)" \
  -DSDL2TTF_VENDORED=OFF -DSDL2TTF_HARFBUZZ=OFF -DSDL2TTF_SAMPLES=OFF

# The header-only libraries, by name only.
for h in eigen3 nlohmann CLI boost stb; do
  [[ -e /usr/include/$h ]] || { echo "error: /usr/include/$h missing (scripts/install-deps.sh)" >&2; exit 1; }
  ln -sfn "/usr/include/$h" "$prefix/include/$h"
done
