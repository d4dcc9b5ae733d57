#include "obstacles/obstacle_validate.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "world/validate.hpp"

namespace psb::detail {
namespace {

std::string point(const Vec2& v) {
    return pointText(v);
}

std::string number(double v) {
    return csv::number(v);
}

bool finite(const Vec2& v) {
    return std::isfinite(v.x()) && std::isfinite(v.y());
}

bool inBox(const Vec2& v, double width, double height) {
    return v.x() >= 0.0 && v.x() <= width && v.y() >= 0.0 && v.y() <= height;
}

std::string boxText(double width, double height) {
    return "the " + csv::number(width) + " x " + csv::number(height) + " m box";
}

}  // namespace

void validateObstacle(const Obstacle& o, std::size_t index, double width, double height,
                      const char* where) {
    const bool peg = o.kind == Obstacle::Kind::Peg;
    if (!peg && o.kind != Obstacle::Kind::Segment) {
        fail(where, ("obstacle " + std::to_string(index)).c_str(), "is of no known kind");
    }
    const std::string what = "obstacle " + std::to_string(index) + (peg ? " (peg)" : " (segment)");
    const char* w = what.c_str();
    if (peg) {
        if (!finite(o.a)) fail(where, w, "centre must be finite (got " + point(o.a) + ")");
        if (!(o.b == o.a)) {
            fail(where, w,
                 "second point must equal its centre " + point(o.a) + " (got " + point(o.b) + ")");
        }
        if (!std::isfinite(o.radius) || !(o.radius > 0.0)) {
            fail(where, w, "radius must be finite and > 0 " + got(o.radius));
        }
        if (o.radius > std::max(width, height)) {
            fail(where, w,
                 "radius must be at most the box's larger side, " +
                     number(std::max(width, height)) + " m " + got(o.radius));
        }
        if (!inBox(o.a, width, height)) {
            fail(where, w,
                 "cannot be drawn in " + boxText(width, height) + ": its centre " + point(o.a) +
                     " lies outside it");
        }
        return;
    }
    if (!finite(o.a)) fail(where, w, "first end must be finite (got " + point(o.a) + ")");
    if (!finite(o.b)) fail(where, w, "second end must be finite (got " + point(o.b) + ")");
    if (!std::isfinite(o.radius) || !(o.radius > 0.0)) {
        fail(where, w, "thickness must be finite and > 0 " + got(2.0 * o.radius));
    }
    if (o.radius > std::max(width, height)) {
        fail(where, w,
             "thickness must be at most twice the box's larger side, " +
                 number(2.0 * std::max(width, height)) + " m " + got(2.0 * o.radius));
    }
    if (o.a == o.b) {
        fail(where, w, "has zero length: both ends are at " + point(o.a) + " (use a peg)");
    }
    for (const Vec2* end : {&o.a, &o.b}) {
        if (!inBox(*end, width, height)) {
            fail(where, w,
                 "cannot be drawn in " + boxText(width, height) + ": its end " + point(*end) +
                     " lies outside it");
        }
    }
}

void validateObstacles(const Obstacles& obstacles, double width, double height, const char* where) {
    for (std::size_t i = 0; i < obstacles.size(); ++i)
        validateObstacle(obstacles[i], i, width, height, where);
}

}  // namespace psb::detail
