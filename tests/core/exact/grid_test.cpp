// The exact mode's cells (Grid): every pair that can touch is among the neighbours a search
// visits, across size levels; the order of a re-sort; a cell move.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "exact/grid.hpp"
#include "parts.hpp"

namespace psb::exact {
namespace {

struct Scene {
    WorldDef def;
    std::vector<Body> bodies;
    std::vector<Cold> cold;
};

// 300 discs of 0.2 m and 5 of 2 to 4 m, placed at random in a 40 m box.
Scene mixedSizes() {
    Scene s;
    s.def.width = 40.0;
    s.def.height = 40.0;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 305; ++k) {
        const double r = k < 300 ? 0.2 : 2.0 + 2.0 * u(rng);
        s.bodies.push_back(bodyAt(r + (40.0 - 2.0 * r) * u(rng), r + (40.0 - 2.0 * r) * u(rng), r));
    }
    s.cold.assign(s.bodies.size(), Cold{});
    return s;
}

TEST(ExactGrid, EveryPairThatCanTouchIsVisitedAcrossSizeLevels) {
    Scene s = mixedSizes();
    Grid grid;
    grid.setUp(s.def, s.bodies, s.cold);
    ASSERT_GT(grid.levelCount(), 1) << "the big discs make levels of their own";
    for (std::uint32_t i = 0; i < s.bodies.size(); ++i)
        grid.insert(i, s.cold[i]);
    for (std::uint32_t i = 0; i < s.bodies.size(); ++i) {
        std::set<std::uint32_t> seen;
        grid.forEachAround(s.cold[i], [&](std::uint32_t q) { EXPECT_TRUE(seen.insert(q).second); });
        EXPECT_TRUE(seen.count(i)) << i;
        for (std::uint32_t j = 0; j < s.bodies.size(); ++j) {
            const Body& a = s.bodies[i];
            const Body& b = s.bodies[j];
            if (std::hypot(b.x - a.x, b.y - a.y) <= a.r + b.r) {
                EXPECT_TRUE(seen.count(j)) << i << " touches " << j;
            }
        }
    }
}

TEST(ExactGrid, CellOrderSortsByFineCellKeepingTheOrderWithinACell) {
    Scene s = mixedSizes();
    Grid grid;
    grid.setUp(s.def, s.bodies, s.cold);
    const std::vector<std::uint32_t> to = grid.cellOrder(s.cold);
    std::vector<std::uint32_t> from(to.size());
    for (std::uint32_t i = 0; i < to.size(); ++i)
        from[to[i]] = i;
    for (std::uint32_t k = 1; k < from.size(); ++k) {
        const Cold& a = s.cold[from[k - 1]];
        const Cold& b = s.cold[from[k]];
        const std::uint32_t ca = grid.fine().cell(a.kx, a.ky), cb = grid.fine().cell(b.kx, b.ky);
        ASSERT_LE(ca, cb) << k;
        if (ca == cb) {
            EXPECT_LT(from[k - 1], from[k]) << k;
        }
    }
}

TEST(ExactGrid, AMoveAcrossAFaceListsTheParticleInTheNextCell) {
    Scene s = mixedSizes();
    Grid grid;
    grid.setUp(s.def, s.bodies, s.cold);
    for (std::uint32_t i = 0; i < s.bodies.size(); ++i)
        grid.insert(i, s.cold[i]);
    const CellList& cells = grid.fine();
    const auto listed = [&](std::uint32_t cell, std::uint32_t i) {
        for (std::uint32_t q = cells.head(cell); q != CellList::kNone; q = cells.next(q))
            if (q == i) return true;
        return false;
    };
    // A small disc not in the last column: one face to the right.
    std::uint32_t i = 0;
    while (s.cold[i].level != 0 || s.cold[i].kx + 1 >= cells.nx())
        ++i;
    Cold& c = s.cold[i];
    const std::int64_t kx = c.kx, ky = c.ky;
    grid.move(i, c, 1);
    EXPECT_EQ(c.kx, kx + 1);
    EXPECT_EQ(c.ky, ky);
    EXPECT_FALSE(listed(cells.cell(kx, ky), i));
    EXPECT_TRUE(listed(cells.cell(kx + 1, ky), i));
}

}  // namespace
}  // namespace psb::exact
