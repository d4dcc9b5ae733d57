#pragma once
// The broadphases' output: overlapping pairs by storage index, and helpers to keep the list in
// the canonical ascending (i, j) order.

#include <algorithm>
#include <cstdint>
#include <vector>

namespace psb {

/// Two storage indices whose discs overlap, i < j. Broadphases emit pairs in ascending
/// (i, j) order so that resolution order, and therefore the result, does not depend on which
/// broadphase found them.
struct ContactPair {
    std::uint32_t i;
    std::uint32_t j;

    friend bool operator==(ContactPair a, ContactPair b) = default;
    friend bool operator<(ContactPair a, ContactPair b) {
        return a.i != b.i ? a.i < b.i : a.j < b.j;
    }
};

/// Sorts pairs[from..] into ascending (i, j) order; every index is below `indexLimit`. Pairs
/// must be distinct (then any correct sort gives the same list). A list nearly in order (as the
/// grids give it) is insertion-sorted; others go to an LSD radix sort on 11-bit digits of j,
/// then of i, using `scratch` (short lists to std::sort).
void sortPairs(std::vector<ContactPair>& pairs, std::size_t from, std::vector<ContactPair>& scratch,
               std::uint32_t indexLimit);

}  // namespace psb
