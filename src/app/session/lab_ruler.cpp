#include "session/lab_ruler.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "session/camera.hpp"

namespace psb::app {

void LabRuler::place(double width, double height) {
    a_ = Vec2(0.25 * width, 0.5 * height);
    b_ = Vec2(0.75 * width, 0.5 * height);
    box_ = Vec2(width, height);
    held_.reset();
}

void LabRuler::keepIn(double width, double height) {
    if (box_ != Vec2(width, height)) place(width, height);
}

std::optional<LabRuler::Part> LabRuler::partAt(const Vec2& screen, const Camera& camera) const {
    const Vec2 pa = camera.worldToScreen(a_), pb = camera.worldToScreen(b_);
    const double da = (screen - pa).norm(), db = (screen - pb).norm();
    if (std::min(da, db) <= kGrabPixels) return da <= db ? Part::EndA : Part::EndB;
    const Vec2 along = pb - pa;
    const double len2 = along.squaredNorm();
    if (!(len2 > 0.0)) return std::nullopt;
    const double t = std::clamp((screen - pa).dot(along) / len2, 0.0, 1.0);
    if ((screen - (pa + t * along)).norm() <= 0.6 * kGrabPixels) return Part::Edge;
    return std::nullopt;
}

void LabRuler::take(Part part, const Vec2& at) {
    held_ = part;
    switch (part) {
        case Part::EndA:
            grabOffset_ = a_ - at;
            break;
        case Part::EndB:
            grabOffset_ = b_ - at;
            break;
        case Part::Edge:
            grabOffset_ = a_ - at;
            break;
    }
}

void LabRuler::moveTo(const Vec2& at) {
    if (!held_ || !at.allFinite()) return;
    const Vec2 to = at + grabOffset_;
    switch (*held_) {
        case Part::EndA:
            a_ = to;
            break;
        case Part::EndB:
            b_ = to;
            break;
        case Part::Edge: {
            const Vec2 span = b_ - a_;
            a_ = to;
            b_ = to + span;
            break;
        }
    }
}

double slopeDegrees(const Vec2& d) {
    if (d == Vec2::Zero() || !d.allFinite()) return 0.0;
    return std::atan2(std::abs(d.y()), std::abs(d.x())) * 180.0 / std::numbers::pi;
}

}  // namespace psb::app
