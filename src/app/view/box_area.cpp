#include "view/box_area.hpp"

#include <algorithm>

#include "session/session.hpp"
#include "view/hud.hpp"
#include "view/overlays.hpp"
#include "view/screen_layout.hpp"

namespace psb::app {

namespace {

/// The band above the box the HUD takes in a window that leaves it `room` pixels right of the
/// control panel: its lines as wide as the readings get, wrapped to the room (frame_view.cpp
/// wraps them so), with the note that the side column is folded when `folded`, one spare line
/// for the notes about labels left out, and the margin.
double hudBand(const TextMeasure& font, int room, bool folded) {
    HudData wide;
    wide.simTime = 123.45;
    wide.particles = 10000;
    wide.kineticEnergy = 123.45;
    wide.momentum = Vec2(-0.123, -0.123);
    wide.spawnMass = 0.00123;
    wide.spawnRadius = 0.00123;
    wide.arrowSeconds = 0.0123;
    wide.paused = true;
    wide.recording = true;
    std::size_t lines = wrapHudLines(font, hudLines(wide), room - 8).size();
    if (folded) {  // the longer of the two notes
        lines += std::max(wrapLines(font, {foldedChartsNote(true)}, room - 8).size(),
                          wrapLines(font, {foldedChartsNote(false)}, room - 8).size());
    }
    return static_cast<double>(lines + 1) * font.lineHeight() + 10.0;
}

}  // namespace

WindowLayout windowLayout(const TextMeasure& hudFont, int width, int height,
                          const ControlsWidth& controls, bool inPage) {
    const int lh = hudFont.lineHeight();
    // The HUD's band at its shortest, with one spare line for the notes about labels left out.
    const double top = static_cast<double>(hudLines(HudData{}).size() + 1) * lh + 10.0;
    const double bottom = static_cast<double>(kMessageLines) * lh + 4.0 + kPanelMargin;
    // The inspector with long numbers in its widest line, and the margin.
    const double inspector =
        textBoxSize(hudFont, {"momentum        (-123.45, -123.45) kg m/s"}).x + 2.0 * kPanelMargin;
    const auto area = [&](double left, bool columnAsked) {
        BoxArea a;
        a.left = left;
        a.bottom = bottom;
        const int room = width - static_cast<int>(left);
        const bool fits = sideColumnFits(width, static_cast<int>(left), controls.pointPixels);
        a.top = std::max(top, hudBand(hudFont, room, columnAsked && !fits));
        // The momentum legend is three short lines: it does not cost the box a column.
        if (columnAsked && fits) {
            a.right = sideColumnWidth(width, static_cast<int>(left), controls.pointPixels) +
                      1.0 * kPanelMargin;
        } else {
            a.spareColumn = inspector;
        }
        return a;
    };
    WindowLayout l;
    l.controlsFit = controlsFit(width, controls);
    // A panel opened in a window too narrow for it lies over the box, which stays where it was:
    // squeezed into what is left, it would be a sliver, partly under the panel all the same.
    const double open = l.controlsFit ? controls.open : controls.folded;
    l.controlsOpen = area(open, false);
    l.controlsFolded = area(controls.folded, false);
    l.controlsOpenColumn = area(open, true);
    l.controlsFoldedColumn = area(controls.folded, true);
    const PixelRect room = helpRoom(width, height);
    l.helpPages = static_cast<int>(helpPages(hudFont, helpLines(inPage), {room.w, room.h}).size());
    return l;
}

bool controlsFit(int width, const ControlsWidth& controls) {
    // In points: on a phone's screen of 3 pixels a point, 240 pixels were a sliver of box.
    return width - controls.open >= kBoxMinRoom * controls.pointPixels;
}

int controlsInset(const Session& session, const ControlsWidth& controls) {
    return static_cast<int>(session.controlsShown() ? controls.open : controls.folded);
}

bool sideColumnFolded(const Session& session, const ControlsWidth& controls) {
    return session.columnAsked() &&
           !sideColumnFits(session.camera().viewportWidth(), controlsInset(session, controls),
                           controls.pointPixels);
}

}  // namespace psb::app
