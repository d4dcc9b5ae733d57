#include "view/label_places.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>
#include <utility>

#include "view/screen_layout.hpp"

namespace psb::app {

namespace {

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
/// Rings tried, each a gap further out than the last.
constexpr int kRings = 48;

}  // namespace

namespace {

/// placeLabels with the labels taken in `order` (indices into `asks`).
std::vector<LabelPlace> placeInOrder(const std::vector<LabelAsk>& asks,
                                     const std::vector<std::size_t>& order, const PixelRect& window,
                                     const PixelRect& walls,
                                     const std::vector<PixelRect>& keepOut) {
    std::vector<LabelPlace> out(asks.size());
    std::vector<PixelRect> placed;
    placed.reserve(asks.size());
    const bool rings = asks.size() <= kMaxLeaderLabels;
    const auto crossesWalls = [&walls](const PixelRect& r) {
        return walls.w > 0 && overlaps(r, walls) && !contains(walls, r);
    };
    const auto onDiscs = [&asks](const PixelRect& r) {
        return std::any_of(asks.begin(), asks.end(),
                           [&r](const LabelAsk& a) { return overlaps(r, a.disc); });
    };
    const auto clearOfOthers = [&](const PixelRect& r) {
        if (!contains(window, r)) return false;
        for (const PixelRect& o : placed)
            if (overlaps(r, o)) return false;
        for (const PixelRect& o : keepOut)
            if (overlaps(r, o)) return false;
        return true;
    };

    for (const std::size_t i : order) {
        const LabelAsk& a = asks[i];
        const PixelRect& d = a.disc;
        const int bw = a.size.x, bh = a.size.y;
        if (bw <= 0 || bh <= 0) continue;
        PixelRect room = window;
        const bool inBox = a.inBox && walls.w > 0;
        if (inBox) {
            const int x0 = std::max(window.x, walls.x), y0 = std::max(window.y, walls.y);
            const int x1 = std::min(window.x + window.w, walls.x + walls.w);
            const int y1 = std::min(window.y + window.h, walls.y + walls.h);
            room = {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
        }
        const int cx = d.x + d.w / 2, cy = d.y + d.h / 2;
        // Above, below, right and left, centred on the disc and then slid a quarter of the
        // label at a time along that side (a neighbour's label may leave room only at one end),
        // each kept in the room; then the corners.
        std::vector<PixelRect> beside;
        beside.reserve(24);
        for (const int t : {0, -1, 1, -2, 2}) {
            const int across = along(cx - bw / 2 + t * bw / 4, bw, room.x, room.x + room.w);
            const int down = along(cy - bh / 2 + t * bh / 4, bh, room.y, room.y + room.h);
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
        LabelPlace& p = out[i];
        const auto take = [&](const PixelRect& r) {
            p.at = r;
            p.acrossWall = crossesWalls(r);
            placed.push_back(r);
        };
        const auto firstBeside = [&](bool inRoom, bool overDiscs, bool acrossWalls) {
            for (const PixelRect& r : beside) {
                if (inRoom && !contains(room, r)) continue;
                if (!acrossWalls && crossesWalls(r)) continue;
                if (!overDiscs && onDiscs(r)) continue;
                if (clearOfOthers(r)) {
                    take(r);
                    return true;
                }
            }
            return false;
        };
        // Rings round the disc, each a gap further out: the label's centre on a circle through
        // which it clears the disc by that gap in every direction.
        const auto firstOnRings = [&](bool acrossWalls) {
            if (!rings) return false;
            const double gap = std::max(4.0, bh / 6.0);
            const double reach = 0.5 * d.w + 0.5 * std::hypot(bw, bh);
            for (int k = 1; k <= kRings; ++k) {
                const double distance = reach + k * gap;
                for (int j = 0; j < kRingDirections; ++j) {
                    // 0, +1, -1, +2, -2, ... steps from straight up.
                    const int step = (j + 1) / 2 * (j % 2 == 1 ? 1 : -1);
                    const double angle =
                        -std::numbers::pi / 2.0 + step * (2.0 * std::numbers::pi / kRingDirections);
                    const PixelRect r{
                        static_cast<int>(std::lround(cx + distance * std::cos(angle))) - bw / 2,
                        static_cast<int>(std::lround(cy + distance * std::sin(angle))) - bh / 2, bw,
                        bh};
                    if ((!acrossWalls && crossesWalls(r)) || onDiscs(r) || !clearOfOthers(r))
                        continue;
                    take(r);
                    p.leader = true;
                    return true;
                }
            }
            return false;
        };
        // Over a wall rather than over a ball: a box too small for a label anywhere inside
        // (the lesson's 4 m box at 200 %) still shows every ball.
        if (firstBeside(inBox, false, false) || firstBeside(false, false, false) ||
            firstOnRings(false) || firstBeside(false, false, true) || firstOnRings(true)) {
            continue;
        }
        if (firstBeside(false, true, true)) {
            p.overDiscs = onDiscs(p.at);
            continue;
        }
        p.offWindow = std::none_of(beside.begin(), beside.begin() + 4,
                                   [&window](const PixelRect& r) { return contains(window, r); });
    }
    return out;
}

/// How bad a placing is: labels left out, then labels over discs, then across a wall.
std::tuple<std::size_t, std::size_t, std::size_t> cost(const std::vector<LabelPlace>& places) {
    std::size_t out = 0, over = 0, across = 0;
    for (const LabelPlace& p : places) {
        out += p.at.w == 0;
        over += p.overDiscs;
        across += p.acrossWall;
    }
    return {out, over, across};
}

bool isClean(const std::vector<LabelPlace>& places) {
    return cost(places) == std::tuple<std::size_t, std::size_t, std::size_t>{0, 0, 0};
}

/// placeLabels in the sizes `asks` give: in order, then, in a small scene, a few times with the
/// labels that fared worst first, keeping the best placing.
std::vector<LabelPlace> placeBest(const std::vector<LabelAsk>& asks, const PixelRect& window,
                                  const PixelRect& walls, const std::vector<PixelRect>& keepOut) {
    std::vector<std::size_t> order(asks.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::vector<LabelPlace> best = placeInOrder(asks, order, window, walls, keepOut);
    // In a small scene a label placed first can take the one place another had: the labels
    // that fared worst go first, a few times, and the best placing is kept.
    for (int attempt = 0; attempt < 4 && asks.size() <= kMaxLeaderLabels && !isClean(best);
         ++attempt) {
        std::stable_partition(order.begin(), order.end(), [&best](std::size_t i) {
            return best[i].at.w == 0 || best[i].overDiscs || best[i].acrossWall;
        });
        std::vector<LabelPlace> again = placeInOrder(asks, order, window, walls, keepOut);
        if (cost(again) < cost(best)) best = std::move(again);
    }
    return best;
}

}  // namespace

std::vector<LabelPlace> placeLabels(const std::vector<LabelAsk>& asks, const PixelRect& window,
                                    const PixelRect& walls, const std::vector<PixelRect>& keepOut) {
    std::vector<LabelPlace> best = placeBest(asks, window, walls, keepOut);
    const bool shortForms =
        !asks.empty() && std::all_of(asks.begin(), asks.end(), [](const LabelAsk& a) {
            return a.shortSize.x > 0 && a.shortSize.y > 0;
        });
    if (isClean(best) || !shortForms) return best;
    std::vector<LabelAsk> shorter = asks;
    for (LabelAsk& a : shorter)
        a.size = a.shortSize;
    std::vector<LabelPlace> brief = placeBest(shorter, window, walls, keepOut);
    if (!(cost(brief) < cost(best))) return best;
    for (LabelPlace& p : brief)
        p.shortForm = true;
    return brief;
}

}  // namespace psb::app
