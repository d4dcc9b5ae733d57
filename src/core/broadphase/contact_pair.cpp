#include "broadphase/contact_pair.hpp"

namespace psb {

namespace {

/// Insertion sort of a[0, n) that gives up after `budget` moves (then a[0, n) is a
/// permutation of what it was, and false is returned). A list k moves from sorted costs n + k.
bool insertionSortWithin(ContactPair* a, std::size_t n, std::size_t budget) {
    std::size_t moves = 0;
    for (std::size_t k = 1; k < n; ++k) {
        const ContactPair x = a[k];
        std::size_t m = k;
        while (m > 0 && x < a[m - 1]) {
            a[m] = a[m - 1];
            --m;
        }
        a[m] = x;
        moves += k - m;
        if (moves > budget) return false;
    }
    return true;
}

}  // namespace

void sortPairs(std::vector<ContactPair>& pairs, std::size_t from, std::vector<ContactPair>& scratch,
               std::uint32_t indexLimit) {
    const std::size_t n = pairs.size() - from;
    ContactPair* a = pairs.data() + from;
    // The grids find pairs in cell order and the world keeps its particles in cell order, so the
    // list is nearly sorted already (a gas of 4096 discs: about one move a pair, twice that in
    // a periodic box, whose wrapped discs keep their index): an insertion sort then costs a pass.
    // Lists further from order (another broadphase, a world not reordered yet) go on to a sort
    // whose cost does not depend on the order, after at most kMovesPerPair moves a pair.
    constexpr std::size_t kMovesPerPair = 4;
    if (insertionSortWithin(a, n, kMovesPerPair * n + 64)) return;
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
