#include <particle_sandbox/detail/id_table.hpp>

#include <algorithm>
#include <functional>

namespace psb::detail {

ParticleId IdTable::allocate(std::uint32_t index) {
    std::uint32_t slot;
    if (!freeSlots_.empty()) {
        std::pop_heap(freeSlots_.begin(), freeSlots_.end(), std::greater<>{});
        slot = freeSlots_.back();
        freeSlots_.pop_back();
    } else {
        slot = static_cast<std::uint32_t>(index_.size());
        index_.push_back(kFree);
        generation_.push_back(0);
    }
    index_[slot] = index;
    return ParticleId{slot, generation_[slot]};
}

void IdTable::release(ParticleId id) {
    index_[id.slot] = kFree;
    ++generation_[id.slot];  // every id handed out for this slot so far is now stale
    freeSlots_.push_back(id.slot);
    std::push_heap(freeSlots_.begin(), freeSlots_.end(), std::greater<>{});
}

void IdTable::relocate(ParticleId id, std::uint32_t index) {
    index_[id.slot] = index;
}

std::optional<std::uint32_t> IdTable::find(ParticleId id) const {
    if (id.slot >= index_.size() || generation_[id.slot] != id.generation ||
        index_[id.slot] == kFree) {
        return std::nullopt;
    }
    return index_[id.slot];
}

void IdTable::clear() {
    // Keep generations so that ids from before the clear stay stale.
    freeSlots_.clear();
    for (std::uint32_t s = static_cast<std::uint32_t>(index_.size()); s-- > 0;) {
        if (index_[s] != kFree) ++generation_[s];
        index_[s] = kFree;
        freeSlots_.push_back(s);
    }
    std::make_heap(freeSlots_.begin(), freeSlots_.end(), std::greater<>{});
}

void IdTable::reserve(std::size_t slots) {
    index_.reserve(slots);
    generation_.reserve(slots);
}

std::size_t IdTable::memoryBytes() const {
    return sizeof(std::uint32_t) *
           (index_.capacity() + generation_.capacity() + freeSlots_.capacity());
}

}  // namespace psb::detail
