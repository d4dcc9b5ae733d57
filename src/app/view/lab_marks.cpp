#include "view/lab_marks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>
#include <utility>

#include "session/units.hpp"
#include "view/screen_layout.hpp"

namespace psb::app {

namespace {

/// How far the reading's centre is from the ruler's middle, pixels.
constexpr double kReadingOffset = 22.0;
/// The reading's places are tried beside the ruler's middle and this many steps further out,
/// kReadingStep pixels each; then kReadingFarStep pixels a step, out to the window's far side
/// (on the ramp at 200 % the room near the ruler was all balls, ramps and grid labels, and the
/// reading took the place over ball 3 that covered fewest; above the box was clear).
constexpr int kReadingSteps = 24;
constexpr int kReadingStep = 8;
constexpr int kReadingFarStep = 24;

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

GridView gridView(const Camera& camera, double width, double height, bool yUp, double minPixels,
                  double labelPixels) {
    GridView g;
    if (!(camera.zoom() > 0.0) || !(width > 0.0) || !(height > 0.0)) return g;
    g.step = roundStep(camera.toWorld(std::max(kGridMinPixels, minPixels)));
    if (!(g.step > 0.0)) return g;
    // A box that holds no line that far apart, each way: the next finer round step (5, 2, 1,
    // 0.5...) while its lines stay kGridLeastPixels apart; a small box kept no label at all.
    for (double finer = roundStep(g.step / 2.5);
         g.step >= std::min(width, height) && camera.toScreen(finer) >= kGridLeastPixels;
         finer = roundStep(finer / 2.5)) {
        g.step = finer;
    }
    // The box's visible part, in metres.
    const Vec2 lo = camera.screenToWorld(Vec2(0.0, 0.0));
    const Vec2 hi = camera.screenToWorld(Vec2(camera.viewportWidth(), camera.viewportHeight()));
    const double x0 = std::max(0.0, lo.x()), x1 = std::min(width, hi.x());
    const double y0 = std::max(0.0, lo.y()), y1 = std::min(height, hi.y());
    if (!(x1 > x0) || !(y1 > y0)) return g;
    const Vec2 top0 = camera.worldToScreen(Vec2(x0, y0)),
               bottom1 = camera.worldToScreen(Vec2(x1, y1));
    const int every = strongEvery(g.step);
    // Labels just inside the box's top and left edges, or the window's when those are off it:
    // a line's height clear of the top wall.
    const double labelY = top0.y() + 4.0 + 0.5 * labelPixels, labelX = top0.x() + 4.0;
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
    v.line = rulerLine(ruler);
    for (int k = 0; k < 3; ++k)
        v.forms[static_cast<std::size_t>(k)] = rulerLines(ruler, k + 1);
    v.label.text = v.line;
    // Beside the middle, on the side of the ticks' normal turned to point down the screen.
    const Vec2 side = n.y() >= 0.0 ? n : Vec2(-n);
    v.label.at = 0.5 * (v.a + v.b) + side * kReadingOffset;
    return v;
}

PixelRect labelRect(const MarkLabel& label, const TextMeasure& font, int pad) {
    int w = 0, lines = 0;
    for (std::size_t from = 0; from <= label.text.size(); ++lines) {
        const std::size_t end = std::min(label.text.find('\n', from), label.text.size());
        w = std::max(w, font.measure(std::string_view(label.text).substr(from, end - from)));
        from = end + 1;
    }
    const int h = lines * font.lineHeight();
    // As the drawing layer places the text: whole pixels, centred or from the left.
    const int x = static_cast<int>(std::lround(label.at.x() - (label.left ? 0.0 : 0.5 * w)));
    const int y = static_cast<int>(std::lround(label.at.y() - 0.5 * h));
    return {x - pad, y - pad / 2, w + 2 * pad, h + pad};
}

std::vector<PixelRect> gridLabelPlates(const GridView& grid, const TextMeasure& font) {
    std::vector<PixelRect> out;
    out.reserve(grid.labels.size());
    for (const MarkLabel& l : grid.labels)
        out.push_back(labelRect(l, font, kGridLabelPad));
    return out;
}

ScreenWall rulerBand(const RulerView& ruler) {
    const Vec2 d = ruler.b - ruler.a;
    const double length = d.norm();
    const Vec2 n =
        length > 0.0 && std::isfinite(length) ? Vec2(Vec2(-d.y(), d.x()) / length) : Vec2(0.0, 1.0);
    // The ticks' side, as rulerView turned it.
    const Vec2 face = (ruler.label.at - 0.5 * (ruler.a + ruler.b)).dot(n) >= 0.0 ? n : Vec2(-n);
    // The face is 14 pixels (as drawn), the handles 5 either side of the edge.
    const Vec2 a = ruler.a + 7.0 * face, b = ruler.b + 7.0 * face;
    return {a.x(), a.y(), b.x(), b.y(), 9.0};
}

namespace {

/// The reading's places round the ruler's middle: beside it, below first (the ticks' side, down
/// the screen), then above, right and left, each slid along its side; then the same a step
/// further out, kReadingSteps times, then in larger steps until the window is behind them.
std::vector<PixelRect> readingPlaces(const Vec2& middle, PixelPoint size, const PixelRect& room) {
    std::vector<PixelRect> places;
    const int near = static_cast<int>(kReadingOffset) - 4 + kReadingSteps * kReadingStep;
    // Far enough that every side's place is outside the window.
    const int reach = static_cast<int>(std::ceil(
        std::max({std::abs(middle.x() - room.x), std::abs(room.x + room.w - middle.x()),
                  std::abs(middle.y() - room.y), std::abs(room.y + room.h - middle.y())})));
    for (int k = 0;; ++k) {
        const int half = k <= kReadingSteps
                             ? static_cast<int>(kReadingOffset) - 4 + k * kReadingStep
                             : near + (k - kReadingSteps) * kReadingFarStep;
        if (k > kReadingSteps && half > reach) break;
        const PixelRect around{static_cast<int>(std::lround(middle.x())) - half,
                               static_cast<int>(std::lround(middle.y())) - half, 2 * half,
                               2 * half};
        std::vector<PixelRect> beside = placesBeside(around, size, room);
        for (std::size_t j = 0; j + 1 < beside.size() && j < 20; j += 4)
            std::swap(beside[j], beside[j + 1]);  // below before above
        places.insert(places.end(), beside.begin(), beside.end());
    }
    return places;
}

}  // namespace

void keepMarkLabelsClear(GridView* grid, RulerView* ruler, const TextMeasure& font,
                         const LabelRoom& room, const std::vector<PixelRect>& discs) {
    const PixelRect& window = room.window;
    const auto inside = [&window](const PixelRect& r) {
        return r.x >= window.x && r.y >= window.y && r.x + r.w <= window.x + window.w &&
               r.y + r.h <= window.y + window.h;
    };
    const auto clear = [&room](const PixelRect& r) {
        return std::none_of(room.keepOut.begin(), room.keepOut.end(),
                            [&r](const PixelRect& k) { return overlaps(r, k); });
    };
    PixelRect reading{};
    if (ruler != nullptr) {
        MarkLabel& l = ruler->label;
        const Vec2 middle = 0.5 * (ruler->a + ruler->b);
        LabelRoom around = room;
        around.walls.push_back(rulerBand(*ruler));
        // In one line where it reads clear, else in two, else three; else the one that covers
        // least.
        std::vector<std::vector<PixelRect>> places;
        for (const std::string& form : ruler->forms) {
            MarkLabel sized = l;
            sized.text = form;
            const PixelRect r = labelRect(sized, font, kReadingPad);
            places.push_back(readingPlaces(middle, {r.w, r.h}, window));
        }
        // The grid's distances that are read (inside the window, clear of the panels): one is
        // left out only where no place is clear of them; a ball is never covered where a place
        // is clear of the balls (firstClearPlace).
        std::vector<PixelRect> marks;
        if (grid != nullptr) {
            for (const MarkLabel& g : grid->labels) {
                const PixelRect r = labelRect(g, font, kGridLabelPad);
                if (inside(r) && clear(r)) marks.push_back(r);
            }
        }
        const ReadingPlace chosen = firstClearPlace(places, discs, around, marks);
        if (chosen.at.w > 0) {
            l.text = ruler->forms[chosen.form];
            l.at = Vec2(chosen.at.x + 0.5 * chosen.at.w, chosen.at.y + 0.5 * chosen.at.h);
        } else {
            // No place clear of the panels at all (a room narrower than the reading): below the
            // middle in three lines, slid into the room as far as it goes.
            l.text = ruler->forms[2];
            const PixelRect r = labelRect(l, font, kReadingPad);
            double dx = 0.0, dy = 0.0;
            if (r.x < window.x) dx = window.x - r.x;
            if (r.x + r.w + dx > window.x + window.w) dx = window.x + window.w - (r.x + r.w);
            if (r.y < window.y) dy = window.y - r.y;
            if (r.y + r.h + dy > window.y + window.h) dy = window.y + window.h - (r.y + r.h);
            l.at += Vec2(dx, dy);
        }
        l.at = Vec2(std::round(l.at.x()), std::round(l.at.y()));
        reading = labelRect(l, font, kReadingPad);
    }
    if (grid != nullptr) {
        std::vector<MarkLabel>& labels = grid->labels;
        labels.erase(std::remove_if(labels.begin(), labels.end(),
                                    [&](const MarkLabel& g) {
                                        // Its plate whole, clear of the rest.
                                        const PixelRect r = labelRect(g, font, kGridLabelPad);
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

std::string rulerLines(const LabRuler& ruler, int count) {
    if (count <= 1) return rulerLine(ruler);
    const Vec2 d = ruler.b() - ruler.a();
    char angle[32];
    std::snprintf(angle, sizeof angle, "%.1f\u00b0", ruler.slopeDegrees());
    return quantity(ruler.length(), "m") + ", " + angle + "\nhorizontal " +
           quantity(std::abs(d.x()), "m") + (count == 2 ? ", vertical " : "\nvertical ") +
           quantity(std::abs(d.y()), "m");
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
