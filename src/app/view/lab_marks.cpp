#include "view/lab_marks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "session/units.hpp"
#include "view/screen_layout.hpp"

namespace psb::app {

namespace {

/// How far the reading's centre is from the ruler's middle, pixels.
constexpr double kReadingOffset = 22.0;

/// The smallest of 1, 2 or 5 × 10^k at least `least`.
double roundStep(double least) {
    if (!(least > 0.0) || !std::isfinite(least)) return 0.0;
    const double p = std::pow(10.0, std::floor(std::log10(least)));
    for (const double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * p >= least * (1.0 - 1e-12)) return m * p;
    }
    return 10.0 * p;
}

/// `metres` with the digits a grid of `step` needs: "0", "0.5 m", "2 m", "150 m".
std::string gridLabel(double metres, double step) {
    if (std::abs(metres) < 1e-9 * step) return "0";
    const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*f m", decimals, metres);
    return buf;
}

/// The strong lines: every fifth step when the step starts with 1 or 2, every second with 5
/// (so 0, 5, 10 m or 0, 1, 2 m at steps of 1 or 0.5 m).
int strongEvery(double step) {
    const double lead = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    return lead > 4.0 ? 2 : 5;
}

}  // namespace

GridView gridView(const Camera& camera, double width, double height, bool yUp, double minPixels) {
    GridView g;
    if (!(camera.zoom() > 0.0) || !(width > 0.0) || !(height > 0.0)) return g;
    g.step = roundStep(camera.toWorld(std::max(kGridMinPixels, minPixels)));
    if (!(g.step > 0.0)) return g;
    // The box's visible part, in metres.
    const Vec2 lo = camera.screenToWorld(Vec2(0.0, 0.0));
    const Vec2 hi = camera.screenToWorld(Vec2(camera.viewportWidth(), camera.viewportHeight()));
    const double x0 = std::max(0.0, lo.x()), x1 = std::min(width, hi.x());
    const double y0 = std::max(0.0, lo.y()), y1 = std::min(height, hi.y());
    if (!(x1 > x0) || !(y1 > y0)) return g;
    const Vec2 top0 = camera.worldToScreen(Vec2(x0, y0)),
               bottom1 = camera.worldToScreen(Vec2(x1, y1));
    const int every = strongEvery(g.step);
    // Labels just inside the box's top and left edges, or the window's when those are off it.
    const double labelY = top0.y() + 9.0, labelX = top0.x() + 4.0;
    const auto first = static_cast<long long>(std::ceil(x0 / g.step - 1e-9));
    const auto last = static_cast<long long>(std::floor(x1 / g.step + 1e-9));
    for (long long k = first; k <= last; ++k) {
        const double x = camera.worldToScreen(Vec2(static_cast<double>(k) * g.step, 0.0)).x();
        g.lines.push_back({Vec2(x, top0.y()), Vec2(x, bottom1.y()), k % every == 0});
        // The corner and the far edge are left bare (a label there would cross the wall).
        if (k != 0 && static_cast<double>(k) * g.step < width - 1e-9 * g.step) {
            g.labels.push_back(
                {Vec2(x, labelY), gridLabel(static_cast<double>(k) * g.step, g.step)});
        }
    }
    // Heights as the numbers read them: from the floor up with y up (Axes), else from the top
    // edge down; the lines at round numbers of those.
    const double shown0 = yUp ? height - y1 : y0, shown1 = yUp ? height - y0 : y1;
    const auto firstY = static_cast<long long>(std::ceil(shown0 / g.step - 1e-9));
    const auto lastY = static_cast<long long>(std::floor(shown1 / g.step + 1e-9));
    for (long long k = firstY; k <= lastY; ++k) {
        const double shown = static_cast<double>(k) * g.step;
        const double y = camera.worldToScreen(Vec2(0.0, yUp ? height - shown : shown)).y();
        g.lines.push_back({Vec2(top0.x(), y), Vec2(bottom1.x(), y), k % every == 0});
        if (k != 0 && static_cast<double>(k) * g.step < height - 1e-9 * g.step) {
            g.labels.push_back(
                {Vec2(labelX, y), gridLabel(static_cast<double>(k) * g.step, g.step), true});
        }
    }
    g.legend = "Grid: ";
    g.legend += quantity(g.step, "m");
    g.legend += yUp ? " squares, from the bottom-left corner (y up)"
                    : " squares, from the top-left corner (y down)";
    return g;
}

