#pragma once
// Where the text and analysis panels go, as a pure function of the window size and what each
// panel would need: the HUD at the top-left (right of the control panel's column), then a column at
// the right edge holding, from the top, the profile and the momentum legend (the recording mark
// goes last, in the top-right corner or under what stands there), and from the bottom
// the selected particle's inspector, the bins' histogram, the speed histogram and the plots. The
// profile and the legend keep off the box (LayoutRequest::box): where the top of the column
// would put one over it (the HUD's lines grew and pushed it down into the box's corner), it goes
// to the highest free place, then the rightmost: beside the HUD or the box, above or below the
// box, clear of the panels placed before it. The
// column starts below the HUD when the window is too narrow for both side by side, panels shrink to
// the room there is (the plots drop their least important first: rate, then py, then energy;
// plotsChosen), and a panel that does not fit at its smallest is left out. The values table (I)
// docks in a band along the window's bottom, right of the control panel and under everything else
// (valuesBand): the messages, the inspector and the column sit above it; or, in a window too short
// for that, in a column at the right below the HUD (valuesColumn), left of which the other panels
// go. A window too narrow for the column beside the box (sideColumnFits) folds the column's panels
// away, and says so (columnFolded), instead of laying them over the box. No two rectangles returned
// overlap.

#include <algorithm>
#include <string>
#include <vector>

#include "view/pixel_rect.hpp"

