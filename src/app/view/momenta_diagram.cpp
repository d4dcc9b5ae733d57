#include "view/momenta_diagram.hpp"

#include <algorithm>
#include <cmath>

#include "session/units.hpp"
#include "view/label_places.hpp"
#include "view/screen_layout.hpp"

namespace psb::app {

namespace {

/// The arrows of one moment: each particle's momentum tip to tail, then the total.
std::vector<MomentaDiagram::Arrow> tipToTail(const CollisionCard& card, const Vec2& pA,
                                             const Vec2& pB) {
    using Kind = MomentaDiagram::Kind;
    std::vector<MomentaDiagram::Arrow> arrows;
    arrows.push_back({Vec2::Zero(), pA, Kind::First, "p " + std::to_string(card.numberA)});
    Vec2 tip = pA;
    if (card.pair()) {
        arrows.push_back({pA, pA + pB, Kind::Second, "p " + std::to_string(card.numberB)});
        tip = pA + pB;
    }
    arrows.push_back({Vec2::Zero(), tip, Kind::Total, "total p"});
    return arrows;
}

std::string line(const char* when, const std::vector<MomentaDiagram::Arrow>& arrows,
                 const Axes& axes) {
    std::string s = "Momenta ";
    s += when;
    s += ": ";
    for (std::size_t i = 0; i < arrows.size(); ++i) {
        const MomentaDiagram::Arrow& a = arrows[i];
        if (a.kind == MomentaDiagram::Kind::Total) {
            s += " = ";
            s += a.label;
            s += ' ';
            s += components(axes.vector(a.to));
        } else {
            if (i > 0) s += " + ";
            s += a.label;
            s += ' ';
            s += components(axes.vector(a.to - a.from));
        }
    }
    s += " kg m/s";
    return s;
}

/// The smallest round number (1, 1.5, 2, 2.5, 3, 4, 5, 6, 8 times a power of ten) at least
/// `x` > 0: a scale a student reads at a glance and that quantity() writes exactly.
double roundUp(double x) {
    static constexpr double kSteps[] = {1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0};
    const double decade = std::pow(10.0, std::floor(std::log10(x)));
    for (const double step : kSteps) {
        // The tolerance keeps 2.5 at 2.5 where log10 and pow round against it.
        if (step * decade >= x * (1.0 - 1e-12)) return step * decade;
    }
    return 10.0 * decade;
}

}  // namespace

Vec2 MomentaDiagram::toPixels(const Vec2& p, double side) const {
    const double half = 0.5 * side;
    return Vec2(half, half) + (half / reach) * p;
}

MomentaDiagram momentaDiagram(const CollisionCard& card) {
    const Collision& c = card.collision;
    MomentaDiagram d;
    d.before = tipToTail(card, card.massA * c.aBefore, card.massB * c.bBefore);
    d.after = tipToTail(card, card.massA * c.aAfter, card.massB * c.bAfter);
    double reach = 0.0;
    for (const auto* half : {&d.before, &d.after}) {
        for (const MomentaDiagram::Arrow& a : *half) {
            reach = std::max({reach, a.from.cwiseAbs().maxCoeff(), a.to.cwiseAbs().maxCoeff()});
        }
    }
    // Resting particles still get a scale; a non-finite momentum (never from a valid world)
    // would give a diagram of nothing rather than of NaN pixels. A tip at `reach` lies
    // 1 - 2 kMargin of the half-width out.
    d.reach = std::isfinite(reach) && reach > 0.0
                  ? roundUp(reach / (1.0 - 2.0 * MomentaDiagram::kMargin))
                  : 1.0;
    // Every momentum along x (or every one along y): a row each, across that axis.
    bool alongX = true, alongY = true;
    for (const auto* half : {&d.before, &d.after}) {
        for (const MomentaDiagram::Arrow& a : *half) {
            alongX = alongX && std::abs(a.to.y()) <= 1e-9 * d.reach;
            alongY = alongY && std::abs(a.to.x()) <= 1e-9 * d.reach;
        }
    }
    if (alongX != alongY) {
        constexpr double kRow = 0.16;  // sides of the square between rows
        for (auto* half : {&d.before, &d.after}) {
            // Centred on the axis, but never on it: an arrow along the axis's line was lost in
            // it (the lesson's "p 2" before, three rows with the middle one on the axis), so
            // an odd number of rows is moved half a row down.
            const double rows = static_cast<double>(half->size());
            const double first =
                -0.5 * kRow * (rows - 1.0) + (half->size() % 2 == 1 ? 0.5 * kRow : 0.0);
            for (std::size_t k = 0; k < half->size(); ++k) {
                const double row = first + kRow * static_cast<double>(k);
                (*half)[k].offset = alongX ? Vec2(0.0, row) : Vec2(row, 0.0);
            }
        }
    }
    return d;
}

std::vector<Vec2> momentaLabelPlaces(const MomentaDiagram& d,
                                     const std::vector<MomentaDiagram::Arrow>& arrows, double side,
                                     const std::vector<Vec2>& sizes, double arrowHalfWidth) {
    const double half = 0.5 * side;
    // What a label keeps clear of: the axes through the centre and every arrow.
    std::vector<ScreenWall> lines = {{0.0, half, side, half, 1.0}, {half, 0.0, half, side, 1.0}};
    for (const MomentaDiagram::Arrow& a : arrows) {
        const Vec2 from = d.fromPixels(a, side), to = d.toPixels(a, side);
        lines.push_back({from.x(), from.y(), to.x(), to.y(), arrowHalfWidth});
    }
    const auto box = [](const Vec2& centre, const Vec2& size) {
        return PixelRect{static_cast<int>(std::floor(centre.x() - 0.5 * size.x())),
                         static_cast<int>(std::floor(centre.y() - 0.5 * size.y())),
                         static_cast<int>(std::ceil(size.x())) + 1,
                         static_cast<int>(std::ceil(size.y())) + 1};
    };
    const int edge = static_cast<int>(std::floor(side)) - 1;
    std::vector<PixelRect> placed;
    // Lines crossed and labels covered; far more for a box out of the square.
    const auto cost = [&](const PixelRect& r) {
        if (r.x < 1 || r.y < 1 || r.x + r.w > edge || r.y + r.h > edge) return 1000;
        int n = 0;
        for (const ScreenWall& l : lines)
            n += crosses(r, l);
        for (const PixelRect& p : placed)
            n += overlaps(r, p);
        return n;
    };
    std::vector<Vec2> out;
    for (std::size_t k = 0; k < arrows.size(); ++k) {
        const Vec2 size = k < sizes.size() ? sizes[k] : Vec2::Zero();
        const Vec2 from = d.fromPixels(arrows[k], side), to = d.toPixels(arrows[k], side);
        const Vec2 along = to - from;
        const double length = along.norm();
        const Vec2 u = length > 0.5 ? Vec2(along / length) : Vec2(1.0, 0.0);
        const Vec2 n(-u.y(), u.x());
        // Above the arrow (left of an upright one) first: in a head-on collision's rows each
        // label then sits in the gap above its own arrow.
        const Vec2 up = n.y() < 0.0 || (n.y() == 0.0 && n.x() < 0.0) ? n : Vec2(-n);
        const double clear =
            std::abs(up.y()) * 0.5 * size.y() + std::abs(up.x()) * 0.5 * size.x() + arrowHalfWidth;
        std::vector<Vec2> tries;
        for (const double t : {0.5, 0.35, 0.65, 0.2, 0.8}) {
            for (const double sign : {1.0, -1.0}) {
                for (const double further : {0.0, 0.5, 1.0}) {
                    tries.push_back(from + t * along +
                                    sign * (clear + 2.0 + further * size.y()) * up);
                }
            }
        }
        // Then every place in the square, nearest the arrow's middle first.
        const Vec2 middle = from + 0.5 * along;
        std::vector<Vec2> grid;
        for (double y = 0.5 * size.y() + 2.0; y <= side - 0.5 * size.y() - 2.0; y += 3.0) {
            for (double x = 0.5 * size.x() + 2.0; x <= side - 0.5 * size.x() - 2.0; x += 3.0)
                grid.emplace_back(x, y);
        }
        std::stable_sort(grid.begin(), grid.end(), [&middle](const Vec2& a, const Vec2& b) {
            return (a - middle).squaredNorm() < (b - middle).squaredNorm();
        });
        tries.insert(tries.end(), grid.begin(), grid.end());
        PixelRect best = box(tries.front(), size);
        int bestCost = cost(best);
        for (const Vec2& c : tries) {
            if (bestCost == 0) break;
            const PixelRect r = box(c, size);
            if (const int here = cost(r); here < bestCost) {
                best = r;
                bestCost = here;
            }
        }
        placed.push_back(best);
        out.emplace_back(best.x + 0.5 * (best.w - size.x()), best.y + 0.5 * (best.h - size.y()));
    }
    return out;
}

std::string momentaDiagramScale(const MomentaDiagram& diagram) {
    // The arrows point as the particles move on screen, whichever way the numbers count y.
    return "The square reaches " + quantity(diagram.reach, "kg m/s", false) +
           " from its centre; each arrow points the way its particle moves in the box";
}

std::vector<std::string> momentaDiagramLines(const MomentaDiagram& diagram, const Axes& axes) {
    return {line("before", diagram.before, axes), line("after", diagram.after, axes)};
}

std::array<Color, 3> momentaColours(Theme theme) {
    const Rgba text = palette(theme).text;
    const Color total{text.r, text.g, text.b};
    if (theme == Theme::Light) return {Color{213, 94, 0}, Color{0, 114, 178}, total};
    return {Color{230, 159, 0}, Color{86, 180, 233}, total};
}

}  // namespace psb::app
