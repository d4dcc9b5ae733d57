#include "view/screen_layout.hpp"

#include <algorithm>

namespace psb::app {

bool overlaps(const PixelRect& a, const PixelRect& b) {
    if (a.w <= 0 || a.h <= 0 || b.w <= 0 || b.h <= 0) return false;
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

PanelLayout layoutPanels(const LayoutRequest& r) {
    PanelLayout l;
    const int m = kPanelMargin, gap = kPanelGap;
    const int right = r.width - m;
    const int left = r.left + m;  // the leftmost a right-aligned panel may start
    const int room = r.width - r.left - 2 * m;
    if (r.hud.x > 0 && r.hud.y > 0) l.hud = {r.left + 4, 4, r.hud.x, r.hud.y};
    const int hudRight = l.hud.w > 0 ? l.hud.x + l.hud.w : 0;
    const int hudBottom = l.hud.w > 0 ? l.hud.y + l.hud.h : 0;

    // A box right-aligned in the column, below `top` and below the HUD where they would share
    // columns of pixels.
    const auto place = [&](PixelPoint size, int top) {
        const int x = std::max(left, right - size.x);
        const int y = x < hudRight + gap ? std::max(top, hudBottom + gap) : top;
        return PixelRect{x, y, size.x, size.y};
    };
    int bottom = r.height - m;
    const auto placeMessages = [&] {
        if (r.messages.x <= 0 || r.messages.y <= 0 || bottom - r.messages.y <= hudBottom) return;
        const PixelRect box{r.left + 4, bottom - r.messages.y, r.messages.x, r.messages.y};
        if (!overlaps(box, l.inspector)) l.messages = box;
    };
    if (!r.inspectorFirst) placeMessages();

    // The inspector is what the user just asked for by clicking: it goes first, at the bottom.
    if (r.inspector.x > 0 && r.inspector.y > 0 && r.inspector.x <= room) {
        const PixelRect box{std::max(left, right - r.inspector.x), bottom - r.inspector.y,
                            r.inspector.x, r.inspector.y};
        if (box.y > hudBottom + gap && !overlaps(box, l.messages) && !overlaps(box, l.hud)) {
            l.inspector = box;
        }
    }
    if (r.inspectorFirst) placeMessages();
    if (l.inspector.w > 0) bottom = l.inspector.y - gap;

    const bool columnAsked = (r.profile.x > 0 && r.profile.y > 0) || r.plots || r.speeds || r.bins;
    const bool fits = sideColumnFits(r.width, r.left, r.scale);
    const auto scaled = [&r](int pixels) { return static_cast<int>(pixels * r.scale); };
    l.columnFolded = columnAsked && !fits;
    int top = 4;
    for (const auto& [size, out] : {std::pair{r.profile, &l.profile}, {r.legend, &l.legend}}) {
        if (out == &l.profile && !fits) continue;
        if (size.x <= 0 || size.y <= 0 || size.x > room) continue;
        const PixelRect box = place(size, top);
        if (box.y + box.h > bottom || overlaps(box, l.messages)) continue;  // no room: left out
        *out = box;
        top = box.y + box.h + gap;
    }
    if (!fits || (!r.plots && !r.speeds && !r.bins)) return l;

    const int width = std::min(room, sideColumnWidth(r.width, r.left, r.scale));
    if (width < scaled(kPanelMinWidth)) return l;
    const PixelRect column = place({width, 0}, top);
    top = column.y;
    if (overlaps({column.x, top, width, bottom - top}, l.messages)) {
        bottom = l.messages.y - gap;
    }
    int height = bottom - top;
    const int rowMin = scaled(kPlotRowMinHeight);
    const int plotsMin = rowMin + 8;  // one row plus the panel's padding
    // The histograms take what is left after the plots' smallest useful size (one row), within
    // their own limits, from the bottom: the bins first (a scene with bins is about them), then
    // the speeds.
    const auto stack = [&](bool on, int most, int least, PixelRect& out) {
        if (!on) return;
        const int want = r.plots ? std::min(most, height - plotsMin - gap) : std::min(most, height);
        if (want < least) return;
        out = {column.x, bottom - want, width, want};
        bottom -= want + gap;
        height = bottom - top;
    };
    stack(r.bins, scaled(kBinsMaxHeight), scaled(kBinsMinHeight), l.bins);
    stack(r.speeds, scaled(kSpeedsMaxHeight), scaled(kSpeedsMinHeight), l.speeds);
    if (r.plots && height >= plotsMin) {
        const int rows = std::clamp((height - 8) / rowMin, 1, 4);
        const int rowHeight = std::min(scaled(kPlotRowMaxHeight), (height - 8) / rows);
        const int h = rows * rowHeight + 8;
        l.plots = {column.x, bottom - h, width, h};
        l.plotRows = rows;
        l.plotRowHeight = rowHeight;
    }
    return l;
}

}  // namespace psb::app