namespace psb::app {

/// Between the panels and the window's edges, pixels.
inline constexpr int kPanelMargin = 8;
/// Narrowest the side column's panels get, pixels.
inline constexpr int kSideColumnMinWidth = 220;
/// Widest the side column's panels get, pixels.
inline constexpr int kSideColumnMaxWidth = 330;

/// The side column's panel width for a window `windowWidth` pixels wide of which `leftInset`
/// are the control panel's: two fifths of what is left, within [min, max] × `scale` (pixels per
/// point of the UI: the pixel ratio × the UI's scale; the charts grow with their text).
[[nodiscard]] inline int sideColumnWidth(int windowWidth, int leftInset, double scale = 1.0) {
    const int least = static_cast<int>(kSideColumnMinWidth * scale);
    return std::clamp(static_cast<int>(0.4 * (windowWidth - leftInset)), least,
                      std::max(least, static_cast<int>(kSideColumnMaxWidth * scale)));
}

/// Narrowest room the box keeps beside the side column, pixels: a window that would leave it
/// less folds the column's panels away (the box keeps the width; the HUD says so).
inline constexpr int kBoxMinRoom = 240;

/// Whether the side column fits beside the box in a window `windowWidth` pixels wide of which
/// `leftInset` are the control panel's.
[[nodiscard]] inline bool sideColumnFits(int windowWidth, int leftInset, double scale = 1.0) {
    const int column = sideColumnWidth(windowWidth, leftInset, scale) + kPanelMargin;
    return windowWidth - leftInset - column >= kBoxMinRoom;
}

/// The values table's band (I), in points of the UI: its chrome (the line of its name and
/// buttons, the line saying which way y counts, the header and units rows, the totals row, a
/// horizontal scroll bar, the padding) and its particles' rows. The band holds up to
/// kValuesBandRows rows (a lesson's few balls); more scroll. The gui's table keeps to these
/// (section_values.cpp).
inline constexpr int kValuesChromePoints = 136;
inline constexpr int kValuesRowPoints = 21;
inline constexpr int kValuesBandRows = 3;
/// The values table's width with its particles' numbers and every column of a world without
/// rotation (x, y, vx, vy, px, py, KE, mass) in sight, points: the gui's columns are as wide as
/// their numbers (section_values.cpp), 440 points, and the window's padding.
inline constexpr int kValuesWidthPoints = 460;
/// The values table's column, when it docks at the right (a short window, where a band along
/// the bottom would leave the box too low), is 40 % of the room right of the control panel
/// and at least this wide, points.
inline constexpr int kValuesColumnMinPoints = 160;
/// The box keeps at least this height beside the values table's band, pixels, for its
/// column to be offered (a taller band is then not worth a narrower box).
inline constexpr int kBoxMinHeight = 240;

/// The values table's band, pixels: with its kValuesBandRows rows, the height of a row, and
/// with one row.
struct ValuesBand {
    int height = 0;
    int row = 0;
    int least = 0;
};

/// The values table's band in a window `windowHeight` pixels high whose HUD's band is `top`
/// pixels high, at `scale` pixels per point: never up into the HUD's band (then shorter than
/// `least`: its rows scroll).
[[nodiscard]] ValuesBand valuesBand(int windowHeight, double top, double scale);

/// The values table's column at the right of a window `width` pixels wide of which `left`
/// are the control panel's and `right` the side column's, at `scale` pixels per point, in a
/// window `height` high whose box's area is `top` and `bottom` from its edges: 0 when the box
/// would be left less than kBoxMinRoom beside it. The session docks the table there only where
/// a band along the bottom (`band` high) leaves the box too small (SceneView::fit).
[[nodiscard]] int valuesColumn(int width, double left, double right, int height, double top,
                               double bottom, int band, double scale);

/// The band's rectangle at the bottom of a window `width` × `height` pixels whose left `left`
/// pixels are the control panel's, for a band `band` pixels high.
[[nodiscard]] inline PixelRect valuesBandRect(int width, int height, int left, int band) {
    return {left + kPanelMargin, height - kPanelMargin - band, width - left - 2 * kPanelMargin,
            band};
}

/// The column's rectangle at the right of a window `width` × `height` pixels, below a HUD's
/// band `top` pixels high, for a column `column` pixels wide (valuesColumn, with its margin).
[[nodiscard]] inline PixelRect valuesColumnRect(int width, int height, int top, int column) {
    return {width - column, top, column - kPanelMargin, height - top - kPanelMargin};
}

/// What to lay out; sizes in pixels, {0, 0} for a panel that is off.
struct LayoutRequest {
    int width = 0;             ///< the window
    int left = 0;              ///< pixels at the left taken by the control panel
    int height = 0;            ///< the window
    PixelPoint hud{0, 0};      ///< the HUD's box (text plus padding)
    PixelPoint profile{0, 0};  ///< the profile overlay's box
    /// The recording mark's box: in the top-right corner, or under what stands there (the
    /// HUD as shown, `hudShown`, and the panels); placed last, as it is not in the video.
    PixelPoint recording{0, 0};
    /// The HUD's box as the screen shows it this frame, where the layout keeps `hud` more
    /// room (a video's HUD and the lines that come and go through the clip); {0, 0}: `hud`.
    PixelPoint hudShown{0, 0};
    PixelPoint legend{0, 0};    ///< the momentum legend's box
    PixelPoint messages{0, 0};  ///< the messages' box, at the bottom-left
    /// Where the messages' box ends (its bottom edge), where the band at the window's bottom
    /// has no room for them whole: over the box's lower part, above the charts' band under it.
    /// 0: at the bottom.
    int messagesBottom = 0;
    PixelPoint inspector{0, 0};  ///< the selected particle's panel, at the bottom of the column
    /// The values table (valuesTableRect): along the bottom, or at the right (`valuesRight`);
    /// w == 0: not shown.
    PixelRect values{};
    bool valuesRight = false;
    /// The inspector holds the open edit prompt, which has the keyboard: it is placed before the
    /// messages, which are left out where they would cover it.
    bool inspectorFirst = false;
    /// The side column's charts are folded away so that the box keeps its share of the window
    /// (SceneView::fit).
    bool foldColumn = false;
    bool plots = false;   ///< K
    bool speeds = false;  ///< D
    bool bins = false;    ///< a scene's bins (a Galton board's histogram)
    /// Pixels per point of the UI (sideColumnWidth): the charts' sizes below are × this.
    double scale = 1.0;
    /// The side column's charts go side by side in this band under the box instead of the
    /// column (chartsBandRect; the session chose it: SceneView::fit); w == 0: the column.
    PixelRect chartsBand{};
    /// The box on screen with its walls as drawn (w == 0: none): the profile and the momentum
    /// legend, placed at the top of the column, keep off it.
    PixelRect box{};
    /// The height of the line under the plots that names those left out for want of room
    /// (PanelLayout::plotsNote), pixels; 0: no such line.
    int plotsNote = 0;
    /// The least width of a plot side by side with others in the band under the box, pixels:
    /// its brief title (plotTitle) and its y axis's labels with some curve, as measured in the
    /// charts' font; 0: kPlotColumnMinWidth × scale.
    int plotColumnLeast = 0;
};

/// Panel rectangles in window pixels; w == 0 for a panel that is off or did not fit.
struct PanelLayout {
    PixelRect hud{};
    PixelRect recording{};
    PixelRect profile{};
    PixelRect legend{};
    PixelRect messages{};
    PixelRect inspector{};
    PixelRect plots{};
    PixelRect speeds{};
    PixelRect bins{};
    PixelRect values{};     ///< the values table (valuesBandRect or valuesColumnRect)
    int plotRows = 0;       ///< rows of plots shown, 1-4, of those plotsChosen picks
    int plotRowHeight = 0;  ///< pixels per plot
    /// The plots side by side in `plots` (a band under the box too low for them one above the
    /// other): each of these columns (plotColumn) shows plotRows of them, the next ones.
    int plotColumns = 1;
    /// The profile, plots or histograms were asked for but folded away: the window leaves the
    /// side column no room beside the box (sideColumnFits).
    bool columnFolded = false;
    /// Fewer than the four plots fit: the last `plotsNote` pixels of `plots`, under their rows,
    /// are a line naming the others (plotsLeftOutNote). 0: all four shown, or no room for it.
    int plotsNote = 0;
};

/// Which of the four plots (0 energy, 1 px, 2 py, 3 rate: kPlotCount) are shown when `shown`
/// (0-4) fit, in their order on screen: px first (a collision's lesson reads it), then the
/// energy, then py, then the rate; px alone, energy and px, energy, px and py, all four.
[[nodiscard]] std::vector<int> plotsChosen(int shown);

/// The line under the plots when `shown` (1-3) of the four fit: "No room: energy, rate" (a
/// teacher saw the momentum lesson's px and py charts gone without a word); "" when
/// all four fit.
[[nodiscard]] std::string plotsLeftOutNote(int shown);

inline constexpr int kPanelGap = 6;                         ///< between panels, pixels
inline constexpr int kPanelMaxWidth = kSideColumnMaxWidth;  ///< plots and histogram, pixels
inline constexpr int kPanelMinWidth = kSideColumnMinWidth;  ///< plots and histogram, pixels
/// The least width of a plot side by side with another in the band under the box, pixels: its
/// title ("momentum px (kg m/s)") and its tick labels, with some curve.
inline constexpr int kPlotColumnMinWidth = 160;
inline constexpr int kPlotRowMaxHeight = 100;  ///< pixels
/// Pixels: a plot's row holds its title, the time axis's labels and a y axis with room for
/// kPlotTicksLeast labels (plotRowsPlace, yTickCount) in the charts' font, a line of up to
/// 17 pixels at 100 % (64 left one tick, "3.50", at 200 %); where the room holds fewer rows,
/// fewer plots are shown, or in a band under the box they stand side by side.
inline constexpr int kPlotRowMinHeight = 96;
inline constexpr int kSpeedsMaxHeight = 210;  ///< pixels
inline constexpr int kSpeedsMinHeight = 130;  ///< pixels
inline constexpr int kBinsMaxHeight = 280;    ///< pixels
inline constexpr int kBinsMinHeight = 170;    ///< pixels

/// The band the side column's charts take under the box instead of the column (BoxArea's
/// chartsBand), pixels at `scale` pixels per point: a plots' row at its smallest and the
/// panel's padding (the plots stand side by side in it: PanelLayout::plotColumns), or the speed
/// histogram at its smallest.
[[nodiscard]] inline int chartsBandHeight(double scale) {
    return static_cast<int>(std::max(kPlotRowMinHeight + 8, kSpeedsMinHeight) * scale);
}

/// The `k`th (from 0) of the plots' columns in `layout` (PanelLayout::plotColumns): its box,
/// pixels; it shows the plots from k × plotRows on.
[[nodiscard]] inline PixelRect plotColumn(const PanelLayout& layout, int k) {
    const int columns = std::max(1, layout.plotColumns);
    const int each = (layout.plots.w - (columns - 1) * kPanelGap) / columns;
    return {layout.plots.x + k * (each + kPanelGap), layout.plots.y, each, layout.plots.h};
}

/// The band's rectangle at the bottom of a window `width` × `height` pixels whose left `left`
/// pixels are the control panel's, above the messages' band `messages` pixels high (BoxArea's
/// bottom), for a band `band` pixels high.
[[nodiscard]] inline PixelRect chartsBandRect(int width, int height, int left, int messages,
                                              int band) {
    return {left + kPanelMargin, height - messages - band, width - left - 2 * kPanelMargin, band};
}

/// Lays out the panels `r` asks for.
[[nodiscard]] PanelLayout layoutPanels(const LayoutRequest& r);

/// The left edge of the side column `r` would place at the window's right (its charts: plots,
/// histograms), pixels; `r.width` when there is none (off, folded, in the band under the box).
/// The messages wrap left of it (frame_view.cpp): a message of three lines reached under the
/// column and the plots lost a row to it, mid-video, and came back when it went.
[[nodiscard]] int sideColumnLeft(const LayoutRequest& r);

/// How many of the four plots (energy, px, py, rate) `layout` shows: 0 when they are off.
[[nodiscard]] inline int plotsShown(const PanelLayout& layout) {
    if (layout.plots.w <= 0 || layout.plotRows <= 0) return 0;
    return std::min(4, layout.plotRows * std::max(1, layout.plotColumns));
}

/// Every panel `layout` places (those that are off or left out are not listed).
[[nodiscard]] std::vector<PixelRect> panelRects(const PanelLayout& layout);

/// Whether two rectangles share a pixel (an empty one never does).
[[nodiscard]] bool overlaps(const PixelRect& a, const PixelRect& b);

}  // namespace psb::app
