#pragma once
// The part of the window the box is fitted into, as the view lays the window out: right of the
// control panel (open, or folded to its strip), below the HUD's band (which grows when the
// HUD's lines wrap in a narrow window, and holds the note that the side column is folded away),
// above the messages' band, left of the side column while a panel of it is on and the column
// fits beside the box (sideColumnFits), and left of the inspector's column when the box can
// spare it. The app sends these areas, with the help's page count, to the session with each
// window size (cmd::Resize, session/box_area.hpp): the box the session fits and the panels
// layoutPanels places agree, and a panel never covers the box.
//
//   ┌─────────┬──────────── HUD (top) ───────────┬──────────┐
//   │ control │                                  │  plots,  │
//   │ panel   │             the box              │ histogram│
//   │ (left)  │                                  │ (column) │
//   │         ├─────────── messages (bottom) ────┤          │
//   └─────────┴──────────────────────────────────┴──────────┘

#include "session/box_area.hpp"
#include "view/pixel_rect.hpp"
#include "view/text_measure.hpp"

namespace psb::app {

class Session;

/// The control panel's width at the window's left, pixels: open, and folded to its strip; and
/// the scale they were measured at, pixels per point of the UI (the pixel ratio × the UI's
/// scale), which the side column's charts take too (sideColumnWidth).
struct ControlsWidth {
    double open = 0.0;
    double folded = 0.0;
    double pointPixels = 1.0;
};

/// What the session is told of a window `width` × `height` pixels with the control panel
/// `controls` wide at its left: the box's area for each state of the panels, the HUD's band
/// and the help's pages measured in `hudFont` (the page's help when `inPage`).
[[nodiscard]] WindowLayout windowLayout(const TextMeasure& hudFont, int width, int height,
                                        const ControlsWidth& controls, bool inPage = false);

/// Whether the open control panel leaves the box a usable width (kBoxMinRoom points, pixels at a
/// pixel ratio of 1) in a window `width` pixels wide: a window made narrower folds it
/// (WindowLayout::controlsFit, which also asks that the HUD's lines, wrapped beside it, leave the
/// box kBoxMinHeight pixels).
[[nodiscard]] bool controlsFit(int width, const ControlsWidth& controls);

/// Pixels at the window's left the control panel takes now: open or folded, as in `session`.
[[nodiscard]] int controlsInset(const Session& session, const ControlsWidth& controls);

/// Whether `session`'s side-column panels are folded away: one is asked for, but the window
/// leaves the column no room beside the box (sideColumnFits; the box keeps the width), or the
/// values table docks at the right in its place (a short window).
[[nodiscard]] bool sideColumnFolded(const Session& session, const ControlsWidth& controls);

/// Where the values table docks while `session` shows it (valuesBandRect, in pixels; empty
/// while it is hidden): the panel places its window there, the layout puts the other panels
/// above it.
[[nodiscard]] PixelRect valuesTableRect(const Session& session, const ControlsWidth& controls);

}  // namespace psb::app
