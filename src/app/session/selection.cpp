#include "session/selection.hpp"

#include <cstdio>

namespace psb::app {

bool Selection::forgetIfGone(const World& world) {
    if (!id_ || world.contains(*id_)) return false;
    id_.reset();
    return true;
}

std::string selectionLogLine(const Particle& p, const Axes& axes) {
    const Vec2 at = axes.point(p.position), v = axes.vector(p.velocity);
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "[I] Selected particle %llu at [%.2f, %.2f] m with velocity [%.2f, %.2f] m/s, "
                  "mass %.4g kg, radius %.4g m",
                  static_cast<unsigned long long>(particleNumber(p.id)), at.x(), at.y(), v.x(),
                  v.y(), p.mass, p.radius);
    return buf;
}

}  // namespace psb::app
