#!/usr/bin/env bash
# Installs what is missing, builds the sandbox and particle-sim in Release and launches the
# sandbox on its default scene.
# Arguments are passed to particle-sandbox (try --help).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/release -j"$(nproc)" --target particle-sandbox particle-sim
exec build/release/src/app/particle-sandbox "$@"
