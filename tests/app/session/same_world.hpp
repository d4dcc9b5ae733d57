#pragma once
// Two worlds compared bit for bit: every particle's every field, the ids, the time, the
// counters and the laws (the timeline's and the undo history's tests).

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include <particle_sandbox/world.hpp>

namespace psb::app {

template <typename T>
inline bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// Every particle's every field, the ids, the time and (unless `counters` is false: the session
// clears them every frame, a rebuilt frame sums them since its keyframe) the counters.
inline ::testing::AssertionResult identical(const World& a, const World& b, bool counters = true) {
    const ParticleArrays &p = a.particles(), &q = b.particles();
    if (!sameBits(p.x, q.x) || !sameBits(p.y, q.y)) {
        return ::testing::AssertionFailure() << "positions differ";
    }
    if (!sameBits(p.vx, q.vx) || !sameBits(p.vy, q.vy)) {
        return ::testing::AssertionFailure() << "velocities differ";
    }
    if (!sameBits(p.invMass, q.invMass) || !sameBits(p.mass, q.mass) ||
        !sameBits(p.radius, q.radius) || !sameBits(p.color, q.color) || !sameBits(p.id, q.id)) {
        return ::testing::AssertionFailure() << "masses, radii, colours or ids differ";
    }
    if (a.time() != b.time()) return ::testing::AssertionFailure() << "times differ";
    const StepCounters &c = a.counters(), &d = b.counters();
    if (counters && (c.collisions != d.collisions || c.wallCollisions != d.wallCollisions ||
                     std::memcmp(&c.wallImpulse, &d.wallImpulse, sizeof c.wallImpulse) != 0)) {
        return ::testing::AssertionFailure() << "counters differ";
    }
    if (a.def().restitution != b.def().restitution || a.def().gravity != b.def().gravity) {
        return ::testing::AssertionFailure() << "laws differ";
    }
    return ::testing::AssertionSuccess();
}

}  // namespace psb::app
