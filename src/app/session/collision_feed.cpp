#include "session/collision_feed.hpp"

namespace psb::app {

std::optional<CollisionLog> mergeWanted(const std::optional<CollisionLog>& a,
                                        const std::optional<CollisionLog>& b) {
    if (!a) return b;
    if (!b) return a;
    if (a->keepsAll() || b->keepsAll()) return CollisionLog();
    std::vector<ParticleId> ids = a->chosen();
    ids.insert(ids.end(), b->chosen().begin(), b->chosen().end());
    return CollisionLog(std::move(ids));  // sorted, each id once
}

void listen(World& world, const std::optional<CollisionLog>& wanted) {
    if (!wanted) {
        if (world.recordingCollisions()) world.stopRecordingCollisions();
        return;
    }
    const CollisionLog* now = world.collisionLog();
    if (now != nullptr && now->keepsAll() == wanted->keepsAll() &&
        now->chosen() == wanted->chosen()) {
        (void)world.takeCollisions();
        return;
    }
    world.recordCollisions(*wanted);
}

std::vector<Collision> heard(World& world) {
    if (!world.recordingCollisions()) return {};
    return world.takeCollisions();
}

}  // namespace psb::app
