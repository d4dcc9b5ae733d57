#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "broadphase/contact_pair.hpp"

namespace psb {
namespace {

/// `count` distinct pairs of indices below `limit`, in ascending order.
std::vector<ContactPair> sortedPairs(std::size_t count, std::uint32_t limit, std::mt19937& rng) {
    std::vector<ContactPair> pairs;
    std::uniform_int_distribution<std::uint32_t> index(0, limit - 1);
    while (pairs.size() < count) {
        const std::uint32_t a = index(rng), b = index(rng);
        if (a != b) pairs.push_back({std::min(a, b), std::max(a, b)});
        if (pairs.size() == count) {
            std::sort(pairs.begin(), pairs.end());
            pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
        }
    }
    return pairs;
}

/// Sorts `shuffled` after a prefix that must stay as it is, and checks the result against
/// `sorted`.
void expectSorts(const std::vector<ContactPair>& sorted, std::vector<ContactPair> shuffled,
                 std::uint32_t limit) {
    const std::vector<ContactPair> prefix = {{7, 9}, {1, 2}};
    std::vector<ContactPair> pairs = prefix;
    pairs.insert(pairs.end(), shuffled.begin(), shuffled.end());
    std::vector<ContactPair> scratch;
    sortPairs(pairs, prefix.size(), scratch, limit);
    ASSERT_EQ(pairs.size(), prefix.size() + sorted.size());
    EXPECT_TRUE(std::equal(prefix.begin(), prefix.end(), pairs.begin()));
    EXPECT_TRUE(std::equal(sorted.begin(), sorted.end(), pairs.begin() + 2));
}

// Lists in every state of order, short and long (the sort changes method with both): the same
// ascending list, the prefix before `from` untouched.
TEST(SortPairs, SortsListsNearlyInOrderAndFarFromIt) {
    std::mt19937 rng(12);
    for (const std::size_t count : {0u, 1u, 2u, 40u, 255u, 256u, 300u, 3000u, 20000u}) {
        for (const std::uint32_t limit : {5000u, 70000u, 5000000u}) {
            const std::vector<ContactPair> sorted = sortedPairs(count, limit, rng);
            SCOPED_TRACE(::testing::Message() << sorted.size() << " pairs below " << limit);
            expectSorts(sorted, sorted, limit);
            std::vector<ContactPair> reversed(sorted.rbegin(), sorted.rend());
            expectSorts(sorted, reversed, limit);
            std::vector<ContactPair> shuffled = sorted;
            std::shuffle(shuffled.begin(), shuffled.end(), rng);
            expectSorts(sorted, shuffled, limit);
            // As a grid gives them: neighbours swapped here and there, and a few pairs far from
            // their place (a disc that wrapped across a periodic box's edge).
            std::vector<ContactPair> near = sorted;
            for (std::size_t k = 0; k + 3 < near.size(); k += 5)
                std::swap(near[k], near[k + 3]);
            if (near.size() > 10) {
                std::rotate(near.begin(), near.begin() + 1, near.end());
                std::swap(near[near.size() / 3], near[near.size() - 2]);
            }
            expectSorts(sorted, near, limit);
        }
    }
}

}  // namespace
}  // namespace psb
