#!/usr/bin/env bash
# Installs the Debian packages Particle Sandbox needs, skipping those already present.
#   scripts/install-deps.sh          build dependencies (compiler, CMake, ccache, libraries,
#                                    pybind11 and NumPy for the Python module)
#   scripts/install-deps.sh --test   also what the tests need (Xvfb, xdotool, ImageMagick, xclip,
#                                    ffprobe (ffmpeg) to read the recorded videos back,
#                                    clang with libFuzzer for the fuzz targets, and for the
#                                    install test man, desktop-file-validate, file (which
#                                    CPack's dependency scan uses), lintian and mmdebstrap,
#                                    pytest, pandas, Dask and Matplotlib for the Python module's
#                                    tests, nbclient and ipykernel to run its notebooks),
#                                    and what the web build and its test need (--web)
#   scripts/install-deps.sh --web    build dependencies and the web build's: Emscripten,
#                                    dpkg-dev (apt-get source unpacks with it), Chromium, npm
set -euo pipefail

packages=(
  build-essential cmake pkg-config ccache
  libeigen3-dev libsdl2-dev libsdl2-ttf-dev libstb-dev libimgui-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev libcli11-dev libboost-dev
  libtbb-dev libbox2d-dev
  libavcodec-dev libavformat-dev libavfilter-dev libavutil-dev libswscale-dev
  python3-dev python3-pybind11 pybind11-dev python3-numpy
)
web_packages=(emscripten dpkg-dev chromium)
# npm installs playwright-core for the web test; a Node.js from elsewhere brings its own npm.
command -v npm >/dev/null || web_packages+=(npm)
if [[ "${1:-}" == "--web" ]]; then
  packages+=("${web_packages[@]}")
fi
if [[ "${1:-}" == "--test" ]]; then
  packages+=("${web_packages[@]}")
  packages+=(xvfb xauth xdotool imagemagick x11-utils xclip ffmpeg)
  packages+=(clang libclang-rt-14-dev)
  packages+=(man-db desktop-file-utils file lintian mmdebstrap)
  packages+=(python3-pytest python3-pandas python3-dask python3-distributed python3-matplotlib)
  packages+=(python3-nbclient python3-nbformat python3-ipykernel)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "Installing: ${missing[*]}" >&2
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "error: need root or sudo to install ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
