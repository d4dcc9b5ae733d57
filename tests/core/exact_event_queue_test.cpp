// The exact mode's event queue: one entry per particle, ordered by (time, index).

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

#include "event_queue.hpp"

namespace psb::exact {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ExactEventQueue, TopIsTheEarliestEventAfterAnySequenceOfUpdates) {
    constexpr std::uint32_t n = 1000;
    EventQueue q;
    q.reset(n, kInf);
    std::vector<double> time(n, kInf);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(0.0, 100.0);
    for (int k = 0; k < 20000; ++k) {
        const std::uint32_t i = rng() % n;
        time[i] = (k % 7 == 0) ? kInf : u(rng);
        q.update(i, time[i]);
        const auto best = std::min_element(time.begin(), time.end());
        ASSERT_EQ(q.top().time, *best);
        ASSERT_EQ(q.top().key, static_cast<std::uint32_t>(best - time.begin()));
        ASSERT_EQ(q.timeOf(i), time[i]);
    }
}

TEST(ExactEventQueue, SimultaneousEventsComeOutInIndexOrder) {
    EventQueue q;
    q.reset(6, kInf);
    for (std::uint32_t i : {4u, 1u, 5u, 3u})
        q.update(i, 2.5);
    std::vector<std::uint32_t> order;
    while (q.top().time == 2.5) {
        order.push_back(q.top().key);
        q.update(q.top().key, kInf);
    }
    EXPECT_EQ(order, (std::vector<std::uint32_t>{1, 3, 4, 5}));
}

TEST(ExactEventQueue, PostponingTheTopRevealsTheNext) {
    EventQueue q;
    q.reset(3, kInf);
    q.update(0, 1.0);
    q.update(1, 2.0);
    q.update(2, 3.0);
    q.update(0, 5.0);
    EXPECT_EQ(q.top().key, 1u);
    q.update(2, 0.5);
    EXPECT_EQ(q.top().key, 2u);
}

}  // namespace
}  // namespace psb::exact
