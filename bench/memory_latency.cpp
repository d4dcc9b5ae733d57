// Memory latency of the machine the benchmarks run on: one dependent load after another
// through a random cycle of 64-byte lines spread over a working set of the given size.
//
// Why it is here. The exact mode handles events in time order, which is random in space, so
// its speed at large N is set by how long a read that misses the caches takes, not by
// arithmetic (docs/exact.md). This shows where the caches end and what a miss costs:
//
//   build/bench/memory_latency
//
// Reports ns per load for working sets of 256 KiB to 128 MiB.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

namespace {

struct alignas(64) Line {
    std::size_t next;
};

void BM_PointerChase(benchmark::State& state) {
    const auto lines = static_cast<std::size_t>(state.range(0)) * 1024 / sizeof(Line);
    // One cycle through every line in a random order: the hardware prefetchers cannot guess
    // the next address, and each load waits for the one before.
    std::vector<std::size_t> order(lines);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::shuffle(order.begin(), order.end(), std::mt19937_64(1));
    std::vector<Line> cycle(lines);
    for (std::size_t k = 0; k < lines; ++k)
        cycle[order[k]].next = order[(k + 1) % lines];
    std::size_t at = order[0];
    for (std::size_t k = 0; k < lines; ++k)
        at = cycle[at].next;  // warm the caches and the TLB as far as they reach
    constexpr int kLoads = 1 << 16;
    for (auto _ : state) {
        for (int k = 0; k < kLoads; ++k)
            at = cycle[at].next;
        benchmark::DoNotOptimize(at);
    }
    state.counters["ns/load"] =
        benchmark::Counter(static_cast<double>(state.iterations()) * kLoads * 1e-9,
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_PointerChase)
    ->ArgName("KiB")
    ->RangeMultiplier(2)
    ->Range(256, 128 * 1024)
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
