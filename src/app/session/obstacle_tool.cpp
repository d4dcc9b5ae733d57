#include "session/obstacle_tool.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "session/units.hpp"

namespace psb::app {
namespace {

bool inBox(const Vec2& p, const WorldDef& box) {
    return p.x() >= 0.0 && p.x() <= box.width && p.y() >= 0.0 && p.y() <= box.height;
}

bool finite(const Vec2& p) {
    return std::isfinite(p.x()) && std::isfinite(p.y());
}

}  // namespace

ObstacleSizes obstacleSizesFor(double typicalRadius) {
    ObstacleSizes s;
    s.pegRadius = typicalRadius;
    s.wallThickness = typicalRadius;
    return s;
}

void ObstacleTool::press(Kind kind, const Vec2& point) {
    kind_ = kind;
    press_ = point;
    pointer_ = point;
}

void ObstacleTool::pressOn(std::size_t index, const Obstacle& obstacle, const Vec2& point) {
    press(Kind::Move, point);
    movedIndex_ = index;
    moved_ = obstacle;
}

namespace {

Obstacle translated(Obstacle o, const Vec2& by) {
    o.a += by;
    o.b += by;
    return o;
}

bool obstacleInBox(const Obstacle& o, const WorldDef& box) {
    return inBox(o.a, box) && inBox(o.b, box);
}

}  // namespace

void ObstacleTool::moveTo(const Vec2& point) {
    pointer_ = point;
}

ObstaclePlacement ObstacleTool::release(const Vec2& point, const ObstacleSizes& sizes,
                                        const WorldDef& box, double minLength) {
    pointer_ = point;
    ObstaclePlacement out;
    if (!press_) return out;
    const Vec2 from = *press_;
    press_.reset();
    if (!finite(from) || !finite(point)) {
        out.refusal = "Nothing placed: the pointer is not at a number of metres";
        return out;
    }
    if (kind_ == Kind::Move) {
        if (!((point - from).norm() >= minLength)) return out;  // a click: it selects
        const Obstacle o = translated(moved_, point - from);
        if (!obstacleInBox(o, box)) {
            out.refusal = std::string("Not moved: the ") + obstacleNoun(o) + " would leave the box";
            return out;
        }
        out.obstacle = o;
        return out;
    }
    if (kind_ == Kind::Peg) {
        if (!inBox(point, box)) {
            out.refusal = "No peg placed: click inside the box";
            return out;
        }
        out.obstacle = Obstacle::peg(point, sizes.pegRadius);
        return out;
    }
    if (!inBox(from, box)) {
        out.refusal = "No wall drawn: start the drag inside the box";
        return out;
    }
    const Vec2 to(std::clamp(point.x(), 0.0, box.width), std::clamp(point.y(), 0.0, box.height));
    if (!((to - from).norm() >= minLength) || to == from) {
        out.refusal = "No wall drawn: drag from one end of the wall to the other";
        return out;
    }
    out.obstacle = Obstacle::segment(from, to, sizes.wallThickness);
    return out;
}

std::optional<Obstacle> ObstacleTool::preview(const ObstacleSizes& sizes,
                                              const WorldDef& box) const {
    if (press_ && kind_ == Kind::Move) {
        const Obstacle o = translated(moved_, pointer_ - *press_);
        if (o == moved_ || !obstacleInBox(o, box)) return std::nullopt;
        return o;
    }
    if (!press_ || kind_ != Kind::Wall || !inBox(*press_, box)) return std::nullopt;
    const Vec2 to(std::clamp(pointer_.x(), 0.0, box.width),
                  std::clamp(pointer_.y(), 0.0, box.height));
    if (to == *press_) return std::nullopt;
    return Obstacle::segment(*press_, to, sizes.wallThickness);
}

std::string obstacleSizesRefusal(const ObstacleSizes& sizes, const WorldDef& box) {
    const double most = 0.5 * std::min(box.width, box.height);
    const auto check = [most](double v, const char* what) -> std::string {
        if (!std::isfinite(v) || !(v > 0.0)) {
            return std::string("The ") + what + " must be a number above 0";
        }
        if (v > most) {
            return std::string("The ") + what + " can be at most " + quantity(most, "m") +
                   " (half the box)";
        }
        return {};
    };
    if (std::string r = check(sizes.pegRadius, "peg radius"); !r.empty()) return r;
    return check(sizes.wallThickness, "wall thickness");
}

double distanceToObstacle(const Obstacle& o, const Vec2& p) {
    Vec2 nearest = o.a;
    if (!o.isPeg()) {
        const Vec2 ab = o.b - o.a;
        const double len2 = ab.squaredNorm();
        const double t = len2 > 0.0 ? std::clamp((p - o.a).dot(ab) / len2, 0.0, 1.0) : 0.0;
        nearest = o.a + t * ab;
    }
    return (p - nearest).norm() - o.radius;
}

std::optional<std::size_t> pickObstacle(const Obstacles& obstacles, const Vec2& point,
                                        double slop) {
    std::optional<std::size_t> best;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
        const double d = distanceToObstacle(obstacles[i], point);
        if (d <= slop && d < bestDistance) {
            best = i;
            bestDistance = d;
        }
    }
    return best;
}

const char* obstacleNoun(const Obstacle& obstacle) {
    return obstacle.isPeg() ? "peg" : "wall";
}

}  // namespace psb::app
