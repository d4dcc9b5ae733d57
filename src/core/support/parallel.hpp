#pragma once
// How the discrete step uses more than one core.
//
// Threading model. Intel oneTBB (Debian's libtbb-dev) through the two helpers below: a
// parallel_for over a fixed list of chunks, run in a task arena limited to the World's thread
// count. The calling thread works too and takes any chunk another thread has not started, so
// a step does not stall when a worker is descheduled (on a machine shared with other work, a
// fork-join runtime whose master waits for every worker at each barrier loses whole time
// slices; we measured that with OpenMP before choosing TBB).
// Without TBB the helpers run the loop on the calling thread.
//
// Determinism. Results must not depend on the thread count, so every parallel loop obeys one
// of two rules:
//   1. Each output element is written by exactly one iteration and computed from inputs that
//      no iteration writes (move, gravity, walls, cell indices, pair queries per particle).
//      Which thread runs the iteration cannot change the value.
//   2. A reduction whose result depends on the order of its terms (a floating-point sum) is cut
//      into blocks of a fixed size (kBlock particles, independent of the thread count), each
//      block is reduced sequentially, and the block results are combined on one thread in block
//      order. Minima, maxima and integer counts are exact in any order.
// Lists built in parallel (contact pairs) are written per chunk, concatenated in chunk order
// and sorted; pairs are distinct, so the sorted list is the same for any chunking. The grid's
// counting sort splits cells, not particles, between threads, so each cell's slots are filled
// by one thread in the same order as by a single pass.
// The resolve and separate stages stay sequential: Gauss–Seidel over the pair list in order.

#include <algorithm>
#include <cstddef>

#ifdef PSB_HAVE_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#endif

namespace psb::parallel {

/// Particles per block of an order-sensitive reduction (rule 2 above). Fixed: changing it
/// changes rounding, never correctness. Small, so that the blocks of a world of ten thousand
/// particles still share out evenly between threads (forBlocks groups them).
inline constexpr std::size_t kBlock = 1024;
/// Below this many items per chunk a parallel loop costs more than it saves.
inline constexpr std::size_t kMinPerChunk = 4096;
/// Chunks per thread: more than one, so that a thread that finishes early (or a worker that
/// starts late) evens out the load.
inline constexpr int kChunksPerThread = 4;

#ifdef PSB_HAVE_TBB
/// The arena limiting parallel loops to `threads` threads (made on first use, then reused).
tbb::task_arena& arenaFor(int threads);
#endif

/// How many chunks to split `n` items into for `threads` threads (1 means run inline).
[[nodiscard]] inline int chunksFor(int threads, std::size_t n) {
    if (threads <= 1) return 1;
    const std::size_t useful = std::max<std::size_t>(1, n / kMinPerChunk);
    return static_cast<int>(
        std::min<std::size_t>(useful, static_cast<std::size_t>(threads) * kChunksPerThread));
}

/// Runs body(k) for k in [0, count) on up to `threads` threads.
template <typename F>
void forEachIndex(int threads, std::size_t count, F&& body) {
#ifdef PSB_HAVE_TBB
    if (threads > 1 && count > 1) {
        arenaFor(threads).execute([&] {
            tbb::parallel_for(
                tbb::blocked_range<std::size_t>(0, count, 1),
                [&](const tbb::blocked_range<std::size_t>& range) {
                    for (std::size_t k = range.begin(); k != range.end(); ++k)
                        body(k);
                },
                tbb::simple_partitioner());
        });
        return;
    }
#else
    (void)threads;
#endif
    for (std::size_t k = 0; k < count; ++k)
        body(k);
}

/// Splits [0, n) into `chunks` contiguous ranges and calls f(chunk, begin, end) for each, in
/// parallel when chunks > 1 (the thread count is the one chunksFor was given).
template <typename F>
void forChunks(int threads, int chunks, std::size_t n, F&& f) {
    forEachIndex(threads, static_cast<std::size_t>(chunks), [&](std::size_t c) {
        f(static_cast<int>(c), n * c / chunks, n * (c + 1) / chunks);
    });
}

/// Calls f(block, begin, end) for each block of kBlock items of [0, n), spread over up to
/// `threads` threads. The block boundaries do not depend on `threads`; the blocks are handed out
/// in contiguous groups, as many as chunksFor gives chunks, so that small n runs inline, 10^4
/// items still balance and large n does not pay a task per block.
template <typename F>
void forBlocks(int threads, std::size_t n, F&& f) {
    const std::size_t blocks = (n + kBlock - 1) / kBlock;
    const std::size_t groups = std::min(blocks, static_cast<std::size_t>(chunksFor(threads, n)));
    forEachIndex(threads, groups, [&](std::size_t g) {
        for (std::size_t b = blocks * g / groups; b < blocks * (g + 1) / groups; ++b)
            f(b, b * kBlock, std::min(n, (b + 1) * kBlock));
    });
}

/// Blocks forBlocks makes of n items.
[[nodiscard]] inline std::size_t blockCount(std::size_t n) {
    return (n + kBlock - 1) / kBlock;
}

}  // namespace psb::parallel
