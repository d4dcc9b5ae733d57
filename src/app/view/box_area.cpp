#include "view/box_area.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "session/session.hpp"
#include "view/hud.hpp"
#include "view/overlays.hpp"
#include "view/screen_layout.hpp"

namespace psb::app {

namespace {

/// The band above the box the HUD takes in a window that leaves it `room` pixels right of the
/// control panel: its lines wrapped to the room (frame_view.cpp wraps them so), the key to the
/// discs' shades among them, each as many
/// lines as the most it takes for readings short or long (a line broken between its parts can
/// take more lines with shorter numbers: "momentum (0, 0) kg" and "m/s"), the note that the
/// side column is folded when `folded`, room for the note about labels left out, and the
/// margin.
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
    wide.lightestMass = 0.00123;  // the shade's key: a scene of several masses
    wide.heaviestMass = 123.45;
    HudData lesson;  // a lesson's two balls at rest in the HUD's shortest figures
    lesson.particles = 2;
    lesson.kineticEnergy = 3.5;
    lesson.momentum = Vec2(-1.0, 0.0);
    lesson.spawnMass = 1.0;
    lesson.spawnRadius = 0.12;
    lesson.arrowSeconds = 1.0 / 3.0;
    lesson.paused = true;
    HudData zero = lesson;
    zero.kineticEnergy = 0.0;
    zero.momentum = Vec2::Zero();
    HudData noArrows = zero;
    noArrows.arrowSeconds = 0.0;
    const int width = room - 8;
    const bool narrow = hudIsNarrow(font, room);
    std::vector<std::size_t> most;
    for (HudData d : {wide, lesson, zero, noArrows}) {
        d.narrow = narrow;
        const std::vector<std::string> lines = hudLines(d);
        most.resize(std::max(most.size(), lines.size()));
        for (std::size_t k = 0; k < lines.size(); ++k)
            most[k] = std::max(most[k], wrapHudLines(font, {lines[k]}, width).size());
    }
    std::size_t lines = 0;
    for (const std::size_t n : most)
        lines += n;
    if (folded) {  // the longest of the notes
        std::size_t note = 0;
        for (const bool open : {true, false})
            for (const bool touch : {false, true})
                note = std::max(
                    note, wrapLines(font, {foldedChartsNote(open, touch, narrow)}, width).size());
        lines += note;
    }
    lines += std::max(wrapLines(font, {labelsLeftOutNote(99, false, narrow)}, width).size(),
                      wrapLines(font, {labelsLeftOutNote(99, true, narrow)}, width).size());
    return static_cast<double>(lines) * font.lineHeight() + 10.0;
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
        const ValuesBand band = valuesBand(height, a.top, controls.pointPixels);
        // The values table's column takes the side column's place, whose charts then fold
        // away (the HUD says so: the box then stands below foldedTop).
        a.valuesColumn = valuesColumn(width, a.left, 0.0, height, a.top, a.bottom, band.least,
                                      controls.pointPixels);
        a.valuesWidth = kValuesWidthPoints * controls.pointPixels;
        a.valuesRows = kValuesBandRows;
        a.foldedTop = std::max(a.top, hudBand(hudFont, room, true));
        a.chartsBand = chartsBandHeight(controls.pointPixels) + kPanelGap;
        a.valuesBand = band.height + kPanelGap;
        a.valuesRow = band.row;
        a.valuesLeast = std::min(band.least, band.height) + kPanelGap;
        return a;
    };
    WindowLayout l;
    // The open panel also leaves the box its height: beside a panel at 200 % in a window 1024
    // pixels wide the HUD's lines wrap to half the window's height.
    const BoxArea besideOpen = area(controls.open, false);
    l.controlsFit = controlsFit(width, controls) &&
                    height - besideOpen.top - besideOpen.bottom >= kBoxMinHeight;
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

PixelRect valuesTableRect(const Session& session, const ControlsWidth& controls) {
    if (!session.view().values) return {};
    const Camera& camera = session.camera();
    const BoxArea& a = session.layout().area(session.controlsShown(), session.columnAsked());
    const ValuesDock& dock = session.valuesDock();
    if (dock.right) {
        // Below the note that the side column's charts are folded, when they are asked for.
        const double top = session.columnAsked() ? std::max(a.top, a.foldedTop) : a.top;
        return valuesColumnRect(camera.viewportWidth(), camera.viewportHeight(),
                                static_cast<int>(top), static_cast<int>(dock.size));
    }
    // A band the session has not chosen yet (no fit since the table was shown): the full one.
    const int band = static_cast<int>(dock.size > 0.0 ? dock.size : a.valuesBand) - kPanelGap;
    return valuesBandRect(camera.viewportWidth(), camera.viewportHeight(),
                          controlsInset(session, controls), band);
}

bool sideColumnFolded(const Session& session, const ControlsWidth& controls) {
    if (session.chartsBelow()) return false;  // in a band under the box
    if (session.columnAsked() && session.view().values && session.valuesDock().right) return true;
    // Folded so that the box keeps its share of the window (SceneView::fit).
    if (session.columnAsked() && session.columnFolded()) return true;
    return session.columnAsked() &&
           !sideColumnFits(session.camera().viewportWidth(), controlsInset(session, controls),
                           controls.pointPixels);
}

}  // namespace psb::app
