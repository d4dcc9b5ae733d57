#include "view/dropper_mark.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <utility>

#include "view/screen_layout.hpp"
#include "view/word_wrap.hpp"

namespace psb::app {

DropperSpout dropperSpout(const Camera& camera, const DropperView& d) {
    const Vec2 at = camera.worldToScreen(d.at);
    const double ppm = camera.worldToScreen(d.at + Vec2(1.0, 0.0)).x() - at.x();
    const double r = std::max(d.radius * ppm, 2.0);
    DropperSpout s;
    s.x = at.x();
    s.bottom = at.y() - 1.3 * r;
    s.top = s.bottom - std::max(3.5 * r, 10.0);
    s.low = d.spread * ppm + 1.5 * r;
    s.high = s.low + std::max(2.0 * r, 6.0);
    return s;
}

namespace {

/// Pixels between the spout's rim and its words.
constexpr double kWordsGap = 6.0;

bool inside(const PixelRect& outer, const PixelRect& r) {
    return r.x >= outer.x && r.y >= outer.y && r.x + r.w <= outer.x + outer.w &&
           r.y + r.h <= outer.y + outer.h;
}

/// `lines` as a box with its top-left at (x, y) (or its top-right, `fromRight`).
DropperView::Words wordsAt(const std::vector<std::string>& lines, double x, double y,
                           bool fromRight, const TextMeasure& font) {
    int w = 0;
    for (const std::string& l : lines)
        w = std::max(w, font.measure(l));
    const int h = static_cast<int>(lines.size()) * font.lineHeight() + 1;
    const double left = fromRight ? x - w - 1 : x;
    return {{static_cast<int>(std::floor(left)), static_cast<int>(std::floor(y)), w + 1, h}, lines};
}

}  // namespace

DropperView::Words dropperWords(const DropperSpout& s, const std::string& label,
                                const TextMeasure& font, const LabelRoom& labelRoom) {
    const PixelRect &box = labelRoom.box, &window = labelRoom.window;
    const std::vector<PixelRect>& keepOut = labelRoom.keepOut;
    const PixelRect room = box.w > 0 ? box : window;
    const auto clear = [&](const DropperView::Words& words) {
        return inside(room, words.at) && inside(window, words.at) &&
               std::none_of(keepOut.begin(), keepOut.end(),
                            [&](const PixelRect& k) { return overlaps(words.at, k); });
    };
    const auto wrapped = [&](double width) {
        return wrapAtSpaces(
            label, static_cast<float>(std::max(width, 1.0)),
            [&font](std::string_view t) { return static_cast<float>(font.measure(t)); });
    };
    const double middle = 0.5 * (s.top + s.bottom);
    const double rightOf = s.x + s.high + kWordsGap, leftOf = s.x - s.high - kWordsGap;
    // Level with the spout's middle, moved down (never up) to stay below the top wall: two or
    // three lines centred on the spout reached over it.
    const auto level = [&](std::size_t lines) {
        const double h = static_cast<double>(lines) * font.lineHeight();
        return std::max(middle - 0.5 * h, static_cast<double>(room.y) + 1.0);
    };
    // Level with the spout, else as high as the box lets them (clear of the pegs below).
    const auto beside = [&](const std::vector<std::string>& lines, bool right, bool high) {
        const double y = high ? room.y + 2.0 : level(lines.size());
        return right ? wordsAt(lines, rightOf, y, false, font)
                     : wordsAt(lines, leftOf, y, true, font);
    };
    const DropperView::Words oneLine = beside({label}, true, false);
    const double roomRight = room.x + room.w - rightOf - 1.0, roomLeft = leftOf - room.x - 1.0;
    for (const bool high : {false, true}) {
        // In one line, right then left; then wrapped to the room on each side, the roomier
        // first.
        for (const bool right : {true, false}) {
            if (DropperView::Words w = beside({label}, right, high); clear(w)) return w;
        }
        for (const bool right : {roomRight >= roomLeft, roomRight < roomLeft}) {
            DropperView::Words w = beside(wrapped(right ? roomRight : roomLeft), right, high);
            if (clear(w)) return w;
        }
    }
    // Over the box's top wall, centred on the spout and slid into the window: a box too narrow
    // for its words beside the spout.
    if (box.w > 0) {
        for (const double width : {1e9, static_cast<double>(window.w)}) {
            std::vector<std::string> lines = wrapped(width);
            const int h = static_cast<int>(lines.size()) * font.lineHeight() + 1;
            DropperView::Words w = wordsAt(lines, 0.0, 0.0, false, font);
            const int x = std::clamp(static_cast<int>(std::lround(s.x - 0.5 * w.at.w)), window.x,
                                     window.x + window.w - w.at.w);
            w.at.x = x;
            w.at.y = box.y - labelRoom.boxWall - 2 - h;
            if (inside(window, w.at) &&
                std::none_of(keepOut.begin(), keepOut.end(),
                             [&](const PixelRect& k) { return overlaps(w.at, k); })) {
                return w;
            }
        }
    }
    return oneLine;
}

std::string dropperLabel(const Dropper& d) {
    if (d.balls == 0) return "dropper: empty";
    return "dropper: " + std::to_string(d.balls) + (d.balls == 1 ? " ball left" : " balls left");
}

}  // namespace psb::app
