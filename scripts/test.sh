#!/usr/bin/env bash
# Installs what is missing, builds everything with warnings as errors, and runs every test, in
# four stages over three trees (docs/testing.md explains each and lists measured durations):
#   release  build/test   Release: unit, rendering, end-to-end under Xvfb, the soak run
#   install  build/test   the same tree installed into a staging prefix and packaged as .debs,
#                         checked from outside (tests/install/install_test.sh)
#   asan     build/asan   ASan + UBSan + LeakSanitizer, -O1 -g: the same tests except those
#                         labelled e2e or bench (why: see below)
#   fuzz     build/fuzz   clang + libFuzzer: each fuzz target for PSB_FUZZ_SECONDS (default 60)
#   web      build/web-cmake  the web build (scripts/web.sh), tested in headless Chromium
#                         (tests/web/); its libraries built for WebAssembly are kept in
#                         ~/.cache/particle-sandbox (scripts/web.sh), for the next clone too
# Any failure, sanitizer report or fuzzer crash fails the script.
#   scripts/test.sh [CTEST ARGS...]     extra arguments go to the release and asan ctest runs
#   PSB_TEST_STAGES="release asan" scripts/test.sh   runs only the stages named
#   PSB_SKIP_CLEAN_ROOT=1 scripts/test.sh   the install stage without its clean-root install
#                                           (which downloads Debian packages)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
stages=" ${PSB_TEST_STAGES:-release install asan fuzz web} "
jobs=$(nproc)
scripts/install-deps.sh --test

stage() { printf '\n=== %s (%s)\n' "$1" "$(date -u +%H:%M:%S)"; }

if [[ $stages == *" release "* ]]; then
  stage "release build and tests"
  cmake -S . -B build/test -DCMAKE_BUILD_TYPE=Release -DPSB_WARNINGS_AS_ERRORS=ON >/dev/null
  cmake --build build/test -j"$jobs"
  ctest --test-dir build/test --output-on-failure -j"$jobs" "$@"
fi

if [[ $stages == *" install "* ]]; then
  stage "install, package and run from outside"
  # The release tree again (a no-op after the release stage), so the stage also runs alone.
  cmake -S . -B build/test -DCMAKE_BUILD_TYPE=Release -DPSB_WARNINGS_AS_ERRORS=ON >/dev/null
  cmake --build build/test -j"$jobs"
  tests/install/install_test.sh build/test build/test/install-test
fi

if [[ $stages == *" asan "* ]]; then
  stage "sanitizer build and tests"
  # -O1 keeps the run fast enough and the stack traces readable; Debug keeps assertions on;
  # -g1 (line tables, no variables) is all a sanitizer's stack trace reads, and compiles faster.
  cmake -S . -B build/asan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
    -DPSB_SANITIZE=ON -DPSB_WARNINGS_AS_ERRORS=ON -DPSB_BUILD_BENCH=OFF >/dev/null
  cmake --build build/asan -j"$jobs"
  # Leak detection stays on. tests/sanitizers/lsan.supp only names leaks inside system
  # libraries (SDL's video and font stack), never our code.
  export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1"
  export LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  # Left out, and why:
  #   e2e   drives the real program under Xvfb with xdotool and timed waits tuned to Release
  #         frame times; the code it exercises runs under the sanitizers in app_tests.
  #   bench timings under ASan mean nothing (and the tree is built without benchmarks); the
  #         benchmark smoke run is in the release stage.
  ctest --test-dir build/asan --output-on-failure -j"$jobs" -LE 'e2e|bench' "$@"
fi

if [[ $stages == *" fuzz "* ]]; then
  stage "fuzzers (${PSB_FUZZ_SECONDS:-60} s each)"
  CXX=clang++ cmake -S . -B build/fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPSB_BUILD_FUZZ=ON \
    -DPSB_BUILD_TESTS=OFF -DPSB_BUILD_APP=OFF -DPSB_BUILD_BENCH=OFF -DPSB_WARNINGS_AS_ERRORS=ON \
    -DPSB_FUZZ_SECONDS="${PSB_FUZZ_SECONDS:-60}" >/dev/null
  cmake --build build/fuzz -j"$jobs"
  # As many at once as there are cores: each fuzzer wants a whole core, and its run time is
  # fixed (on two cores the four take two minutes, not four).
  ctest --test-dir build/fuzz --output-on-failure -L fuzz -j"$jobs"
fi
if [[ $stages == *" web "* ]]; then
  stage "web build and browser test"
  # The release tree's particle-sim reads back the scene the page saves (a no-op after the
  # release stage).
  cmake -S . -B build/test -DCMAKE_BUILD_TYPE=Release -DPSB_WARNINGS_AS_ERRORS=ON >/dev/null
  cmake --build build/test -j"$jobs" --target particle-sim
  PSB_SIM=$root/build/test/src/cli/particle-sim scripts/web.sh test
fi
stage "all tests passed"
