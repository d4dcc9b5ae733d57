#pragma once
// Per-chunk pair buffers for a broadphase query that runs in parallel.
//
// Each chunk of a parallel query writes its pairs into its own buffer, without locks and without
// a push_back per candidate: the query reserves room for every candidate it is about to test
// (room()), writes each candidate at the next free slot and advances the count only when the
// discs overlap (branch-free), then records how many it kept (setFound()). gather() appends the
// chunks' pairs to one list in chunk order; the caller then sorts it (sortPairs), so the result
// does not depend on how the query was chunked. Buffers grow to their largest need and stay,
// so a steady state allocates nothing.

#include <algorithm>
#include <cstddef>
#include <vector>

#include "broadphase/contact_pair.hpp"

namespace psb {

class PairChunks {
  public:
    /// Makes sure there are buffers for `chunks` chunks.
    void prepare(int chunks) {
        if (lists_.size() < static_cast<std::size_t>(chunks)) {
            lists_.resize(chunks);
            found_.resize(chunks);
        }
        used_ = chunks;
    }
    /// Chunk c's buffer with room for at least `most` pairs (the kept ones count).
    [[nodiscard]] ContactPair* room(int c, std::size_t most) {
        std::vector<ContactPair>& list = lists_[c];
        if (list.size() < most) list.resize(2 * most);  // grows, then stays
        return list.data();
    }
    /// Chunk c kept the first `found` pairs of its buffer.
    void setFound(int c, std::size_t found) { found_[c] = found; }
    /// Pairs kept by all chunks of the last prepare().
    [[nodiscard]] std::size_t total() const {
        std::size_t sum = 0;
        for (int c = 0; c < used_; ++c)
            sum += found_[c];
        return sum;
    }
    /// Copies the kept pairs to `dst` in chunk order; returns the end of what it wrote.
    ContactPair* copyTo(ContactPair* dst) const {
        for (int c = 0; c < used_; ++c)
            dst = std::copy_n(lists_[c].data(), found_[c], dst);
        return dst;
    }
    /// Bytes held (capacities).
    [[nodiscard]] std::size_t memoryBytes() const {
        std::size_t bytes = sizeof(std::size_t) * found_.capacity();
        for (const auto& v : lists_)
            bytes += sizeof(ContactPair) * v.capacity();
        return bytes;
    }

  private:
    std::vector<std::vector<ContactPair>> lists_;
    std::vector<std::size_t> found_;
    int used_ = 0;
};

}  // namespace psb
