#pragma once
// How the discrete step uses more than one core.
//
// Threading model. OpenMP from the compiler (libgomp), used only through the two helpers
// below, both a static `parallel for`: no task queue, no work stealing, no scheduler of ours.
// Without OpenMP the helpers run the loop on the calling thread.
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
// Lists built in parallel (contact pairs) are written per chunk and concatenated in chunk
// order; because each chunk covers an ascending range of first indices and sorts its own
// output, the concatenation is the same ascending (i, j) list for any number of chunks.
// The resolve and separate stages stay sequential: Gauss–Seidel over the pair list in order.

#include <algorithm>
#include <cstddef>

namespace psb::parallel {

/// Particles per block of an order-sensitive reduction (rule 2 above). Fixed: changing it
/// changes rounding, never correctness.
inline constexpr std::size_t kBlock = 8192;
/// Below this many items per thread a parallel region costs more than it saves.
inline constexpr std::size_t kMinPerThread = 4096;

/// How many chunks `threads` threads should split `n` items into (>= 1).
[[nodiscard]] inline int chunksFor(int threads, std::size_t n) {
    const std::size_t useful = std::max<std::size_t>(1, n / kMinPerThread);
    return static_cast<int>(std::clamp<std::size_t>(useful, 1, std::max(threads, 1)));
}

/// Splits [0, n) into `chunks` contiguous ranges and calls f(chunk, begin, end) for each, in
/// parallel with one thread per chunk.
template <typename F>
void forChunks(int chunks, std::size_t n, F&& f) {
    if (chunks <= 1) {
        f(0, std::size_t{0}, n);
        return;
    }
#pragma omp parallel for schedule(static, 1) num_threads(chunks)
    for (int c = 0; c < chunks; ++c) {
        const std::size_t begin = n * static_cast<std::size_t>(c) / chunks;
        const std::size_t end = n * static_cast<std::size_t>(c + 1) / chunks;
        f(c, begin, end);
    }
}

/// Calls f(block, begin, end) for each block of kBlock items of [0, n), spread over up to
/// `threads` threads. The block boundaries do not depend on `threads`.
template <typename F>
void forBlocks(int threads, std::size_t n, F&& f) {
    const std::size_t blocks = (n + kBlock - 1) / kBlock;
    const int t = chunksFor(threads, n);
    if (t <= 1) {
        for (std::size_t b = 0; b < blocks; ++b)
            f(b, b * kBlock, std::min(n, (b + 1) * kBlock));
        return;
    }
#pragma omp parallel for schedule(static) num_threads(t)
    for (std::size_t b = 0; b < blocks; ++b)
        f(b, b * kBlock, std::min(n, (b + 1) * kBlock));
}

/// Blocks forBlocks makes of n items.
[[nodiscard]] inline std::size_t blockCount(std::size_t n) {
    return (n + kBlock - 1) / kBlock;
}

}  // namespace psb::parallel
