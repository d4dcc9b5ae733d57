#pragma once
// Where the box may go on screen. The view lays out the window (view/box_area.hpp) and hands
// the session, with each window size (cmd::Resize), the area the box is fitted into for each
// state of the panels the session switches: the control panel open or folded, a panel of the
// side column (plots, histograms, profile) asked for or not, and the values table's band. The
// session fits the box into the area its panels are in; it knows no panel, font or margin, only
// these rectangles.

namespace psb::app {

/// The part of the window the box is fitted into, as the pixels kept free at each of the
/// window's edges (all 0: the whole window).
struct BoxArea {
    double left = 0.0;
    double top = 0.0;
    double right = 0.0;
    double bottom = 0.0;
    /// A column this wide at the area's right (the inspector's) is kept free too when the box
    /// fitted into the area leaves it whole beside it: the box then moves left and keeps its
    /// size. Whether it does depends on the box's proportions, which the session knows.
    double spareColumn = 0.0;
    /// While the values table is shown it docks where it leaves the box largest, and never
    /// over it: in a band this tall above the area's bottom (its chrome and its few rows; it
    /// docks along the window's bottom, under the messages), or that band less a row or more
    /// (`valuesRow` pixels each, down to `valuesLeast`: one row; the others scroll), or in a column
    /// `valuesColumn` wide at the area's right, below the HUD (0: no room for it there, the
    /// side column is).
    double valuesBand = 0.0;
    double valuesRow = 0.0;
    double valuesLeast = 0.0;
    double valuesColumn = 0.0;
    /// The values table's width with every column in sight, pixels: a column at the right
    /// narrower than this hides some of them (they scroll).
    double valuesWidth = 0.0;
    /// Particles' rows the full band holds.
    double valuesRows = 0.0;
    /// The area's top when the side column's charts are folded away (the HUD's band then holds
    /// the line that says so).
    double foldedTop = 0.0;
    /// The side column's charts may go in a band this tall under the box instead (above the
    /// messages), where a column beside the box would leave it less than its share (a wide,
    /// low box: the momentum lesson's 10 m by 4 m at 200 %); 0: no such band.
    double chartsBand = 0.0;

    friend bool operator==(const BoxArea&, const BoxArea&) = default;
};

/// Where the values table docks, as the session chose in fitting the box (BoxArea).
struct ValuesDock {
    bool right = false;  ///< in a column at the right, else in a band along the bottom
    double size = 0.0;   ///< the band's height or the column's width, pixels
    friend bool operator==(const ValuesDock&, const ValuesDock&) = default;
};

/// What the session is told of the window's layout at one window size.
struct WindowLayout {
    BoxArea controlsOpen;        ///< the control panel open, no side column asked for
    BoxArea controlsFolded;      ///< the control panel folded to its strip, likewise
    BoxArea controlsOpenColumn;  ///< the control panel open, a side-column panel asked for
    BoxArea controlsFoldedColumn;
    /// Pages the help takes in this window (H turns them, and closes the help after the last).
    int helpPages = 1;
    /// The open control panel leaves the box a usable width beside it. When not, a window made
    /// this narrow folds the panel; opened all the same, it lies over the box, which keeps the
    /// folded panel's area (controlsOpen is then controlsFolded).
    bool controlsFit = true;

    /// The area for the panels in this state.
    [[nodiscard]] const BoxArea& area(bool controlsShown, bool columnAsked) const {
        if (columnAsked) return controlsShown ? controlsOpenColumn : controlsFoldedColumn;
        return controlsShown ? controlsOpen : controlsFolded;
    }

    friend bool operator==(const WindowLayout&, const WindowLayout&) = default;
};

}  // namespace psb::app
