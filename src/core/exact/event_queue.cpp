#include "exact/event_queue.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace psb::exact {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

void EventQueue::reset(std::uint32_t n, double bucketWidth, double origin) {
    width_ = (std::isfinite(bucketWidth) && bucketWidth > 0.0) ? bucketWidth : 1.0;
    origin_ = origin;
    cur_ = 0;
    rec_.assign(n, Record{kInf, 0, Where::Nowhere});
    heap_.clear();
    buckets_.resize(kBuckets);
    for (auto& b : buckets_)
        b.clear();
    overflow_.clear();
    listed_ = 0;
}

std::int64_t EventQueue::bucketOf(double t) const {
    const double b = std::floor((t - origin_) / width_);
    // Far future (or past the range of the integers) is overflow; the past is the current
    // bucket (callers never schedule before the last event taken, but rounding may).
    constexpr double kFar = 4.0e18;
    if (!(b < kFar)) return std::numeric_limits<std::int64_t>::max();
    return static_cast<std::int64_t>(b);
}

void EventQueue::update(std::uint32_t i, double time) {
    if (rec_[i].where == Where::Heap) {
        if (time != kInf && bucketOf(time) <= cur_) {
            // Stays in the heap: re-key in place.
            const std::uint32_t k = rec_[i].slot;
            const double old = heap_[k].time;
            heap_[k].time = time;
            rec_[i].time = time;
            if (time < old) {
                siftUp(k);
            } else {
                siftDown(k);
            }
            return;
        }
        heapRemove(i);
    }
    // An entry left in a bucket or overflow list is now stale; it is skipped when drained.
    rec_[i].where = Where::Nowhere;
    rec_[i].time = time;
    place(i);
}

void EventQueue::place(std::uint32_t i) {
    const double t = rec_[i].time;
    if (t == kInf) {
        rec_[i].where = Where::Nowhere;
        return;
    }
    const std::int64_t b = bucketOf(t);
    if (b <= cur_) {
        heapPush(i);
    } else if (b - cur_ < kBuckets) {
        buckets_[static_cast<std::size_t>(b % kBuckets)].push_back(i);
        rec_[i].where = Where::Bucket;
        ++listed_;
    } else {
        overflow_.push_back(i);
        rec_[i].where = Where::Overflow;
    }
}

EventQueue::Entry EventQueue::top() {
    while (heap_.empty()) {
        if (!advance()) return {kInf, 0};
    }
    return heap_[0];
}

bool EventQueue::advance() {
    if (listed_ == 0) {
        // Nothing in the calendar: jump straight to the earliest overflow bucket.
        std::int64_t first = std::numeric_limits<std::int64_t>::max();
        for (std::uint32_t i : overflow_) {
            if (rec_[i].where == Where::Overflow) {
                const std::int64_t b = bucketOf(rec_[i].time);
                if (b < first) first = b;
            }
        }
        if (first == std::numeric_limits<std::int64_t>::max()) {
            // Every entry left lies past the range of the bucket numbers (a width tiny against
            // the times, as a box ten quadrillion times wider than high makes): the calendar
            // starts again at the earliest of them rather than lose them all.
            double earliest = kInf;
            for (std::uint32_t i : overflow_) {
                if (rec_[i].where == Where::Overflow) earliest = std::min(earliest, rec_[i].time);
            }
            if (earliest == kInf) {
                overflow_.clear();
                return false;
            }
            origin_ = earliest;
            first = bucketOf(earliest);
        }
        cur_ = first;
        redistributeOverflow();
        return true;
    }
    ++cur_;
    // The window now reaches one bucket further; an overflow entry always lies at least a
    // full turn after the bucket current when it was filed, so checking at each turn suffices.
    if (cur_ % kBuckets == 0) redistributeOverflow();
    std::vector<std::uint32_t>& list = buckets_[static_cast<std::size_t>(cur_ % kBuckets)];
    listed_ -= list.size();
    const std::size_t n = list.size();
    for (std::size_t k = 0; k < n; ++k) {
        // The keys of a bucket are in random order: fetch a few ahead.
        if (k + 8 < n) __builtin_prefetch(&rec_[list[k + 8]]);
        const std::uint32_t i = list[k];
        if (rec_[i].where == Where::Bucket && bucketOf(rec_[i].time) == cur_) heapPush(i);
    }
    list.clear();
    return true;
}

void EventQueue::redistributeOverflow() {
    std::vector<std::uint32_t> waiting;
    waiting.swap(overflow_);
    for (std::uint32_t i : waiting) {
        if (rec_[i].where == Where::Overflow) {
            rec_[i].where = Where::Nowhere;
            place(i);
        }
    }
}

void EventQueue::heapPush(std::uint32_t i) {
    rec_[i].where = Where::Heap;
    heap_.push_back({rec_[i].time, i});
    const auto k = static_cast<std::uint32_t>(heap_.size() - 1);
    rec_[i].slot = k;
    siftUp(k);
}

void EventQueue::heapRemove(std::uint32_t i) {
    const std::uint32_t k = rec_[i].slot;
    const Entry last = heap_.back();
    heap_.pop_back();
    rec_[i].where = Where::Nowhere;
    if (k == heap_.size()) return;
    heap_[k] = last;
    rec_[last.key].slot = k;
    siftUp(k);
    siftDown(rec_[last.key].slot);
}

void EventQueue::siftUp(std::uint32_t k) {
    const Entry e = heap_[k];
    while (k > 0) {
        const std::uint32_t parent = (k - 1) / 4;
        if (!before(e, heap_[parent])) break;
        heap_[k] = heap_[parent];
        rec_[heap_[k].key].slot = k;
        k = parent;
    }
    heap_[k] = e;
    rec_[e.key].slot = k;
}

void EventQueue::siftDown(std::uint32_t k) {
    const Entry e = heap_[k];
    const auto n = static_cast<std::uint32_t>(heap_.size());
    for (;;) {
        const std::uint32_t first = 4 * k + 1;
        if (first >= n) break;
        std::uint32_t best = first;
        const std::uint32_t last = first + 4 < n ? first + 4 : n;
        for (std::uint32_t c = first + 1; c < last; ++c) {
            if (before(heap_[c], heap_[best])) best = c;
        }
        if (!before(heap_[best], e)) break;
        heap_[k] = heap_[best];
        rec_[heap_[k].key].slot = k;
        k = best;
    }
    heap_[k] = e;
    rec_[e.key].slot = k;
}

}  // namespace psb::exact
