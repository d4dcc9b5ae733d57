#include "view/label_places.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>
#include <utility>

#include "view/screen_layout.hpp"

namespace psb::app {

namespace {

/// overlaps() for rectangles known not to be empty, inline in the loops over discs.
inline bool meet(const PixelRect& a, const PixelRect& b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

bool contains(const PixelRect& outer, const PixelRect& r) {
    return r.x >= outer.x && r.y >= outer.y && r.x + r.w <= outer.x + outer.w &&
           r.y + r.h <= outer.y + outer.h;
}

/// `at` moved so that a length `size` starting there lies within [lo, hi), if it can.
int along(int at, int size, int lo, int hi) {
    return std::max(lo, std::min(at, hi - size));
}

/// Directions the rings try, from straight up round both ways: a label above or below its
/// disc reads most naturally, then beside it, then at the corners.
constexpr int kRingDirections = 32;

/// Whether the segment from a to b meets the rectangle [x0, x1] × [y0, y1] (Liang–Barsky).
bool segmentMeetsRect(double ax, double ay, double bx, double by, double x0, double y0, double x1,
                      double y1) {
    double t0 = 0.0, t1 = 1.0;
    const double dx = bx - ax, dy = by - ay;
    for (const auto& [p, q] :
         {std::pair{-dx, ax - x0}, {dx, x1 - ax}, {-dy, ay - y0}, {dy, y1 - ay}}) {
        if (p == 0.0) {
            if (q < 0.0) return false;
            continue;
        }
        const double t = q / p;
        if (p < 0.0) {
            t0 = std::max(t0, t);
        } else {
            t1 = std::min(t1, t);
        }
        if (t0 > t1) return false;
    }
    return true;
}

/// The squared distance from (px, py) to the segment from a to b.
double squaredDistanceToSegment(double px, double py, double ax, double ay, double bx, double by) {
    const double dx = bx - ax, dy = by - ay;
    const double length2 = dx * dx + dy * dy;
    double t = length2 > 0.0 ? ((px - ax) * dx + (py - ay) * dy) / length2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const double ex = ax + t * dx - px, ey = ay + t * dy - py;
    return ex * ex + ey * ey;
}

/// The squared distance from (px, py) to the rectangle [x0, x1] × [y0, y1].
double squaredDistanceToRect(double px, double py, double x0, double y0, double x1, double y1) {
    const double ex = std::max({x0 - px, 0.0, px - x1}), ey = std::max({y0 - py, 0.0, py - y1});
    return ex * ex + ey * ey;
}

/// The discs, found by the cells of a grid over the window they meet: a label's trial place
/// is checked against the few discs near it, not all of them (the funnel's 400 balls, each
/// label trying dozens of places).
class DiscIndex {
  public:
    DiscIndex(const std::vector<PixelRect>& discs, const PixelRect& window)
        : discs_(discs), window_(window) {
        columns_ = std::max(1, (window.w + kCell - 1) / kCell);
        rows_ = std::max(1, (window.h + kCell - 1) / kCell);
        cells_.resize(static_cast<std::size_t>(columns_ * rows_));
        for (std::size_t i = 0; i < discs.size(); ++i) {
            const Span s = span(discs[i]);
            for (int row = s.r0; row <= s.r1; ++row)
                for (int column = s.c0; column <= s.c1; ++column)
                    cell(row, column).push_back(static_cast<int>(i));
        }
        seen_.assign(discs.size(), 0);
        for (const PixelRect& d : discs)
            largest_ = std::max(largest_, d.w);
    }

    /// Whether `r` overlaps any disc.
    [[nodiscard]] bool any(const PixelRect& r) const {
        const Span s = span(r);
        for (int row = s.r0; row <= s.r1; ++row) {
            for (int column = s.c0; column <= s.c1; ++column) {
                for (const int i : cell(row, column))
                    if (meet(r, discs_[static_cast<std::size_t>(i)])) return true;
            }
        }
        return false;
    }

    /// Whether the line from (ax, ay) to (bx, by) passes over any disc but `own` (the discs
    /// without the gap kept round them).
    [[nodiscard]] bool anyOnLine(double ax, double ay, double bx, double by,
                                 const PixelRect& own) const {
        const auto x0 = static_cast<int>(std::floor(std::min(ax, bx)));
        const auto y0 = static_cast<int>(std::floor(std::min(ay, by)));
        const PixelRect around{x0, y0, static_cast<int>(std::ceil(std::max(ax, bx))) - x0 + 1,
                               static_cast<int>(std::ceil(std::max(ay, by))) - y0 + 1};
        const Span s = span(around);
        for (int row = s.r0; row <= s.r1; ++row) {
            for (int column = s.c0; column <= s.c1; ++column) {
                for (const int i : cell(row, column)) {
                    const PixelRect& d = discs_[static_cast<std::size_t>(i)];
                    if (d.x == own.x && d.y == own.y && d.w == own.w && d.h == own.h) continue;
                    const double g = kLabelGap;
                    if (segmentMeetsRect(ax, ay, bx, by, d.x + g, d.y + g, d.x + d.w - g,
                                         d.y + d.h - g)) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    /// Whether a disc other than `own` (an index into the discs) has its rim as near to
    /// (px, py) as `own`'s, or nearer: the discs as circles in their squares.
    [[nodiscard]] bool otherAsNear(double px, double py, std::size_t own) const {
        const auto rim = [&](const PixelRect& d) {
            const double r = 0.5 * d.w;
            return std::hypot(d.x + r - px, d.y + r - py) - r;
        };
        const double mine = rim(discs_[own]);
        // Any disc as near has its square within `mine` plus the largest square of (px, py).
        const int reach = static_cast<int>(std::ceil(std::max(0.0, mine))) + largest_ + 1;
        const PixelRect around{static_cast<int>(std::floor(px)) - reach,
                               static_cast<int>(std::floor(py)) - reach, 2 * reach + 1,
                               2 * reach + 1};
        const Span s = span(around);
        for (int row = s.r0; row <= s.r1; ++row) {
            for (int column = s.c0; column <= s.c1; ++column) {
                for (const int i : cell(row, column)) {
                    const auto k = static_cast<std::size_t>(i);
                    if (k != own && rim(discs_[k]) <= mine) return true;
                }
            }
        }
        return false;
    }

    /// Whether a disc other than `own` has its rim within `clearance` pixels of `r`.
    [[nodiscard]] bool otherWithin(const PixelRect& r, int clearance, std::size_t own) const {
        const PixelRect around{r.x - clearance, r.y - clearance, r.w + 2 * clearance,
                               r.h + 2 * clearance};
        const Span s = span(around);
        for (int row = s.r0; row <= s.r1; ++row) {
            for (int column = s.c0; column <= s.c1; ++column) {
                for (const int i : cell(row, column)) {
                    const auto k = static_cast<std::size_t>(i);
                    if (k == own) continue;
                    const PixelRect& d = discs_[k];
                    const double half = 0.5 * d.w;
                    const double cx = d.x + half, cy = d.y + half;
                    const double ex = std::max({r.x - cx, 0.0, cx - (r.x + r.w)});
                    const double ey = std::max({r.y - cy, 0.0, cy - (r.y + r.h)});
                    if (std::hypot(ex, ey) - half < clearance) return true;
                }
            }
        }
        return false;
    }

    /// How many discs `r` overlaps.
    [[nodiscard]] std::size_t count(const PixelRect& r) {
        ++stamp_;
        std::size_t n = 0;
        const Span s = span(r);
        for (int row = s.r0; row <= s.r1; ++row) {
            for (int column = s.c0; column <= s.c1; ++column) {
                for (const int i : cell(row, column)) {
                    const auto k = static_cast<std::size_t>(i);
                    if (seen_[k] == stamp_) continue;
                    seen_[k] = stamp_;
                    n += meet(r, discs_[k]);
                }
            }
        }
        return n;
    }

  private:
    static constexpr int kCell = 64;  ///< pixels

    /// The cells `r` meets (none: c0 > c1).
    struct Span {
        int c0 = 1, r0 = 1, c1 = 0, r1 = 0;
    };
    [[nodiscard]] Span span(const PixelRect& r) const {
        if (r.w <= 0 || r.h <= 0 || r.x + r.w <= window_.x || r.y + r.h <= window_.y) return {};
        return {std::max(0, (r.x - window_.x) / kCell), std::max(0, (r.y - window_.y) / kCell),
                std::min(columns_ - 1, (r.x + r.w - 1 - window_.x) / kCell),
                std::min(rows_ - 1, (r.y + r.h - 1 - window_.y) / kCell)};
    }
    [[nodiscard]] std::vector<int>& cell(int row, int column) {
        return cells_[static_cast<std::size_t>(row * columns_ + column)];
    }
    [[nodiscard]] const std::vector<int>& cell(int row, int column) const {
        return cells_[static_cast<std::size_t>(row * columns_ + column)];
    }

    const std::vector<PixelRect>& discs_;
    PixelRect window_;
    int columns_ = 1, rows_ = 1;
    std::vector<std::vector<int>> cells_;
    std::vector<unsigned> seen_;
    unsigned stamp_ = 0;
    int largest_ = 0;  ///< the largest disc's square, pixels
};

/// Whether `r` crosses the walled box's outline (as drawn, its thickness outside the box) or
/// any wall of `room`.
bool crossesWalls(const PixelRect& r, const LabelRoom& room) {
    if (room.box.w > 0) {
        const int t = std::max(0, room.boxWall);
        const PixelRect outline{room.box.x - t, room.box.y - t, room.box.w + 2 * t,
                                room.box.h + 2 * t};
        if (overlaps(r, outline) && !contains(room.box, r)) return true;
        // Inside, a little air from the walls (at 200 % a label touched the left wall).
        const int air = std::max(4, r.h / 8);
        const PixelRect inner{room.box.x + air, room.box.y + air, room.box.w - 2 * air,
                              room.box.h - 2 * air};
        if (contains(room.box, r) && !contains(inner, r)) return true;
    }
    return std::any_of(room.walls.begin(), room.walls.end(),
                       [&r](const ScreenWall& w) { return crosses(r, w); });
}

bool clearOf(const PixelRect& r, const std::vector<PixelRect>& boxes) {
    return std::none_of(boxes.begin(), boxes.end(),
                        [&r](const PixelRect& o) { return overlaps(r, o); });
}

/// placeLabels with the labels taken in `order` (indices into `asks`).
std::vector<LabelPlace> placeInOrder(const std::vector<LabelAsk>& asks,
                                     const std::vector<std::size_t>& order, const LabelRoom& room,
                                     const DiscIndex& discs) {
    std::vector<LabelPlace> out(asks.size());
    std::vector<PixelRect> placed;
    placed.reserve(asks.size());
    const bool rings = asks.size() <= kMaxLeaderLabels;
    const PixelRect& window = room.window;
    // The leader lines drawn so far: a label keeps off them, as off another label.
    std::vector<LeaderLine> leaders;
    const auto onLine = [](const LeaderLine& l, const PixelRect& r) {
        return segmentMeetsRect(l.ax, l.ay, l.bx, l.by, r.x, r.y, r.x + r.w, r.y + r.h);
    };
    const auto free = [&](const PixelRect& r) {
        // Side by side, two labels keep about a line apart (half a two-line label's height, up
        // to 24 pixels), and each is framed (render/renderer.cpp): 20 pixels apart at 200 %
        // they read as one line ("particle 1, 1.00 kg particle 2, 3.00 kg").
        const int apart = std::max(kLabelGap, std::min(r.h / 2, kLabelsApart));
        const PixelRect wide{r.x - apart, r.y, r.w + 2 * apart, r.h};
        return contains(window, r) && clearOf(wide, placed) && clearOf(r, room.keepOut) &&
               !discs.any(r) && !crossesWalls(r, room) &&
               std::none_of(leaders.begin(), leaders.end(),
                            [&](const LeaderLine& l) { return onLine(l, r); });
    };

    for (const std::size_t i : order) {
        const LabelAsk& a = asks[i];
        if (a.size.x <= 0 || a.size.y <= 0) continue;
        PixelRect inside = window;
        const bool inBox = a.inBox && room.box.w > 0;
        if (inBox) {
            const PixelRect& box = room.box;
            const int x0 = std::max(window.x, box.x), y0 = std::max(window.y, box.y);
            const int x1 = std::min(window.x + window.w, box.x + box.w);
            const int y1 = std::min(window.y + window.h, box.y + box.h);
            inside = {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
        }
        LabelPlace& p = out[i];
        const auto take = [&](const PixelRect& r) {
            p.at = r;
            placed.push_back(r);
        };
        // Never over its own ball's arrow (at 200 % a label stood on the arrow it reads).
        const auto clearOfArrow = [&a](const PixelRect& r) {
            return !(a.arrow.halfWidth > 0.0) || !crosses(r, a.arrow);
        };
        // Without a line to its disc, a label is read as the nearest ball's.
        const auto nearestIsOwn = [&](const PixelRect& r) {
            return !discs.otherAsNear(r.x + 0.5 * r.w, r.y + 0.5 * r.h, i);
        };
        // Beside its disc (in the box first), then on rings round it: a label of `size`.
        const auto placeAs = [&](PixelPoint size) {
            const std::vector<PixelRect> beside = placesBeside(a.disc, size, inside);
            for (const bool inRoom : {inBox, false}) {
                for (const PixelRect& r : beside) {
                    if (inRoom && !contains(inside, r)) continue;
                    if (free(r) && clearOfArrow(r) && nearestIsOwn(r)) {
                        take(r);
                        return true;
                    }
                }
            }
            if (!rings) return false;
            // Away from its ball, a label keeps half its height clear of every other ball: one
            // touching another ball read as that one's, its short line to its own unseen (the
            // original's particle 5 at 100 %, under particle 3's rim).
            const int clearance = std::max(2 * kLabelGap, size.y / 2);
            for (const PixelRect& r : placesOnRings(a.disc, size, kLabelRings)) {
                if (!free(r) || !clearOfArrow(r) || discs.otherWithin(r, clearance, i)) continue;
                // Its line to the disc crosses no wall at an angle (the box's own walls it
                // may: a small box's labels stand outside it), no other disc, and nothing the
                // room keeps out (it crossed the grid's "2 m").
                const LeaderLine line = leaderLine(a.disc, r);
                if (std::any_of(room.walls.begin(), room.walls.end(),
                                [&line](const ScreenWall& w) { return leaderCrosses(line, w); }) ||
                    discs.anyOnLine(line.ax, line.ay, line.bx, line.by, a.disc) ||
                    std::any_of(placed.begin(), placed.end(),
                                [&](const PixelRect& other) { return onLine(line, other); }) ||
                    std::any_of(room.keepOut.begin(), room.keepOut.end(),
                                [&](const PixelRect& k) { return onLine(line, k); })) {
                    continue;
                }
                take(r);
                leaders.push_back(line);
                p.leader = true;
                return true;
            }
            return false;
        };
        if (placeAs(a.size)) continue;
        const std::vector<PixelRect> beside = placesBeside(a.disc, a.size, inside);
        p.offWindow = std::none_of(beside.begin(), beside.begin() + 4,
                                   [&window](const PixelRect& r) { return contains(window, r); });
    }
    return out;
}

std::size_t leftOut(const std::vector<LabelPlace>& places) {
    return static_cast<std::size_t>(std::count_if(places.begin(), places.end(),
                                                  [](const LabelPlace& p) { return p.at.w == 0; }));
}

/// placeLabels in the sizes `asks` give: in order, then, in a small scene, a few times with the
/// labels left out first, keeping the placing that leaves fewest out.
std::vector<LabelPlace> placeBest(const std::vector<LabelAsk>& asks, const LabelRoom& room,
                                  const DiscIndex& discs) {
    std::vector<std::size_t> order(asks.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::vector<LabelPlace> best = placeInOrder(asks, order, room, discs);
    // In a small scene a label placed first can take the one place another had: the labels
    // left out go first, a few times, and the best placing is kept.
    for (int attempt = 0; attempt < 4 && asks.size() <= kMaxLeaderLabels && leftOut(best) > 0;
         ++attempt) {
        std::stable_partition(order.begin(), order.end(),
                              [&best](std::size_t i) { return best[i].at.w == 0; });
        std::vector<LabelPlace> again = placeInOrder(asks, order, room, discs);
        if (leftOut(again) < leftOut(best)) best = std::move(again);
    }
    return best;
}

}  // namespace

double boxWallPixels(double width, double height, double zoom) {
    return std::max(2.0, 0.004 * std::min(width, height) * zoom);
}

LeaderLine leaderLine(const PixelRect& d, const PixelRect& box) {
    const double cx = d.x + 0.5 * d.w, cy = d.y + 0.5 * d.h;
    const auto x0 = static_cast<double>(box.x), y0 = static_cast<double>(box.y);
    const double nx = std::clamp(cx, x0, x0 + box.w), ny = std::clamp(cy, y0, y0 + box.h);
    const double length = std::hypot(nx - cx, ny - cy);
    if (!(length > 0.0)) return {cx, cy, nx, ny};
    const double rim = 0.5 * d.w - 2.0;
    return {cx + (nx - cx) / length * rim, cy + (ny - cy) / length * rim, nx, ny};
}

bool leaderCrosses(const LeaderLine& l, const ScreenWall& w) {
    const auto side = [](double ax, double ay, double bx, double by, double px, double py) {
        return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
    };
    // The two lines cross...
    const double d1 = side(w.ax, w.ay, w.bx, w.by, l.ax, l.ay);
    const double d2 = side(w.ax, w.ay, w.bx, w.by, l.bx, l.by);
    const double d3 = side(l.ax, l.ay, l.bx, l.by, w.ax, w.ay);
    const double d4 = side(l.ax, l.ay, l.bx, l.by, w.bx, w.by);
    if (((d1 > 0.0) != (d2 > 0.0)) && ((d3 > 0.0) != (d4 > 0.0))) return true;
    // ...or the label's end, or the line past a wall's rounded end, comes within its
    // half-width (the disc's end does, of the ramp the disc rests on, and leads away from it).
    const double reach = w.halfWidth * w.halfWidth;
    return squaredDistanceToSegment(l.bx, l.by, w.ax, w.ay, w.bx, w.by) < reach ||
           squaredDistanceToSegment(w.ax, w.ay, l.ax, l.ay, l.bx, l.by) < reach ||
           squaredDistanceToSegment(w.bx, w.by, l.ax, l.ay, l.bx, l.by) < reach;
}

bool crosses(const PixelRect& r, const ScreenWall& w) {
    if (r.w <= 0 || r.h <= 0) return false;
    const double x0 = r.x, y0 = r.y, x1 = r.x + r.w, y1 = r.y + r.h;
    if (segmentMeetsRect(w.ax, w.ay, w.bx, w.by, x0, y0, x1, y1)) return true;
    const double reach = w.halfWidth * w.halfWidth;
    if (squaredDistanceToRect(w.ax, w.ay, x0, y0, x1, y1) < reach) return true;
    if (squaredDistanceToRect(w.bx, w.by, x0, y0, x1, y1) < reach) return true;
    for (const auto& [cx, cy] : {std::pair{x0, y0}, {x1, y0}, {x0, y1}, {x1, y1}}) {
        if (squaredDistanceToSegment(cx, cy, w.ax, w.ay, w.bx, w.by) < reach) return true;
    }
    return false;
}

std::vector<PixelRect> placesBeside(const PixelRect& d, PixelPoint size, const PixelRect& within) {
    const int bw = size.x, bh = size.y;
    const int cx = d.x + d.w / 2, cy = d.y + d.h / 2;
    std::vector<PixelRect> beside;
    beside.reserve(24);
    for (const int t : {0, -1, 1, -2, 2}) {
        const int across = along(cx - bw / 2 + t * bw / 4, bw, within.x, within.x + within.w);
        const int down = along(cy - bh / 2 + t * bh / 4, bh, within.y, within.y + within.h);
        beside.push_back({across, d.y - bh, bw, bh});
        beside.push_back({across, d.y + d.h, bw, bh});
        beside.push_back({d.x + d.w, down, bw, bh});
        beside.push_back({d.x - bw, down, bw, bh});
    }
    for (const PixelRect& r :
         {PixelRect{d.x + d.w, d.y - bh, bw, bh}, PixelRect{d.x - bw, d.y - bh, bw, bh},
          PixelRect{d.x + d.w, d.y + d.h, bw, bh}, PixelRect{d.x - bw, d.y + d.h, bw, bh}}) {
        beside.push_back(r);
    }
    return beside;
}

std::vector<PixelRect> placesOnRings(const PixelRect& d, PixelPoint size, int rings) {
    const int bw = size.x, bh = size.y;
    const int cx = d.x + d.w / 2, cy = d.y + d.h / 2;
    const double gap = std::max(4.0, bh / 6.0);
    const double reach = 0.5 * d.w + 0.5 * std::hypot(bw, bh);
    std::vector<PixelRect> out;
    out.reserve(static_cast<std::size_t>(std::max(0, rings)) * kRingDirections);
    for (int k = 1; k <= rings; ++k) {
        const double distance = reach + k * gap;
        for (int j = 0; j < kRingDirections; ++j) {
            // 0, +1, -1, +2, -2, ... steps from straight up.
            const int step = (j + 1) / 2 * (j % 2 == 1 ? 1 : -1);
            const double angle =
                -std::numbers::pi / 2.0 + step * (2.0 * std::numbers::pi / kRingDirections);
            out.push_back({static_cast<int>(std::lround(cx + distance * std::cos(angle))) - bw / 2,
                           static_cast<int>(std::lround(cy + distance * std::sin(angle))) - bh / 2,
                           bw, bh});
        }
    }
    return out;
}

std::vector<LabelPlace> placeLabels(const std::vector<LabelAsk>& asks, const LabelRoom& room) {
    std::vector<PixelRect> discRects(asks.size());
    for (std::size_t i = 0; i < asks.size(); ++i)
        discRects[i] = asks[i].disc;
    const DiscIndex discs(discRects, room.window);
    std::vector<LabelPlace> best = placeBest(asks, room, discs);
    const bool names =
        !asks.empty() && std::all_of(asks.begin(), asks.end(), [](const LabelAsk& a) {
            return a.nameSize.x > 0 && a.nameSize.y > 0;
        });
    if (leftOut(best) == 0 || !names) return best;
    // Some label found no place for its values: every label its name alone, where that leaves
    // fewer out (between two of the ramp's ramps at 200 % only a name fits). One form for all.
    std::vector<LabelAsk> named = asks;
    for (LabelAsk& a : named)
        a.size = a.nameSize;
    std::vector<LabelPlace> brief = placeBest(named, room, discs);
    if (leftOut(brief) >= leftOut(best)) return best;
    for (LabelPlace& p : brief)
        p.nameOnly = true;
    return brief;
}

ReadingPlace firstClearPlace(const std::vector<std::vector<PixelRect>>& places,
                             const std::vector<PixelRect>& discRects, const LabelRoom& room,
                             const std::vector<PixelRect>& marks) {
    DiscIndex discs(discRects, room.window);
    const auto allowed = [&room](const PixelRect& r) {
        return contains(room.window, r) && clearOf(r, room.keepOut);
    };
    const auto marksUnder = [&marks](const PixelRect& r) {
        return static_cast<std::size_t>(std::count_if(
            marks.begin(), marks.end(), [&r](const PixelRect& m) { return overlaps(r, m); }));
    };
    // A clear place: any disc rules one out, quickly found in a crowd. Then one clear of the
    // discs and the walls over a mark, which gives way to it (a grid label left out).
    for (const bool overMarks : {false, true}) {
        for (std::size_t form = 0; form < places.size(); ++form) {
            for (const PixelRect& r : places[form]) {
                if (!allowed(r) || discs.any(r) || crossesWalls(r, room)) continue;
                const std::size_t under = marksUnder(r);
                if (under == 0 || overMarks) return {r, form, 0, false, under};
            }
        }
    }
    // None: the least covered of each form's first few allowed (counting costs in a gas).
    ReadingPlace best;
    const auto key = [](const ReadingPlace& p) {
        return std::tuple{p.discs, p.acrossWall, p.marks};
    };
    for (std::size_t form = 0; form < places.size(); ++form) {
        std::size_t tried = 0;
        for (const PixelRect& r : places[form]) {
            if (!allowed(r)) continue;
            const ReadingPlace here{r, form, discs.count(r), crossesWalls(r, room), marksUnder(r)};
            if (best.at.w == 0 || key(here) < key(best)) best = here;
            if (++tried == kReadingFallbacks) break;
        }
    }
    return best;
}

LabelRoom labelRoom(const World& world, const Camera& camera, const PixelRect& window,
                    std::vector<PixelRect> keepOut) {
    LabelRoom room;
    room.window = window;
    if (world.def().walls) {
        // The box's outline on screen: a label is inside it or outside, never across a wall.
        const Camera::ScreenBox sb = camera.boxOnScreen(world.def().width, world.def().height);
        room.box = {static_cast<int>(std::floor(sb.topLeft.x())),
                    static_cast<int>(std::floor(sb.topLeft.y())),
                    static_cast<int>(std::ceil(sb.size.x())) + 1,
                    static_cast<int>(std::ceil(sb.size.y())) + 1};
        // As drawn, and a pixel of air: a label touching the top wall read as crossing it.
        room.boxWall = static_cast<int>(std::ceil(
                           boxWallPixels(world.def().width, world.def().height, camera.zoom()))) +
                       1;
    }
    room.keepOut = std::move(keepOut);
    // The scene's walls at any angle are walls too (the funnel's sides).
    for (const Obstacle& o : world.obstacles()) {
        if (o.isPeg()) continue;
        const Vec2 a = camera.worldToScreen(o.a), b = camera.worldToScreen(o.b);
        room.walls.push_back({a.x(), a.y(), b.x(), b.y(), camera.toScreen(o.radius) + 1.0});
    }
    return room;
}

std::vector<PixelRect> pegsOnScreen(const World& world, const Camera& camera) {
    std::vector<PixelRect> out;
    for (const Obstacle& o : world.obstacles()) {
        if (!o.isPeg()) continue;
        const Vec2 c = camera.worldToScreen(o.a);
        const double r = camera.toScreen(o.radius) + 1.0;
        const int side = static_cast<int>(std::ceil(2.0 * r)) + 1;
        out.push_back({static_cast<int>(std::floor(c.x() - r)),
                       static_cast<int>(std::floor(c.y() - r)), side, side});
    }
    return out;
}

std::vector<PixelRect> discsOnScreen(const World& world, const Camera& camera,
                                     const PixelRect& window) {
    std::vector<PixelRect> out;
    const ParticleArrays& p = world.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec2 c = camera.worldToScreen(Vec2(p.x[i], p.y[i]));
        const int cx = static_cast<int>(std::lround(c.x()));
        const int cy = static_cast<int>(std::lround(c.y()));
        const int r = static_cast<int>(std::ceil(camera.toScreen(p.radius[i]))) + kLabelGap;
        const PixelRect d{cx - r, cy - r, 2 * r, 2 * r};
        if (overlaps(d, window)) out.push_back(d);
    }
    return out;
}

}  // namespace psb::app
