#include "render/screen_text.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include "view/collision_card_lines.hpp"
#include "view/gas_lines.hpp"
#include "view/momenta_diagram.hpp"
#include "view/values_table.hpp"

namespace psb::app {
namespace {

void section(std::string& out, const char* name, const std::vector<std::string>& lines) {
    if (lines.empty()) return;
    out += name;
    out += ":\n";
    for (const std::string& l : lines)
        out += "  " + l + "\n";
}

void rect(std::string& out, const char* name, int x, int y, int w, int h) {
    if (w <= 0 || h <= 0) return;
    out += "  " + std::string(name) + " " + std::to_string(x) + " " + std::to_string(y) + " " +
           std::to_string(w) + " " + std::to_string(h) + "\n";
}

void rect(std::string& out, const char* name, const PixelRect& r) {
    rect(out, name, r.x, r.y, r.w, r.h);
}

}  // namespace

std::string screenText(const FrameView& frame, const DrawStats& drawn) {
    const Overlays& o = frame.overlays;
    std::string out;
    // How the signed numbers below count y (the y up option).
    section(out, "Axes",
            {axesNote(frame.view.axes(frame.world->def()), frame.world->rotationInUse())});
    section(out, "HUD", o.hud);
    section(out, "Messages", o.messages);
    section(out, "Inspector", o.inspector);
    if (o.showProfile) section(out, "Profile", o.profile);
    if (frame.recordingMark) section(out, "Recording", {frame.recordingMark->label});
    if (frame.gas) {
        std::vector<std::string> lines;
        for (const GasLine& l : gasLines(*frame.gas))
            lines.push_back(l.name + ": " + l.value);
        if (!frame.pressurePlot.empty()) lines.push_back(frame.pressurePlot);
        section(out, "Gas", lines);
    }
    if (frame.values) section(out, "Values", valuesLines(*frame.values));
    if (frame.collision) {
        const Axes axes = frame.view.axes(frame.world->def());
        std::vector<std::string> lines =
            collisionCardLines(collisionCardText(*frame.collision, axes));
        for (std::string& l : momentaDiagramLines(momentaDiagram(*frame.collision), axes))
            lines.push_back(std::move(l));
        section(out, "Last collision", lines);
    }
    if (frame.grid) section(out, "Grid", {frame.grid->legend});
    if (frame.ruler) section(out, "Ruler", {frame.ruler->line});
    if (frame.wallAngle) section(out, "Wall tool", {frame.wallAngle->text});
    if (o.showHelp) section(out, "Help", o.help);
    if (frame.bins && frame.layout.bins.w > 0) {
        std::vector<std::string> lines = frame.bins->legend;
        std::string counts = "counts:";
        for (const std::size_t c : frame.bins->now.counts.counts) {
            counts += ' ';
            counts += std::to_string(c);
        }
        lines.push_back(counts);
        if (!frame.bins->now.expected.empty()) {
            std::string expected = "binomial:";
            for (const double e : frame.bins->now.expected) {
                expected += ' ';
                expected += std::to_string(std::lround(e));
            }
            lines.push_back(expected);
        }
        section(out, "Bins", lines);
    }
    if (!frame.droppers.empty()) {
        std::vector<std::string> lines;
        for (const DropperView& d : frame.droppers)
            lines.push_back(d.label);
        section(out, "Droppers", lines);
    }
    if (frame.view.labels) {
        out += "Labels: " + std::to_string(drawn.labelled) + " drawn, " +
               std::to_string(drawn.labelsCrowded + drawn.labelsOffWindow) + " left out" +
               (drawn.labelsSuppressed ? " (too many particles on screen)" : "") + "\n";
    }
    out += "Layout:\n";
    if (frame.world != nullptr && frame.camera != nullptr) {
        const Camera::ScreenBox b =
            frame.camera->boxOnScreen(frame.world->def().width, frame.world->def().height);
        rect(out, "box", static_cast<int>(std::lround(b.topLeft.x())),
             static_cast<int>(std::lround(b.topLeft.y())),
             static_cast<int>(std::lround(b.size.x())), static_cast<int>(std::lround(b.size.y())));
    }
    const PanelLayout& l = frame.layout;
    rect(out, "hud", l.hud);
    rect(out, "messages", l.messages);
    rect(out, "inspector", l.inspector);
    rect(out, "legend", l.legend);
    rect(out, "profile", l.profile);
    rect(out, "plots", l.plots);
    rect(out, "speeds", l.speeds);
    rect(out, "bins", l.bins);
    rect(out, "values", l.values);
    return out;
}

}  // namespace psb::app
