// The exact mode's event queue: a fixed set of keys, ordered by (time, key), whatever the
// calendar's bucket width.

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

#include "exact/event_queue.hpp"

namespace psb::exact {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ExactEventQueue, TopIsTheEarliestEventAfterAnySequenceOfUpdates) {
    constexpr std::uint32_t n = 1000;
    EventQueue q;
    q.reset(n, 0.37);
    std::vector<double> time(n, kInf);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(0.0, 100.0);
    for (int k = 0; k < 20000; ++k) {
        const std::uint32_t i = rng() % n;
        time[i] = (k % 7 == 0) ? kInf : u(rng);
        q.update(i, time[i]);
        const auto best = std::min_element(time.begin(), time.end());
        const EventQueue::Entry top = q.top();
        ASSERT_EQ(top.time, *best);
        if (*best != kInf) {
            ASSERT_EQ(top.key, static_cast<std::uint32_t>(best - time.begin()));
        }
        ASSERT_EQ(q.timeOf(i), time[i]);
    }
}

TEST(ExactEventQueue, PoppingInOrderGivesTheSortedSequenceFarBeyondTheCalendarWindow) {
    // Times spread over many turns of the calendar (256 buckets of 0.01 s), plus infinities.
    constexpr std::uint32_t n = 5000;
    EventQueue q;
    q.reset(n, 0.01);
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(0.0, 1000.0);
    std::vector<double> want;
    for (std::uint32_t i = 0; i < n; ++i) {
        const double t = (i % 10 == 0) ? kInf : u(rng);
        q.update(i, t);
        if (t != kInf) want.push_back(t);
    }
    std::sort(want.begin(), want.end());
    for (double t : want) {
        const EventQueue::Entry e = q.top();
        ASSERT_EQ(e.time, t);
        // Handling an event schedules the next one later, sometimes much later.
        const double next = (e.key % 3 == 0) ? kInf : t + 2000.0 + e.key;
        q.update(e.key, next);
        if (next != kInf) want.push_back(next);  // checked by the loop below
    }
    double last = 0.0;
    for (EventQueue::Entry e = q.top(); e.time != kInf; e = q.top()) {
        ASSERT_GE(e.time, last);
        last = e.time;
        q.update(e.key, kInf);
    }
}

TEST(ExactEventQueue, SimultaneousEventsComeOutInIndexOrder) {
    EventQueue q;
    q.reset(6, 1.0);
    for (std::uint32_t i : {4u, 1u, 5u, 3u})
        q.update(i, 2.5);
    std::vector<std::uint32_t> order;
    while (q.top().time == 2.5) {
        const std::uint32_t k = q.top().key;
        order.push_back(k);
        q.update(k, kInf);
    }
    EXPECT_EQ(order, (std::vector<std::uint32_t>{1, 3, 4, 5}));
}

TEST(ExactEventQueue, PostponingTheTopRevealsTheNext) {
    EventQueue q;
    q.reset(3, 1.0);
    q.update(0, 1.0);
    q.update(1, 2.0);
    q.update(2, 3.0);
    q.update(0, 5.0);
    EXPECT_EQ(q.top().key, 1u);
    q.update(2, 0.5);
    EXPECT_EQ(q.top().key, 2u);
}

TEST(ExactEventQueue, EventsPastTheRangeOfTheBucketNumbersAreKept) {
    // A bucket width tiny against the times (a box 1e-300 m high makes one of ~1e-304 s): every
    // event lies past 4e18 buckets. They were all dropped, and a particle flew through a wall.
    EventQueue q;
    q.reset(3, 1e-304);
    q.update(0, 0.0078);
    q.update(1, 0.5);
    q.update(2, 0.25);
    std::vector<std::uint32_t> order;
    for (int k = 0; k < 3; ++k) {
        const EventQueue::Entry top = q.top();
        ASSERT_NE(top.time, std::numeric_limits<double>::infinity()) << "event " << k << " lost";
        order.push_back(top.key);
        q.update(top.key, std::numeric_limits<double>::infinity());
    }
    EXPECT_EQ(order, (std::vector<std::uint32_t>{0, 2, 1}));
}

}  // namespace
}  // namespace psb::exact
