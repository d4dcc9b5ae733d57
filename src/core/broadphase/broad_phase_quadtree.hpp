#pragma once
// Region quadtree broadphase, rebuilt every step from a Morton-sorted particle order.
//
// Build. Each centre gets a 32-bit Morton code (16 bits per axis over the bounding square of
// the centres). An LSD radix sort (four 8-bit passes, stable) orders the particles by code;
// a node is then a contiguous run of that order whose codes share a prefix, and its children
// are the four sub-runs split on the next two bits (found by binary search). Nodes are appended
// breadth-first to one flat array, so the children of a node are contiguous and every child
// comes after its parent:
//
//   nodes[k] = { bounds of the discs in the subtree (min/max x/y),
//                begin, end     (run of `order`),
//                firstChild, childCount (0 for a leaf) }
//
// A node with at most kLeafSize particles, or at depth kMaxDepth (16, the resolution of the
// code), is a leaf, so depth is bounded even when many centres coincide. Bounds are filled in
// one backward sweep (children before parents). All storage is vectors reused between steps:
// no allocation per node, none at all in steady state.
//
// Mixed sizes. Node bounds cover the discs, not just the centres, so a large disc widens only
// the boxes on its own root path; a query descends into a node only if the querying disc's box
// touches the node's bounds. No radius limit or cell size is involved, which is why `auto`
// picks the quadtree when radii spread widely.
//
// Query. One traversal per leaf, not per particle: the leaf's disc bounds select the leaves it
// can touch, and each pair of touching leaves is tested once (from the lower-numbered leaf),
// every particle against every particle, branch-free. A leaf holds at most kLeafSize discs, so
// the traversal is shared by up to that many particles.
//
// Periodic boxes (findPairsPeriodic). A leaf near an edge also queries the tree with its
// bounds moved by a box width or height (the images of the leaf across that edge and corner);
// the leaves any of its images touch are gathered, each once, and tested between nearest
// images (support/periodic_box.hpp). Each pair of leaves is still tested from the lower one.
//
// Order. Pairs come out leaf by leaf and are then radix-sorted into the ascending (i, j) order
// all-pairs gives (sortPairs); leaves are split over threads in chunks (see parallel.hpp for why
// chunking cannot change the list).

#include <cstdint>
#include <vector>

#include <particle_sandbox/particle_arrays.hpp>

#include "broadphase/contact_pair.hpp"
#include "broadphase/pair_chunks.hpp"
#include "broadphase/particle_stats.hpp"
#include "support/periodic_box.hpp"

namespace psb {

class QuadtreeBroadPhase {
  public:
    static constexpr std::uint32_t kLeafSize = 8;
    static constexpr int kMaxDepth = 16;

    void build(const ParticleArrays& p, const ParticleStats& stats, int threads);
    /// Appends every overlapping pair (i < j) in ascending (i, j) order.
    void findPairs(const ParticleArrays& p, int threads, std::vector<ContactPair>& out);
    /// The same in a periodic box: pairs across its edges too, measured between nearest
    /// images.
    void findPairsPeriodic(const ParticleArrays& p, const periodic::Box& box, int threads,
                           std::vector<ContactPair>& out);

    [[nodiscard]] std::size_t nodeCount() const { return nodes_.size(); }
    [[nodiscard]] int depth() const { return depth_; }
    [[nodiscard]] std::size_t memoryBytes() const;

  private:
    struct Node {
        double minX, minY, maxX, maxY;  ///< bounds of the discs below, metres
        std::uint32_t begin, end;       ///< run of order_
        std::uint32_t firstChild;
        std::uint32_t childCount;
    };

    std::vector<std::uint32_t> code_;   ///< Morton code per particle, in order_ order
    std::vector<std::uint32_t> order_;  ///< particle indices sorted by code
    std::vector<std::uint32_t> codeTmp_, orderTmp_;
    std::vector<std::uint8_t> level_;  ///< depth of each node (build only)
    std::vector<Node> nodes_;
    int depth_ = 0;
    double slack_ = 0.0;                 ///< absolute rounding slack for box tests, metres
    std::vector<std::uint32_t> leaves_;  ///< node indices of the leaves
    std::vector<ContactPair> sortScratch_;
    PairChunks chunks_;
    std::vector<std::vector<std::uint32_t>> touched_;  ///< periodic: per chunk, a leaf's partners
};

}  // namespace psb