RulerView rulerView(const LabRuler& ruler, const Camera& camera) {
    RulerView v;
    v.a = camera.worldToScreen(ruler.a());
    v.b = camera.worldToScreen(ruler.b());
    v.held = ruler.held();
    const double length = ruler.length();
    const double pixels = (v.b - v.a).norm();
    const Vec2 u = pixels > 0.0 ? Vec2((v.b - v.a) / pixels) : Vec2(1.0, 0.0);
    const Vec2 n(-u.y(), u.x());
    if (length > 0.0 && camera.zoom() > 0.0) {
        v.tickStep = roundStep(camera.toWorld(kRulerTickPixels));
        const int every = strongEvery(v.tickStep);
        const auto count = static_cast<long long>(std::floor(length / v.tickStep + 1e-9));
        for (long long k = 0; k <= count && k <= 2000; ++k) {
            const Vec2 at = v.a + u * camera.toScreen(static_cast<double>(k) * v.tickStep);
            const bool strong = k % every == 0;
            v.ticks.push_back({at, at + n * (strong ? 9.0 : 5.0), strong});
        }
    }
    v.label.text = rulerLine(ruler);
    // Beside the middle, on the side of the ticks' normal turned to point down the screen.
    const Vec2 side = n.y() >= 0.0 ? n : Vec2(-n);
    v.label.at = 0.5 * (v.a + v.b) + side * kReadingOffset;
    return v;
}

PixelRect labelRect(const MarkLabel& label, const TextMeasure& font, int pad) {
    const int w = font.measure(label.text), h = font.lineHeight();
    // As the drawing layer places the text: whole pixels, centred or from the left.
    const int x = static_cast<int>(std::lround(label.at.x() - (label.left ? 0.0 : 0.5 * w)));
    const int y = static_cast<int>(std::lround(label.at.y() - 0.5 * h));
    return {x - pad, y - pad / 2, w + 2 * pad, h + pad};
}

void keepMarkLabelsClear(GridView* grid, RulerView* ruler, const TextMeasure& font,
                         const PixelRect& room, const std::vector<PixelRect>& keepOut) {
    const auto inside = [&room](const PixelRect& r) {
        return r.x >= room.x && r.y >= room.y && r.x + r.w <= room.x + room.w &&
               r.y + r.h <= room.y + room.h;
    };
    const auto clear = [&keepOut](const PixelRect& r) {
        return std::none_of(keepOut.begin(), keepOut.end(),
                            [&r](const PixelRect& k) { return overlaps(r, k); });
    };
    PixelRect reading{};
    if (ruler != nullptr) {
        MarkLabel& l = ruler->label;
        const Vec2 middle = 0.5 * (ruler->a + ruler->b);
        const Vec2 below = l.at - middle;  // the side chosen by rulerView
        // The label's centre moved so that its rectangle lies in the room, if it can.
        const auto slid = [&](Vec2 at) {
            MarkLabel moved = l;
            moved.at = at;
            const PixelRect r = labelRect(moved, font, kReadingPad);
            double dx = 0.0, dy = 0.0;
            if (r.x < room.x) dx = room.x - r.x;
            if (r.x + r.w + dx > room.x + room.w) dx = room.x + room.w - (r.x + r.w);
            if (r.y < room.y) dy = room.y - r.y;
            if (r.y + r.h + dy > room.y + room.h) dy = room.y + room.h - (r.y + r.h);
            return Vec2(at + Vec2(dx, dy));
        };
        const Vec2 candidates[4] = {middle + below, middle - below, slid(middle + below),
                                    slid(middle - below)};
        Vec2 chosen = candidates[2];
        for (const Vec2& c : candidates) {
            MarkLabel moved = l;
            moved.at = c;
            const PixelRect r = labelRect(moved, font, kReadingPad);
            if (inside(r) && clear(r)) {
                chosen = c;
                break;
            }
        }
        l.at = Vec2(std::round(chosen.x()), std::round(chosen.y()));
        reading = labelRect(l, font, kReadingPad);
    }
    if (grid != nullptr) {
        std::vector<MarkLabel>& labels = grid->labels;
        labels.erase(std::remove_if(labels.begin(), labels.end(),
                                    [&](const MarkLabel& g) {
                                        const PixelRect r = labelRect(g, font);
                                        return !inside(r) || !clear(r) || overlaps(r, reading);
                                    }),
                     labels.end());
    }
}

MarkLabel wallAngleLabel(const Vec2& a, const Vec2& b, const Camera& camera) {
    MarkLabel l;
    char angle[32];
    std::snprintf(angle, sizeof angle, "%.1f\u00b0", slopeDegrees(b - a));
    l.text = quantity((b - a).norm(), "m");
    l.text += ", ";
    l.text += angle;
    // Beyond the end being dragged, clear of the pointer.
    const Vec2 pa = camera.worldToScreen(a), pb = camera.worldToScreen(b);
    const double length = (pb - pa).norm();
    const Vec2 u = length > 0.0 && std::isfinite(length) ? Vec2((pb - pa) / length) : Vec2(1, 0);
    l.at = pb + 18.0 * u + Vec2(0.0, -14.0);
    return l;
}

std::string rulerLine(const LabRuler& ruler) {
    const Vec2 d = ruler.b() - ruler.a();
    char angle[32];
    std::snprintf(angle, sizeof angle, "%.1f\u00b0", ruler.slopeDegrees());
    std::string s = quantity(ruler.length(), "m");
    s += ", ";
    s += angle;
    s += " (horizontal ";
    s += quantity(std::abs(d.x()), "m");
    s += ", vertical ";
    s += quantity(std::abs(d.y()), "m");
    s += ")";
    return s;
}

}  // namespace psb::app
