#pragma once
// The event queue of the exact mode: a fixed set of keys (the stepper uses two per particle:
// its next collision and its next cell-face crossing), each with the time of its event.
//
// Why a fixed set of keys. The textbook queue holds every predicted pair event and marks stale
// ones with counters; it grows with the number of predictions and spends much of its time
// popping garbage. Keeping only each particle's earliest events (Smallenburg 2022) bounds the
// queue at 2N entries, so an update is a sift in a heap of fixed size and nothing is ever
// garbage-collected.
//
// Why a 4-ary heap. Entries are 16 bytes (time + key), so the four children of a node fill one
// 64-byte cache line (the storage is offset so that they start on one); the heap is half as
// deep as a binary one, and a sift-down (the common case: a particle's next event is later
// than the one just handled) touches one line per level.
//
// Ties. Entries are ordered by (time, key): events at the same time are handled in ascending
// key order, so the same state always gives the same sequence.

#include <cstdint>
#include <vector>

namespace psb::exact {

class EventQueue {
  public:
    struct Entry {
        double time;
        std::uint32_t key;
    };

    /// Makes a queue of keys 0..n-1, every one with time `time` (usually +infinity).
    void reset(std::uint32_t n, double time);
    /// Sets key i's time and restores the heap order. O(log n).
    void update(std::uint32_t i, double time);
    [[nodiscard]] const Entry& top() const { return heap_[0]; }
    [[nodiscard]] double timeOf(std::uint32_t i) const { return heap_[slot_[i]].time; }
    [[nodiscard]] std::uint32_t size() const { return static_cast<std::uint32_t>(heap_.size()); }
    [[nodiscard]] bool empty() const { return heap_.empty(); }

  private:
    static bool before(const Entry& a, const Entry& b) {
        return a.time < b.time || (a.time == b.time && a.key < b.key);
    }
    void siftUp(std::uint32_t k);
    void siftDown(std::uint32_t k);

    std::vector<Entry> heap_;
    std::vector<std::uint32_t> slot_;  // key -> position in heap_
};

}  // namespace psb::exact
