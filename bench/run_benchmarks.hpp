#pragma once
// The main() of a benchmark program whose benchmarks are registered at run time.

#include <benchmark/benchmark.h>

namespace psb::bench {

/// Parses Google Benchmark's options, runs the registered benchmarks and returns the exit code
/// (1 for an unknown option).
inline int runBenchmarks(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

}  // namespace psb::bench
