#include "platform/touch.hpp"

#include <iterator>

#include "platform/clock.hpp"

namespace psb::app {

namespace {

/// Fingers closer than this, pixels, do not zoom (their distance's ratio would be noise).
constexpr double kMinPinchPixels = 20.0;

}  // namespace

// The first two fingers down gesture; a third only rests.
Vec2 TouchGestures::midpoint() const {
    const auto a = fingers_.begin();
    return 0.5 * (a->second + std::next(a)->second);
}

double TouchGestures::spread() const {
    const auto a = fingers_.begin();
    return (a->second - std::next(a)->second).norm();
}

std::vector<Command> TouchGestures::translate(const SDL_TouchFingerEvent& e, SDL_Point output,
                                              Vec2 mouse) {
    const Vec2 at(e.x * output.x, e.y * output.y);
    std::vector<Command> out;
    switch (e.type) {
        case SDL_FINGERDOWN:
            fingers_[e.fingerId] = at;
            if (fingers_.size() == 2 && !pinching_) {
                pinching_ = true;
                out.emplace_back(cmd::PointerUp{mouse, ticksToSeconds(e.timestamp), true});
            }
            break;
        case SDL_FINGERMOTION: {
            const auto it = fingers_.find(e.fingerId);
            if (it == fingers_.end()) break;
            if (fingers_.size() < 2) {
                it->second = at;
                break;
            }
            const Vec2 mid0 = midpoint();
            const double spread0 = spread();
            it->second = at;
            const Vec2 mid1 = midpoint();
            const double spread1 = spread();
            if (mid1 != mid0) out.emplace_back(cmd::Pan{mid1 - mid0});
            if (spread0 >= kMinPinchPixels && spread1 >= kMinPinchPixels && spread1 != spread0) {
                out.emplace_back(cmd::Zoom{mid1, spread1 / spread0});
            }
            break;
        }
        case SDL_FINGERUP:
            fingers_.erase(e.fingerId);
            if (fingers_.empty()) pinching_ = false;
            break;
        default:
            break;
    }
    return out;
}

}  // namespace psb::app
