// A steady-state step allocates nothing. This executable replaces the global operator new to
// count allocations, so it is kept apart from the other core tests.

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <random>

#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/world.hpp>

namespace {
std::atomic<std::size_t> gAllocations{0};
}

void* operator new(std::size_t size) {
    ++gAllocations;
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
// GCC at -O1 and above (the sanitizer build) inlines the replaced operator new into callers and
// then takes free() here for a mismatch; the pair is malloc/free, so the warning is spurious.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace psb {
namespace {

World gas(std::size_t n, BroadPhaseKind kind, int threads) {
    WorldDef def;
    def.width = def.height = std::sqrt(3.141592653589793 * n / 0.1);
    def.gravity = Vec2(0.0, 1.0);
    def.friction = 0.1;
    World w(def, {.broadphase = kind});
    w.setThreads(threads);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(1.0, def.width - 1.0);
    std::normal_distribution<double> g(0.0, 1.0);
    for (std::size_t k = 0; k < n; ++k) {
        w.add({.position = {u(rng), u(rng)},
               .velocity = {g(rng), g(rng)},
               .radius = k % 300 == 0 ? 4.0 : 1.0});
    }
    return w;
}

TEST(SteadyState, StepsAllocateNothing) {
    for (const BroadPhaseKind kind :
         {BroadPhaseKind::Auto, BroadPhaseKind::Grid, BroadPhaseKind::Quadtree}) {
        for (const int threads : {1, 2}) {
            World w = gas(20000, kind, threads);
            for (int k = 0; k < 40; ++k)
                w.step(0.01);  // warm-up: scratch reaches its size
            const std::size_t before = gAllocations.load();
            for (int k = 0; k < 40; ++k)
                w.step(0.01);  // includes a reorder
            EXPECT_EQ(gAllocations.load() - before, 0u)
                << toString(kind) << ", " << threads << " thread(s)";
        }
    }
}

TEST(SteadyState, RecordingATimeSeriesAllocatesNothing) {
    World w = gas(2000, BroadPhaseKind::Auto, 1);
    TimeSeries series(16);
    for (int k = 0; k < 40; ++k)
        w.step(0.01);  // warm-up: the step's scratch reaches its size
    const std::size_t before = gAllocations.load();
    for (int k = 0; k < 40; ++k) {  // wraps the ring more than twice
        w.step(0.01);
        ASSERT_TRUE(series.record(w));
    }
    EXPECT_EQ(gAllocations.load() - before, 0u);
    EXPECT_EQ(series.size(), 16u);
}

}  // namespace
}  // namespace psb
