#include "broadphase/contact_pair.hpp"

namespace psb {

void sortPairs(std::vector<ContactPair>& pairs, std::size_t from, std::vector<ContactPair>& scratch,
               std::uint32_t indexLimit) {
    const std::size_t n = pairs.size() - from;
    ContactPair* a = pairs.data() + from;
    if (n < 256) {
        std::sort(a, a + n);
        return;
    }
    constexpr int kBits = 11;
    constexpr std::uint32_t kMask = (1u << kBits) - 1;
    int digits = 0;
    while (digits * kBits < 32 && (indexLimit - 1) >> (digits * kBits) != 0)
        ++digits;
    if (scratch.size() < n) scratch.resize(n);
    ContactPair* b = scratch.data();
    // Stable passes: the digits of j, least significant first, then those of i.
    for (int pass = 0; pass < 2 * digits; ++pass) {
        const bool byJ = pass < digits;
        const int shift = (byJ ? pass : pass - digits) * kBits;
        std::uint32_t count[(1u << kBits) + 1] = {};
        for (std::size_t k = 0; k < n; ++k) {
            ++count[(((byJ ? a[k].j : a[k].i) >> shift) & kMask) + 1];
        }
        for (std::uint32_t d = 0; d < (1u << kBits); ++d)
            count[d + 1] += count[d];
        for (std::size_t k = 0; k < n; ++k) {
            b[count[((byJ ? a[k].j : a[k].i) >> shift) & kMask]++] = a[k];
        }
        std::swap(a, b);
    }
    if (a != pairs.data() + from) std::copy(a, a + n, pairs.data() + from);
}

}  // namespace psb
