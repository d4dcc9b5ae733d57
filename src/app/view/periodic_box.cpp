#include "view/periodic_box.hpp"

#include <algorithm>
#include <cmath>

#include "view/label_places.hpp"

namespace psb::app {

std::vector<PeriodicImage> periodicImages(const World& world) {
    std::vector<PeriodicImage> images;
    const WorldDef& d = world.def();
    if (!d.periodic) return images;
    const ParticleArrays& p = world.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double r = p.radius[i];
        // Over the left edge: again at the right, and so on; over both a left or right and a
        // top or bottom edge, at the diagonal corner too.
        const double dx = p.x[i] < r ? d.width : p.x[i] > d.width - r ? -d.width : 0.0;
        const double dy = p.y[i] < r ? d.height : p.y[i] > d.height - r ? -d.height : 0.0;
        if (dx != 0.0) images.push_back({i, Vec2(dx, 0.0)});
        if (dy != 0.0) images.push_back({i, Vec2(0.0, dy)});
        if (dx != 0.0 && dy != 0.0) images.push_back({i, Vec2(dx, dy)});
    }
    return images;
}

namespace {

/// The dashes of the segment from `a` to `b` (pixels, a horizontal or vertical edge) that
/// reach into [lo, hi] along it (the window's extent on that axis), from `a`.
void dashEdge(Vec2 a, Vec2 b, double lo, double hi, std::vector<BoxDash>& out) {
    const double length = (b - a).norm();
    if (!(length > 0.0)) return;
    const Vec2 u = (b - a) / length;
    const double along = std::abs(u.x()) > 0.5 ? u.x() : u.y();  // ±1
    const double start = std::abs(u.x()) > 0.5 ? a.x() : a.y();
    // The part of [0, length] whose points lie in [lo, hi].
    const double s0 = along > 0 ? lo - start : start - hi;
    const double s1 = along > 0 ? hi - start : start - lo;
    const double period = PeriodicBoxView::kDashPixels + PeriodicBoxView::kGapPixels;
    const double first = std::max(0.0, std::floor(s0 / period));
    for (double k = first; k * period < std::min(length, s1); k += 1.0) {
        const double from = k * period;
        const double to = std::min(from + PeriodicBoxView::kDashPixels, length);
        if (to < s0) continue;
        out.push_back({a + from * u, a + to * u});
    }
}

}  // namespace

std::vector<BoxDash> boxDashes(const Camera& camera, double width, double height) {
    std::vector<BoxDash> dashes;
    const Vec2 a = camera.worldToScreen(Vec2::Zero());
    const Vec2 c = camera.worldToScreen(Vec2(width, height));
    const Vec2 b(c.x(), a.y()), d(a.x(), c.y());
    const double w = camera.viewportWidth(), h = camera.viewportHeight();
    const auto inside = [](double v, double limit) { return v >= -2.0 && v <= limit + 2.0; };
    // The horizontal edges where their line crosses the window, then the vertical ones; each
    // from a corner, so that the four corners are drawn.
    if (inside(a.y(), h)) dashEdge(a, b, 0.0, w, dashes);
    if (inside(c.y(), h)) dashEdge(c, d, 0.0, w, dashes);
    if (inside(a.x(), w)) dashEdge(d, a, 0.0, h, dashes);
    if (inside(c.x(), w)) dashEdge(b, c, 0.0, h, dashes);
    return dashes;
}

std::optional<PeriodicBoxView> periodicBoxView(const World& world, const Camera& camera) {
    const WorldDef& d = world.def();
    if (!d.periodic) return std::nullopt;
    PeriodicBoxView v;
    v.dashes = boxDashes(camera, d.width, d.height);
    // Half as thick as a walled box's walls, at least two pixels: a line, not a wall.
    v.thickness = std::max(2.0, 0.5 * boxWallPixels(d.width, d.height, camera.zoom()));
    v.images = periodicImages(world);
    return v;
}

}  // namespace psb::app
