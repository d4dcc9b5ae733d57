// The exact stepper's jam guards: the per-step counts of hits on held particles, and the runs
// of hits without time or room between. Why: jam_guard.hpp.

#include "exact/jam_guard.hpp"

namespace psb::exact {

void JamGuard::startStep(std::vector<Body>& bodies, std::vector<Cold>& cold) {
    for (const std::uint32_t i : counted_) {
        bodies[i].flags &= ~kJammed;
        cold[i].heldHits = 0;
    }
    counted_.clear();
}

bool JamGuard::countRun(std::uint32_t who, bool stuck) {
    if (!stuck) {
        repeats_.erase(who);  // it moved: its run of hits ends
        return false;
    }
    std::uint32_t& hits = repeats_[who];
    return !(hits < kJamHits && ++hits < kJamHits);
}

}  // namespace psb::exact
