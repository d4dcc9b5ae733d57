#pragma once
// All-pairs broadphase: every pair is tested. O(n²); the reference the faster broadphases are
// checked against.

#include <vector>

#include <particle_sandbox/particle_arrays.hpp>

#include "broadphase/contact_pair.hpp"
#include "support/periodic_box.hpp"

namespace psb {

/// Appends to `out` every pair (i < j) whose discs overlap (centre distance < r_i + r_j), in
/// ascending (i, j) order. Touching discs (distance == r_i + r_j) are not a contact.
void findPairsAllPairs(const ParticleArrays& p, std::vector<ContactPair>& out);
/// The same in a periodic box: each pair measured between its nearest images.
void findPairsAllPairs(const ParticleArrays& p, const periodic::Box& box,
                       std::vector<ContactPair>& out);

}  // namespace psb
