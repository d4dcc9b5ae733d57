#pragma once
// Per-step scratch, kept between steps so that a steady-state step allocates nothing.

#include <cstdint>
#include <vector>

namespace psb {

/// Two storage indices whose discs overlap, i < j. Broadphases emit pairs in ascending
/// (i, j) order so that resolution order, and therefore the result, does not depend on which
/// broadphase found them.
struct ContactPair {
    std::uint32_t i;
    std::uint32_t j;
};

struct StepContext {
    std::vector<ContactPair> pairs;
};

}  // namespace psb
