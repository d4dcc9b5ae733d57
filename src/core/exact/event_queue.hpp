#pragma once
// The event queue of the exact mode: a fixed set of keys (the stepper uses two per particle:
// its next collision and its next move to another cell), each with the time of its event.
//
// Why a fixed set of keys. The textbook queue holds every predicted pair event and marks stale
// ones with counters; it grows with the number of predictions and spends much of its time
// popping garbage. Keeping only each particle's earliest events (Smallenburg 2022) bounds the
// queue at 2N entries.
//
// Why a calendar in front of a heap. Most updates push an event into the future (a particle's
// next cell face, its next collision): in a heap of 2N entries each is a sift through ~log N
// levels, each level a cache miss once N is large. Here only the events of the current time
// bucket live in the heap (a few thousand: it stays in cache); later ones are appended to the
// unsorted list of their bucket in O(1), and the lists are drained into the heap bucket by
// bucket as time reaches them. Events beyond the calendar's window wait in an overflow list
// that is redistributed once per turn of the calendar.
//
//   time ──►  [ heap: bucket cur ] [ list cur+1 ] [ list cur+2 ] … [ list cur+M-1 ] [ overflow ]
//
// An update never searches a list: the entry it leaves behind is recognised as stale when its
// bucket is drained (the key's current time no longer falls in that bucket, or the key was
// placed already), so updates are O(1) outside the current bucket.
//
// Ties. The heap orders entries by (time, key): events at the same time are handled in
// ascending key order, so the same state always gives the same sequence.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace psb::exact {

class EventQueue {
  public:
    struct Entry {
        double time;
        std::uint32_t key;
    };

    /// Makes a queue of keys 0..n-1, all at +infinity, with buckets `bucketWidth` seconds wide
    /// (finite, > 0) starting at time `origin`.
    void reset(std::uint32_t n, double bucketWidth, double origin = 0.0);
    /// Sets key i's time (>= the time of the last event taken from the queue, or +infinity).
    void update(std::uint32_t i, double time);
    /// The earliest entry; time +infinity when no key has a finite time.
    [[nodiscard]] Entry top();
    [[nodiscard]] double timeOf(std::uint32_t i) const { return rec_[i].time; }
    /// Starts fetching key i's record (a hint; no effect on the order).
    void prefetch(std::uint32_t i) const { __builtin_prefetch(&rec_[i]); }
    /// The key most likely to come out after top() (the earliest child of the heap's root), or
    /// UINT32_MAX; a hint for prefetching, valid until the next update.
    [[nodiscard]] std::uint32_t likelyNext() const {
        const auto n = static_cast<std::uint32_t>(heap_.size());
        std::uint32_t best = UINT32_MAX;
        double t = 0.0;
        for (std::uint32_t c = 1; c < 5 && c < n; ++c) {
            if (best == UINT32_MAX || heap_[c].time < t) {
                best = heap_[c].key;
                t = heap_[c].time;
            }
        }
        return best;
    }
    [[nodiscard]] double bucketWidth() const { return width_; }
    /// Bytes held (capacities of the records, the heap and the bucket lists).
    [[nodiscard]] std::size_t memoryBytes() const {
        std::size_t bytes = sizeof(Record) * rec_.capacity() + sizeof(Entry) * heap_.capacity() +
                            sizeof(std::uint32_t) * overflow_.capacity() +
                            sizeof(std::vector<std::uint32_t>) * buckets_.capacity();
        for (const auto& b : buckets_)
            bytes += sizeof(std::uint32_t) * b.capacity();
        return bytes;
    }

  private:
    enum class Where : std::uint8_t { Nowhere, Heap, Bucket, Overflow };

    [[nodiscard]] std::int64_t bucketOf(double t) const;
    void place(std::uint32_t i);
    bool advance();  // moves to the next non-empty bucket; false if nothing is left
    void redistributeOverflow();

    // Indexed 4-ary heap over the current bucket's keys.
    static bool before(const Entry& a, const Entry& b) {
        return a.time < b.time || (a.time == b.time && a.key < b.key);
    }
    void heapPush(std::uint32_t i);
    void heapRemove(std::uint32_t i);
    void siftUp(std::uint32_t k);
    void siftDown(std::uint32_t k);

    static constexpr std::int64_t kBuckets = 256;

    double width_ = 1.0, origin_ = 0.0;
    std::int64_t cur_ = 0;  // the bucket whose events are in the heap
    struct Record {
        double time;
        std::uint32_t slot;  // position in heap_ (when Where::Heap)
        Where where;
    };
    std::vector<Record> rec_;  // per key: 16 bytes, so a particle's two keys share a line
    std::vector<Entry> heap_;
    std::vector<std::vector<std::uint32_t>> buckets_;
    std::vector<std::uint32_t> overflow_;
    std::uint64_t listed_ = 0;  // entries (live or stale) in the bucket lists
};

}  // namespace psb::exact
