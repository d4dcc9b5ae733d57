#pragma once
// The camera: the one place where coordinates cross between the screen (pixels, origin at the
// window's top-left, y down) and the world (metres, origin at the box's top-left, y down).
//
//   screen = (world - offset) * zoom        world = screen / zoom + offset
//
// This is the original program's mapping; what changes is how zoom moves. The original added
// ±0.1 per wheel notch about the top-left corner and could drift to ~1e-17, after which nothing
// could be grabbed. Here zoom is multiplicative, happens about a chosen screen point (the
// cursor), and is clamped to limits set relative to the zoom that fits the box.

#include <particle_sandbox/math.hpp>

namespace psb::app {

class Camera {
  public:
    /// Size of the drawable area, pixels (> 0; smaller values are clamped to 1).
    void setViewport(int width, int height);
    [[nodiscard]] int viewportWidth() const { return width_; }
    [[nodiscard]] int viewportHeight() const { return height_; }

    [[nodiscard]] Vec2 worldToScreen(const Vec2& world) const { return (world - offset_) * zoom_; }
    [[nodiscard]] Vec2 screenToWorld(const Vec2& screen) const { return screen / zoom_ + offset_; }
    /// worldToScreen as a scale and a shift, screen = origin + scale × world, for code that maps
    /// many points in floats (the trails): the same mapping, stated once here.
    struct Transform {
        float scale = 1.0f;
        float originX = 0.0f;
        float originY = 0.0f;
    };
    [[nodiscard]] Transform transform() const {
        const Vec2 o = worldToScreen(Vec2::Zero());
        return {static_cast<float>(zoom_), static_cast<float>(o.x()), static_cast<float>(o.y())};
    }
    /// A world length (metres) in pixels, and back.
    [[nodiscard]] double toScreen(double metres) const { return metres * zoom_; }
    [[nodiscard]] double toWorld(double pixels) const { return pixels / zoom_; }

    /// Pixels per metre.
    [[nodiscard]] double zoom() const { return zoom_; }
    /// World point shown at the screen's top-left corner, metres.
    [[nodiscard]] const Vec2& offset() const { return offset_; }
    [[nodiscard]] double minZoom() const { return minZoom_; }
    [[nodiscard]] double maxZoom() const { return maxZoom_; }

    /// Sets zoom and offset directly (zoom clamped to the limits).
    void set(double zoom, const Vec2& offset);
    /// Multiplies the zoom by `factor`, clamped to the limits, keeping the world point under
    /// `screenPoint` where it is on screen.
    void zoomAbout(const Vec2& screenPoint, double factor);
    /// Moves the view so the world slides by `pixels` on screen (a drag to the right moves the
    /// world to the right).
    void panPixels(const Vec2& pixels);
    /// Centres a `width` × `height` metre box in the viewport with `marginPixels` around it,
    /// between a band of `topInsetPixels` kept free above (for the HUD), one of
    /// `bottomInsetPixels` below (the messages, the values table) and a column of
    /// `rightInsetPixels` at the right (the panels) and one of `leftInsetPixels` at the left (the
    /// control panel), and resets the zoom limits around that zoom (1/50 to 500 times it). The
    /// top band is kept up to 60 % of the viewport (the HUD's wrapped lines at 200 % in a short
    /// window), the bottom one up to 80 % of it less the top; the left column up to 75 % of the
    /// width, the right one up to 75 % less the left.
    void fit(double width, double height, double marginPixels = 10.0, double topInsetPixels = 0.0,
             double bottomInsetPixels = 0.0, double rightInsetPixels = 0.0,
             double leftInsetPixels = 0.0);
    /// Moves the view back as little as needed so that the box [0, width] × [0, height] stays
    /// within one viewport of the screen (panning has a limit: the box can go off screen, where
    /// a marker points to it, but never far away).
    void keepNear(double width, double height);
    /// The screen rectangle of the world box [0, width] × [0, height]: top-left and size, pixels.
    struct ScreenBox {
        Vec2 topLeft;
        Vec2 size;
    };
    [[nodiscard]] ScreenBox boxOnScreen(double width, double height) const;

  private:
    int width_ = 800;
    int height_ = 800;
    double zoom_ = 1.0;
    Vec2 offset_ = Vec2::Zero();
    double minZoom_ = 1e-3;
    double maxZoom_ = 1e3;
};

}  // namespace psb::app
