#pragma once
// The event queue of the exact mode: one entry per particle, keyed by the time of that
// particle's next event.
//
// Why one entry per particle. The textbook queue holds every predicted pair event and marks
// stale ones with counters; it grows with the number of predictions and spends most of its
// time popping garbage. Keeping only each particle's earliest event (Smallenburg 2022) bounds
// the queue at N entries, so an update is a sift in a heap of fixed size and nothing is ever
// garbage-collected.
//
// Why a 4-ary heap. Entries are 16 bytes (time + particle), so the four children of a node sit
// in one 64-byte cache line; the heap is half as deep as a binary one, and a sift-down (the
// common case: a particle's next event is later than the one just handled) touches one line
// per level.
//
// Ties. Entries are ordered by (time, particle index): two events at the same time are handled
// in ascending index order, so the same state always gives the same sequence.

#include <cstdint>
#include <vector>

namespace psb::exact {

class EventQueue {
  public:
    struct Entry {
        double time;
        std::uint32_t particle;
    };

    /// Makes a queue of n particles, every one with time `time` (usually +infinity).
    void reset(std::uint32_t n, double time);
    /// Sets particle i's time and restores the heap order. O(log n).
    void update(std::uint32_t i, double time);
    [[nodiscard]] const Entry& top() const { return heap_[0]; }
    [[nodiscard]] double timeOf(std::uint32_t i) const { return heap_[slot_[i]].time; }
    [[nodiscard]] std::uint32_t size() const { return static_cast<std::uint32_t>(heap_.size()); }
    [[nodiscard]] bool empty() const { return heap_.empty(); }

  private:
    static bool before(const Entry& a, const Entry& b) {
        return a.time < b.time || (a.time == b.time && a.particle < b.particle);
    }
    void siftUp(std::uint32_t k);
    void siftDown(std::uint32_t k);

    std::vector<Entry> heap_;
    std::vector<std::uint32_t> slot_;  // particle -> position in heap_
};

}  // namespace psb::exact
