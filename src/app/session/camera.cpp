#include "session/camera.hpp"

#include <algorithm>
#include <cmath>

namespace psb::app {

void Camera::setViewport(int width, int height) {
    width_ = std::max(width, 1);
    height_ = std::max(height, 1);
}

void Camera::set(double zoom, const Vec2& offset) {
    if (std::isfinite(zoom) && zoom > 0.0) zoom_ = std::clamp(zoom, minZoom_, maxZoom_);
    if (offset.allFinite()) offset_ = offset;
}

void Camera::zoomAbout(const Vec2& screenPoint, double factor) {
    if (!std::isfinite(factor) || factor <= 0.0 || !screenPoint.allFinite()) return;
    const Vec2 anchor = screenToWorld(screenPoint);
    zoom_ = std::clamp(zoom_ * factor, minZoom_, maxZoom_);
    // Keep `anchor` under `screenPoint`: screenPoint = (anchor - offset) * zoom.
    offset_ = anchor - screenPoint / zoom_;
}

void Camera::panPixels(const Vec2& pixels) {
    if (pixels.allFinite()) offset_ -= pixels / zoom_;
}

void Camera::fit(double width, double height, double marginPixels, double topInsetPixels,
                 double bottomInsetPixels, double rightInsetPixels, double leftInsetPixels) {
    if (!(width > 0.0) || !(height > 0.0) || !std::isfinite(width) || !std::isfinite(height)) {
        return;
    }
    // The top band holds the HUD: a box drawn under its lines is read through text, a smaller
    // one is still read. Given up past 60 % of the window (a window no one could use).
    const double top = std::clamp(topInsetPixels, 0.0, 0.6 * height_);
    // The bottom holds the messages and, while shown, the values table's band: kept while they
    // leave the box a fifth of the window (the view keeps the band smaller than that).
    const double bottom = std::clamp(bottomInsetPixels, 0.0, std::max(0.0, 0.8 * height_ - top));
    // The control panel's column is kept free while it leaves the box a quarter of the window
    // (the view folds the panel before that: box_area.hpp's controlsFit; a panel at 200 % in a
    // 1000-pixel window takes 62 % of it).
    const double left = std::clamp(leftInsetPixels, 0.0, 0.75 * width_);
    const double right = std::clamp(rightInsetPixels, 0.0, std::max(0.0, 0.75 * width_ - left));
    const double usableW = std::max(1.0, width_ - left - right - 2.0 * marginPixels);
    const double usableH = std::max(1.0, height_ - top - bottom - 2.0 * marginPixels);
    const double z = std::min(usableW / width, usableH / height);
    minZoom_ = z / 50.0;
    maxZoom_ = z * 500.0;
    zoom_ = z;
    // The box's centre maps to the centre of the area the insets leave.
    const Vec2 centre(width / 2.0, height / 2.0);
    offset_ =
        centre -
        Vec2(left + (width_ - left - right) / 2.0, top + (height_ - top - bottom) / 2.0) / zoom_;
}

void Camera::keepNear(double width, double height) {
    const ScreenBox b = boxOnScreen(width, height);
    // Screen x of the box's left edge may lie in [-W - size, 2W]: some of it within a viewport.
    const auto shift = [](double lo, double size, double extent) {
        const double minLo = -extent - size, maxLo = 2.0 * extent;
        return lo < minLo ? minLo - lo : lo > maxLo ? maxLo - lo : 0.0;
    };
    const Vec2 d(shift(b.topLeft.x(), b.size.x(), width_),
                 shift(b.topLeft.y(), b.size.y(), height_));
    if (d != Vec2::Zero()) panPixels(d);
}

Camera::ScreenBox Camera::boxOnScreen(double width, double height) const {
    return {worldToScreen(Vec2::Zero()), Vec2(toScreen(width), toScreen(height))};
}

}  // namespace psb::app
