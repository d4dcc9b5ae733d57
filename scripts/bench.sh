#!/usr/bin/env bash
# Runs the benchmark suite and regenerates the figures of docs/performance.md.
#   scripts/bench.sh [REPETITIONS]     (default 3; the whole run takes a few minutes)
# Writes docs/perf/bench_gas.json, docs/perf/bench_box2d.json (if Box2D is installed),
# docs/perf/bench_spread.json, docs/perf/bench_gas_headline.json,
# docs/perf/cost-per-particle-step.svg, docs/perf/tables.md, docs/perf/spread.md and
# docs/perf/headline.md. Records the load average before and after in docs/perf/load.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
reps="${1:-3}"
cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DPSB_BUILD_APP=OFF -DPSB_BUILD_TESTS=OFF >/dev/null
cmake --build build/bench -j2 --target bench_gas $(test -f /usr/include/box2d/box2d.h && echo bench_box2d)
mkdir -p docs/perf
echo "before: $(cat /proc/loadavg)" > docs/perf/load.txt
trap 'echo "after: $(cat /proc/loadavg)" >> docs/perf/load.txt' EXIT
common=(--benchmark_repetitions="$reps" --benchmark_min_time=0.05 --benchmark_out_format=json)
build/bench/bench/bench_gas "${common[@]}" --benchmark_filter=-spread \
  --benchmark_out=docs/perf/bench_gas.json
jsons=(docs/perf/bench_gas.json)
if [[ -x build/bench/bench/bench_box2d ]]; then
  build/bench/bench/bench_box2d "${common[@]}" --benchmark_out=docs/perf/bench_box2d.json
  jsons+=(docs/perf/bench_box2d.json)
fi
scripts/plot_performance.py docs/perf/cost-per-particle-step.svg "${jsons[@]}" > docs/perf/tables.md
# Grid against quadtree where radii spread widely (the scene behind the `auto` rule).
build/bench/bench/bench_gas "${common[@]}" --benchmark_filter=^spread \
  --benchmark_out=docs/perf/bench_spread.json >/dev/null
scripts/plot_performance.py /dev/null docs/perf/bench_spread.json > docs/perf/spread.md
# The headline configurations again, 15 times each: on a shared machine the spread matters.
build/bench/bench/bench_gas --benchmark_filter='gas/grid/threads:./n:(10000|100000|1000000)/' \
  --benchmark_repetitions=15 --benchmark_out_format=json \
  --benchmark_out=docs/perf/bench_gas_headline.json >/dev/null
scripts/plot_performance.py /dev/null docs/perf/bench_gas_headline.json > docs/perf/headline.md
cat docs/perf/tables.md docs/perf/spread.md docs/perf/headline.md
