#include "view/screen_layout.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>

namespace psb::app {

std::vector<int> plotsChosen(int shown) {
    // What a lesson reads first: the momentum px (a collision's lesson), then the energy (kept
    // or not), then py, then the rate.
    static const int priority[4] = {1, 0, 2, 3};
    std::vector<int> out(priority, priority + std::clamp(shown, 0, 4));
    std::sort(out.begin(), out.end());
    return out;
}

std::string plotsLeftOutNote(int shown) {
    static const char* const names[4] = {"energy", "px", "py", "rate"};
    const std::vector<int> chosen = plotsChosen(shown);
    std::string out;
    for (int k = 0; k < 4; ++k) {
        if (std::find(chosen.begin(), chosen.end(), k) != chosen.end()) continue;
        out += std::string(out.empty() ? "" : ", ") + names[k];
    }
    return out.empty() ? out : "No room: " + out;
}

bool overlaps(const PixelRect& a, const PixelRect& b) {
    if (a.w <= 0 || a.h <= 0 || b.w <= 0 || b.h <= 0) return false;
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

std::vector<PixelRect> panelRects(const PanelLayout& l) {
    std::vector<PixelRect> out;
    for (const PixelRect& r : {l.hud, l.recording, l.profile, l.legend, l.messages, l.inspector,
                               l.plots, l.speeds, l.bins, l.values}) {
        if (r.w > 0 && r.h > 0) out.push_back(r);
    }
    return out;
}

ValuesBand valuesBand(int windowHeight, double top, double scale) {
    const auto pixels = [scale](int points) { return static_cast<int>(std::ceil(points * scale)); };
    ValuesBand b;
    b.row = pixels(kValuesRowPoints);
    b.least = pixels(kValuesChromePoints + kValuesRowPoints);
    // Never up into the HUD's band, whatever the scale.
    const int most = std::max(0, windowHeight - static_cast<int>(std::ceil(top)) - kPanelMargin);
    b.height = std::min(most, pixels(kValuesChromePoints + kValuesBandRows * kValuesRowPoints));
    return b;
}

int valuesColumn(int width, double left, double right, int, double, double, int, double scale) {
    // Offered wherever it leaves the box its room beside it: the session takes it only where a
    // band along the bottom would leave the box too small (SceneView::fit).
    const double room = width - left - right;
    const int column = static_cast<int>(
        std::ceil(std::max(0.4 * room, kValuesColumnMinPoints * scale) + kPanelMargin));
    return room - column >= kBoxMinRoom ? column : 0;
}

namespace {

/// Whether the side column at the right holds charts in `r`, and its width, pixels (0: none).
int sideColumnWidthIn(const LayoutRequest& r) {
    if (!r.plots && !r.speeds && !r.bins) return 0;
    if (r.chartsBand.w > 0 && (r.plots || r.speeds)) return 0;
    if (!sideColumnFits(r.width, r.left, r.scale) || (r.values.w > 0 && r.valuesRight) ||
        r.foldColumn) {
        return 0;
    }
    const int room = r.width - r.left - 2 * kPanelMargin;
    const int width = std::min(room, sideColumnWidth(r.width, r.left, r.scale));
    return width < static_cast<int>(kPanelMinWidth * r.scale) ? 0 : width;
}

}  // namespace

int sideColumnLeft(const LayoutRequest& r) {
    const int width = sideColumnWidthIn(r);
    return width > 0 ? r.width - kPanelMargin - width : r.width;
}

namespace {

/// The panels but the recording mark.
PanelLayout layoutWithoutMark(const LayoutRequest& r) {
    PanelLayout l;
    const int m = kPanelMargin, gap = kPanelGap;
    int right = r.width - m;
    const int left = r.left + m;  // the leftmost a right-aligned panel may start
    int room = r.width - r.left - 2 * m;
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
    // The values table first, along the bottom: the other panels stand on it; or at the right:
    // they go left of it.
    if (r.values.w > 0 && room > 0) {
        l.values = r.values;
        if (r.valuesRight) {
            right = l.values.x - gap;
            room = right - left;
        } else {
            bottom = l.values.y - gap;
        }
    }
    const auto placeMessages = [&] {
        const int end = r.messagesBottom > 0 ? std::min(r.messagesBottom, bottom) : bottom;
        if (r.messages.x <= 0 || r.messages.y <= 0 || end - r.messages.y <= hudBottom) return;
        const PixelRect box{r.left + 4, end - r.messages.y, r.messages.x, r.messages.y};
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
    // The values table at the right takes the column's place.
    const bool fits = sideColumnFits(r.width, r.left, r.scale) &&
                      !(r.values.w > 0 && r.valuesRight) && !r.foldColumn;
    const auto scaled = [&r](int pixels) { return static_cast<int>(pixels * r.scale); };
    l.columnFolded = columnAsked && !fits && r.chartsBand.w == 0;
    int top = 4;
    // The charts' band under the box, where the session chose it: the legend and the profile
    // keep off it (below the box, the legend was drawn over by the plots).
    const PixelRect chartsBand =
        r.chartsBand.w > 0 && (r.plots || r.speeds) ? r.chartsBand : PixelRect{};
    // What of the band the plots alone take: their rows at their least (a row, or as many as
    // the band holds), the rest of its height free for the legend below them, so that it does
    // not take the plots' width (the lesson's four at 200 % stand side by side in the band).
    PixelRect bandTaken = chartsBand;
    if (chartsBand.w > 0 && r.plots && !r.speeds) {
        const int rowMin = scaled(kPlotRowMinHeight);
        if (chartsBand.h >= rowMin + 8) {
            const int rows = std::clamp((chartsBand.h - 8) / rowMin, 1, 4);
            const int rowHeight = std::min(scaled(kPlotRowMaxHeight), (chartsBand.h - 8) / rows);
            bandTaken.h = std::min(chartsBand.h, rows * rowHeight + 8);
        }
    }
    // The highest free place for a panel of `size`, then the rightmost, in the room right of
    // the control panel above `bottom`: clear of the box, the HUD, the charts' band and the
    // panels placed so far. Its edges are tried against each of theirs (none: w == 0).
    const auto freePlace = [&](PixelPoint size) {
        const std::vector<PixelRect> taken = {r.box,    l.hud,     l.messages, l.inspector,
                                              l.values, l.profile, l.legend,   bandTaken};
        std::vector<int> xs{right - size.x, left}, ys{top};
        for (const PixelRect& t : taken) {
            if (t.w <= 0) continue;
            xs.push_back(t.x - gap - size.x);
            xs.push_back(t.x + t.w + gap);
            ys.push_back(t.y + t.h + gap);
        }
        std::sort(ys.begin(), ys.end());
        std::sort(xs.begin(), xs.end(), std::greater<>());
        for (const int y : ys) {
            if (y < 4 || y + size.y > bottom) continue;
            for (const int x : xs) {
                if (x < left || x + size.x > right) continue;
                const PixelRect box{x, y, size.x, size.y};
                if (std::none_of(taken.begin(), taken.end(),
                                 [&box](const PixelRect& t) { return overlaps(box, t); })) {
                    return box;
                }
            }
        }
        return PixelRect{};
    };
    for (const auto& [size, out] : {std::pair{r.profile, &l.profile}, {r.legend, &l.legend}}) {
        if (out == &l.profile && !fits) continue;
        if (size.x <= 0 || size.y <= 0 || size.x > room) continue;
        PixelRect box = place(size, top);
        if (overlaps(box, r.box) || overlaps(box, bandTaken)) {
            // Over the box's corner: another place; the column's charts start below it where
            // it stands over them.
            box = freePlace(size);
            if (box.w == 0 && out == &l.legend && chartsBand.w > 0 && size.x <= chartsBand.w / 2 &&
                size.y <= chartsBand.h) {
                // Nowhere else (a HUD grown by a step back, or a video's room for it, down to
                // the box's top): at the right end of the charts' band, the charts beside it.
                box = {chartsBand.x + chartsBand.w - size.x, chartsBand.y, size.x, size.y};
            }
            if (box.w == 0) continue;
            *out = box;
            if (box.x + box.w > right - sideColumnWidth(r.width, r.left, r.scale))
                top = std::max(top, box.y + box.h + gap);
            continue;
        }
        if (box.y + box.h > bottom || overlaps(box, l.messages)) continue;  // no room: left out
        *out = box;
        top = box.y + box.h + gap;
    }
    if (r.chartsBand.w > 0 && (r.plots || r.speeds)) {
        // Under the box, side by side from the left: the plots, the speed histogram; left of
        // the inspector where it stands in the band. A chart narrower than its least is left
        // out.
        PixelRect band = r.chartsBand;
        if (l.inspector.w > 0 && l.inspector.y < band.y + band.h) {
            band.w = std::min(band.w, l.inspector.x - gap - band.x);
        }
        if (overlaps(l.legend, band)) {
            // Below the plots' rows (bandTaken): the band ends above it; else beside them.
            if (l.legend.y >= bandTaken.y + bandTaken.h) {
                band.h = std::min(band.h, l.legend.y - gap - band.y);
            } else {
                band.w = std::min(band.w, l.legend.x - gap - band.x);
            }
        }
        // (Messages above the band, over the box, leave it whole.)
        if (l.messages.w > 0 && l.messages.y < band.y + band.h &&
            l.messages.y + l.messages.h > band.y) {
            band.h = l.messages.y - gap - band.y;
        }
        const int count = (r.plots ? 1 : 0) + (r.speeds ? 1 : 0);
        const int each = (band.w - (count - 1) * gap) / count;
        const int rowMin = scaled(kPlotRowMinHeight);
        const int least = scaled(kPanelMinWidth);
        if (each < least) return l;
        int x = band.x;
        if (r.plots && band.h >= rowMin + 8) {
            const int rows = std::clamp((band.h - 8) / rowMin, 1, 4);
            const int rowHeight = std::min(scaled(kPlotRowMaxHeight), (band.h - 8) / rows);
            // Too low for the plots one above the other: side by side, as many as keep each at
            // its least width (the lesson's four in a band one row high at 200 %).
            const int narrowest =
                r.plotColumnLeast > 0 ? r.plotColumnLeast : scaled(kPlotColumnMinWidth);
            const int columns =
                std::clamp(std::min((4 + rows - 1) / rows, (each + gap) / (narrowest + gap)), 1, 4);
            l.plots = {x, band.y, each, rows * rowHeight + 8};
            l.plotRows = rows;
            l.plotRowHeight = rowHeight;
            l.plotColumns = columns;
            // The note naming the plots left out, under them where the band has the room.
            if (rows * columns < 4 && r.plotsNote > 0 && l.plots.h + r.plotsNote <= band.h) {
                l.plotsNote = r.plotsNote;
                l.plots.h += r.plotsNote;
            }
            x += each + gap;
        }
        if (r.speeds && band.h >= scaled(kSpeedsMinHeight)) {
            l.speeds = {x, band.y, each, std::min(band.h, scaled(kSpeedsMaxHeight))};
        }
        return l;
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
        int rows = std::clamp((height - 8) / rowMin, 1, 4);
        // Fewer than four: a line under them names the others, where a row still fits above it.
        int note = 0;
        if (rows < 4 && r.plotsNote > 0 && height - 8 - r.plotsNote >= rowMin) {
            note = r.plotsNote;
            rows = std::clamp((height - 8 - note) / rowMin, 1, 4);
        }
        const int rowHeight = std::min(scaled(kPlotRowMaxHeight), (height - 8 - note) / rows);
        const int h = rows * rowHeight + 8 + note;
        l.plots = {column.x, bottom - h, width, h};
        l.plotRows = rows;
        l.plotRowHeight = rowHeight;
        l.plotsNote = note;
    }
    return l;
}

}  // namespace

PanelLayout layoutPanels(const LayoutRequest& r) {
    PanelLayout l = layoutWithoutMark(r);
    if (r.recording.x <= 0 || r.recording.y <= 0) return l;
    // The recording mark last, in the top-right corner or under whatever stands there: the HUD
    // as the screen shows it this frame, the panels. It is not in the video, so it may move
    // when the screen's HUD grows (a step into the past) while the panels, which are, stay put.
    const PixelRect shown{l.hud.x, l.hud.y, r.hudShown.x > 0 ? r.hudShown.x : l.hud.w,
                          r.hudShown.y > 0 ? r.hudShown.y : l.hud.h};
    const int x = std::max(r.left + kPanelMargin, r.width - kPanelMargin - r.recording.x);
    int y = kPanelMargin;
    for (int tries = 0; tries < 16 && y + r.recording.y <= r.height - kPanelMargin; ++tries) {
        const PixelRect box{x, y, r.recording.x, r.recording.y};
        const PixelRect* hit = nullptr;
        for (const PixelRect* other : std::initializer_list<const PixelRect*>{
                 &shown, &l.profile, &l.legend, &l.messages, &l.inspector, &l.plots, &l.speeds,
                 &l.bins, &l.values}) {
            if (overlaps(box, *other)) {
                hit = other;
                break;
            }
        }
        if (hit == nullptr) {
            l.recording = box;
            return l;
        }
        y = hit->y + hit->h + kPanelGap;
    }
    return l;
}

}  // namespace psb::app
