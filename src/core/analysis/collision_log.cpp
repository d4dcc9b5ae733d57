#include <particle_sandbox/collision_log.hpp>

#include <algorithm>

namespace psb {
namespace {

bool lessId(ParticleId a, ParticleId b) {
    return a.slot != b.slot ? a.slot < b.slot : a.generation < b.generation;
}

}  // namespace

CollisionLog::CollisionLog(std::vector<ParticleId> ids) : all_(false), ids_(std::move(ids)) {
    std::sort(ids_.begin(), ids_.end(), lessId);
    ids_.erase(std::unique(ids_.begin(), ids_.end()), ids_.end());
}

bool CollisionLog::chosen(ParticleId id) const {
    return all_ || std::binary_search(ids_.begin(), ids_.end(), id, lessId);
}

void CollisionLog::add(const Collision& c) {
    if (chosen(c.a) || (!c.b.isNull() && chosen(c.b))) records_.push_back(c);
}

void CollisionLog::append(const std::vector<Collision>& more) {
    records_.insert(records_.end(), more.begin(), more.end());
}

std::vector<Collision> CollisionLog::take() {
    std::vector<Collision> out;
    out.swap(records_);
    return out;
}

}  // namespace psb
