#include "event_queue.hpp"

namespace psb::exact {

void EventQueue::reset(std::uint32_t n, double time) {
    heap_.resize(n);
    slot_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        heap_[i] = {time, i};
        slot_[i] = i;
    }
}

void EventQueue::update(std::uint32_t i, double time) {
    const std::uint32_t k = slot_[i];
    const double old = heap_[k].time;
    heap_[k].time = time;
    if (time < old) {
        siftUp(k);
    } else {
        siftDown(k);
    }
}

void EventQueue::siftUp(std::uint32_t k) {
    const Entry e = heap_[k];
    while (k > 0) {
        const std::uint32_t parent = (k - 1) / 4;
        if (!before(e, heap_[parent])) break;
        heap_[k] = heap_[parent];
        slot_[heap_[k].key] = k;
        k = parent;
    }
    heap_[k] = e;
    slot_[e.key] = k;
}

void EventQueue::siftDown(std::uint32_t k) {
    const Entry e = heap_[k];
    const std::uint32_t n = size();
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
        slot_[heap_[k].key] = k;
        k = best;
    }
    heap_[k] = e;
    slot_[e.key] = k;
}

}  // namespace psb::exact
