#!/usr/bin/env bash
# Runs the benchmark suite and regenerates the figures of docs/performance.md.
#   scripts/bench.sh [REPETITIONS]     (default 3; the whole run takes a few minutes)
# Writes docs/perf/bench_gas.json, docs/perf/bench_box2d.json (if Box2D is installed),
# docs/perf/cost-per-particle-step.svg and docs/perf/tables.md.
set -euo pipefail
cd "$(dirname "$0")/.."
reps="${1:-3}"
cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DPSB_BUILD_APP=OFF -DPSB_BUILD_TESTS=OFF >/dev/null
cmake --build build/bench -j2 --target bench_gas $(test -f /usr/include/box2d/box2d.h && echo bench_box2d)
mkdir -p docs/perf
common=(--benchmark_repetitions="$reps" --benchmark_min_time=0.05 --benchmark_out_format=json)
build/bench/bench/bench_gas "${common[@]}" --benchmark_out=docs/perf/bench_gas.json
jsons=(docs/perf/bench_gas.json)
if [[ -x build/bench/bench/bench_box2d ]]; then
  build/bench/bench/bench_box2d "${common[@]}" --benchmark_out=docs/perf/bench_box2d.json
  jsons+=(docs/perf/bench_box2d.json)
fi
scripts/plot_performance.py docs/perf/cost-per-particle-step.svg "${jsons[@]}" > docs/perf/tables.md
cat docs/perf/tables.md
