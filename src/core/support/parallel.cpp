#include "support/parallel.hpp"

#ifdef PSB_HAVE_TBB
#include <array>
#include <memory>
#include <mutex>

namespace psb::parallel {

tbb::task_arena& arenaFor(int threads) {
    constexpr int kMax = 256;  // World::setThreads' limit
    static std::array<std::unique_ptr<tbb::task_arena>, kMax + 1> arenas;
    static std::mutex mutex;
    threads = std::clamp(threads, 1, kMax);
    std::lock_guard lock(mutex);
    auto& arena = arenas[threads];
    if (!arena) arena = std::make_unique<tbb::task_arena>(threads);
    return *arena;
}

}  // namespace psb::parallel
#endif
