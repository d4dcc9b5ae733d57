#pragma once
// The pixels the camera keeps free around the box when it fits it, and the width of the side
// column, shared by the session (which fits the box) and the panel layout (which places the
// panels), so that the two always agree and a panel never covers the box.
//
//   ┌─────────┬──────────── HUD (top) ───────────┬──────────┐
//   │ control │                                  │  plots,  │
//   │ panel   │             the box              │ histogram│
//   │ (left)  │                                  │ (column) │
//   │         ├─────────── messages (bottom) ────┤          │
//   └─────────┴──────────────────────────────────┴──────────┘

#include <algorithm>
#include <functional>

namespace psb::app {

struct ViewInsets {
    double top = 0.0;
    double bottom = 0.0;
    /// The side column's widest (plus its margin); it narrows in small windows, see
    /// sideColumnWidth. Kept free while a panel of it (plots, speed histogram, profile) is on.
    double panelColumn = 0.0;
    /// The control panel at the left while it is open, and its folded strip.
    double controls = 0.0;
    double controlsFolded = 0.0;
    /// The inspector's column at the bottom right: kept free when the box can spare it without
    /// shrinking (see Session::fit).
    double inspectorColumn = 0.0;
    /// When set, the band above the box for a HUD `room` pixels wide (its lines wrap in a
    /// narrow window), with the note that the side column is folded when `folded`: the larger
    /// of this and `top` is kept free.
    std::function<double(int room, bool folded)> topFor{};
    /// When set, how many pages the help takes in a window `width` × `height` pixels whose
    /// left `left` pixels are the control panel's (see helpPages); otherwise one.
    std::function<int(int width, int height)> helpPagesFor{};
};

/// Between the panels and the window's edges, pixels.
inline constexpr int kPanelMargin = 8;
/// Narrowest the side column's panels get, pixels.
inline constexpr int kSideColumnMinWidth = 220;
/// Widest the side column's panels get, pixels.
inline constexpr int kSideColumnMaxWidth = 330;

/// The side column's panel width for a window `windowWidth` pixels wide of which `leftInset`
/// are the control panel's: two fifths of what is left, within [min, max] (times `scale`, the
/// pixels per point).
[[nodiscard]] inline int sideColumnWidth(int windowWidth, int leftInset, double scale = 1.0) {
    const int lo = static_cast<int>(kSideColumnMinWidth * scale);
    const int hi = static_cast<int>(kSideColumnMaxWidth * scale);
    return std::clamp(static_cast<int>(0.4 * (windowWidth - leftInset)), lo, hi);
}

/// Narrowest room the box keeps beside the side column, pixels: a window that would leave it
/// less folds the column's panels away (the box keeps the width; the HUD says so).
inline constexpr int kBoxMinRoom = 240;

/// Whether the side column fits beside the box in a window `windowWidth` pixels wide of which
/// `leftInset` are the control panel's (times `scale`, the pixels per point).
[[nodiscard]] inline bool sideColumnFits(int windowWidth, int leftInset, double scale = 1.0) {
    const int column =
        sideColumnWidth(windowWidth, leftInset, scale) + static_cast<int>(kPanelMargin * scale);
    return windowWidth - leftInset - column >= static_cast<int>(kBoxMinRoom * scale);
}

}  // namespace psb::app
