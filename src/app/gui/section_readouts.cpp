// The control panel's Readouts (what a student reads) and Engine (what a developer reads)
// sections.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include <imgui.h>

#include <particle_sandbox/diagnostics.hpp>

#include "gui/control_panel.hpp"
#include "gui/widgets.hpp"
#include "session/accuracy.hpp"
#include "session/physics_controls.hpp"
#include "session/session.hpp"
#include "session/units.hpp"
#include "view/gas_lines.hpp"
#include "view/pressure_plot.hpp"

namespace psb::app {

using widgets::row;
using widgets::tip;

namespace {

/// The farthest any particle moves in one step of `frame` seconds, in its own diameters (one
/// substep in the substep mode): above about 1 a collision can be missed, a particle passing
/// through another.
double stepsPerDiameter(const World& w, double frame) {
    const ParticleArrays& p = w.particles();
    const SolverSettings& s = w.solver();
    const double dt = frame / (s.mode == StepMode::Substep ? s.substeps : 1);
    double worst = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double speed = std::hypot(p.vx[i], p.vy[i]);
        worst = std::max(worst, speed * dt / (2.0 * p.radius[i]));
    }
    return worst;
}

std::string vector(const Vec2& v, const char* unit) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%s, %s) %s", quantity(v.x(), "", false).c_str(),
                  quantity(v.y(), "", false).c_str(), unit);
    return buf;
}

}  // namespace

void ControlPanel::readouts(const Session& s) {
    const bool open = ImGui::CollapsingHeader("Readouts", ImGuiTreeNodeFlags_DefaultOpen);
    mark("section Readouts");
    if (!open) return;
    const World& w = s.world();
    const ObservablesSample& o = s.observables();
    const bool gravity = w.def().gravity != Vec2::Zero();
    // The rows first, then the table: its names' column leaves the values their room.
    struct Readout {
        std::string name, value, help;
    };
    std::vector<Readout> rows;
    {
        const auto readout = [&rows](const char* name, const std::string& value,
                                     const char* help = nullptr) {
            rows.push_back({name, value, help != nullptr ? help : ""});
        };
        readout("Time", quantity(w.time(), "s") + (s.paused() ? ", paused" : ""),
                "Simulated time since the scene started");
        readout("Particles", std::to_string(w.size()));
        const bool rotation = w.rotationInUse();
        readout("Kinetic energy", quantity(o.kineticEnergy, "J"),
                rotation ? "The energy of motion along the paths, the sum of \u00bd m v\u00b2 "
                           "over every particle (the turning's is below)"
                         : "The energy of motion, the sum of \u00bd m v\u00b2 over every particle");
        if (rotation) {
            readout("Rotational energy", quantity(o.rotationalEnergy, "J"),
                    "The energy of turning, the sum of \u00bd I \u03c9\u00b2 with I = k m "
                    "r\u00b2: a rolling ball carries part of its energy this way");
        }
        if (gravity) {
            readout("Mechanical energy",
                    quantity(o.kineticEnergy + o.rotationalEnergy + o.potentialEnergy, "J"),
                    rotation ? "Kinetic, rotational and potential energy (m g h): what elastic "
                               "collisions and rolling without slipping keep constant"
                             : "Kinetic plus potential energy (m g h): what elastic collisions "
                               "under gravity keep constant");
        }
        readout("Momentum", vector(s.axes().vector(o.momentum), "kg m/s"),
                "The total momentum, the sum of m v: walls and gravity change it, collisions "
                "between particles never do");
        readout("  size", quantity(o.momentum.norm(), "kg m/s", false));
        if (rotation) {
            const Axes axes = s.axes();
            readout("Angular momentum",
                    quantity(axes.angularMomentum(o.angularMomentum, o.momentum.x()),
                             "kg m\u00b2/s", false),
                    axes.yUp ? "The total angular momentum about the box's bottom-left corner, "
                               "orbital (m r \u00d7 v) plus spin (I \u03c9), positive "
                               "counterclockwise: collisions between particles never change it, "
                               "the walls and gravity do"
                             : "The total angular momentum about the box's top-left corner, "
                               "orbital (m r \u00d7 v) plus spin (I \u03c9), positive clockwise "
                               "on screen (y down): collisions between particles never change "
                               "it, the walls and gravity do");
        }
        if (const std::optional<GasReading> gas = s.gasReading()) {
            for (const GasLine& line : gasLines(*gas))
                readout(line.name.c_str(), line.value, line.help.c_str());
        }
    }
    std::vector<std::string> names;
    for (const Readout& r : rows)
        names.push_back(r.name);
    if (widgets::beginRows("readouts", widgets::rowNames(names))) {
        // Each readout's name and value are marked, for the tests that check they never meet.
        for (const Readout& row : rows) {
            const widgets::RowRects r = widgets::row(
                row.name.c_str(), row.value, row.help.empty() ? nullptr : row.help.c_str(), true);
            items_.push_back({"readout " + row.name, r.name0.x, r.name0.y, r.name1.x, r.name1.y});
            items_.push_back(
                {"readout " + row.name + " value", r.value0.x, r.value0.y, r.value1.x, r.value1.y});
        }
        ImGui::EndTable();
    }
    if (s.gasReading()) pressurePlot(s);

    // Accuracy, in words.
    const double drift = s.accuracy().drift(monitoredEnergy(w));
    const char* which = gravity ? "Mechanical energy" : "Energy";
    std::string kept = std::string(which) + " " + keptWords(drift) + " since your last change";
    // A loss the laws make on purpose is said so, lest it read as an error of the simulation.
    const WorldDef& laws = w.def();
    if (std::abs(drift) >= 1e-3 && (laws.restitution < 1.0 || laws.friction > 0.0)) {
        kept += laws.friction > 0.0 && laws.restitution < 1.0
                    ? ": friction and inelastic collisions take energy"
                : laws.friction > 0.0 ? ": friction takes energy"
                                      : ": inelastic collisions take energy";
    }
    widgets::wrapped(kept);
    tip("How well the simulation keeps the energy it should keep. Collisions with restitution "
        "below 1, friction and your own changes (a fling, a launch) change it on purpose; the "
        "count starts again at each change.");
    widgets::wrapped(overlapWords(s.accuracy().overlap(), s.spawn().typicalRadius));
    tip("Real balls never overlap; a step-by-step simulation lets them, a little, between steps");
    if (w.solver().mode != StepMode::Exact && w.size() > 0) {
        const double d = stepsPerDiameter(w, s.meta().dt);
        char buf[160];
        if (d > 1.0) {
            std::snprintf(buf, sizeof buf,
                          "Fast particles move %.1f diameters a step: collisions can be missed "
                          "(try more substeps or Exact)",
                          d);
            widgets::wrappedColored(widgets::caution(s.view().theme), buf);
        } else {
            std::snprintf(buf, sizeof buf,
                          "No collision can be missed: the fastest moves %.2f of its size a step",
                          d);
            widgets::wrapped(buf);
        }
        tip("A particle that moves more than its own size in one step can pass through another "
            "without touching it; the exact mode never misses one");
    }
}

namespace {

/// Okabe and Ito's colours, told apart by colour-blind viewers too.
constexpr ImU32 kMeasuredColor = IM_COL32(230, 159, 0, 255);   // orange
constexpr ImU32 kHardDiskColor = IM_COL32(86, 180, 233, 255);  // sky blue
constexpr ImU32 kIdealColor = IM_COL32(0, 158, 115, 255);      // bluish green

ImVec2 onCanvas(const ImVec2& at, const ImVec2& size, const Vec2& unit) {
    return {at.x + static_cast<float>(unit.x()) * size.x,
            at.y + (1.f - static_cast<float>(unit.y())) * size.y};
}

void polyline(ImDrawList& draw, const ImVec2& at, const ImVec2& size, const std::vector<Vec2>& line,
              ImU32 color, float thickness) {
    std::vector<ImVec2> points;
    points.reserve(line.size());
    for (const Vec2& p : line)
        points.push_back(onCanvas(at, size, p));
    if (points.size() >= 2) {
        draw.AddPolyline(points.data(), static_cast<int>(points.size()), color, ImDrawFlags_None,
                         thickness);
    }
}

}  // namespace

void ControlPanel::pressurePlot(const Session& s) {
    const PressurePlot plot = psb::app::pressurePlot(s.gasHistory());
    ImGui::TextUnformatted("Pressure over time");
    tip("The pressure measured on the walls (orange, with its standard error as a band) beside "
        "the hard-disc value (blue) and the ideal gas's N kT / A (green), over the last minute "
        "of simulated time. Heat or cool the gas and watch all three follow");
    mark("pressure plot");
    if (plot.empty()) {
        widgets::wrappedDisabled(s.touch() ? "Run time (Play): a point every 0.25 s"
                                           : "Run time (Space): a point every 0.25 s");
        return;
    }
    const float font = ImGui::GetFontSize();
    const ImVec2 size(ImGui::GetContentRegionAvail().x, 6.0f * font);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##pressure plot", size);
    ImDrawList& draw = *ImGui::GetWindowDrawList();
    const ImU32 frame = ImGui::GetColorU32(ImGuiCol_Border);
    draw.AddRect(at, ImVec2(at.x + size.x, at.y + size.y), frame);
    // Lines as thick as the text is large stay inside the frame.
    draw.PushClipRect(at, ImVec2(at.x + size.x, at.y + size.y), true);
    // The error band as thin vertical strokes between low and high: cheap and clear at any width.
    for (std::size_t k = 0; k < plot.measured.size(); ++k) {
        const std::vector<Vec2>& lo = plot.measuredLow[k];
        const std::vector<Vec2>& hi = plot.measuredHigh[k];
        for (std::size_t i = 0; i < lo.size(); ++i) {
            draw.AddLine(onCanvas(at, size, lo[i]), onCanvas(at, size, hi[i]),
                         (kMeasuredColor & 0x00FFFFFFu) | (0x70u << IM_COL32_A_SHIFT), 2.0f);
        }
    }
    polyline(draw, at, size, plot.ideal, kIdealColor, 0.1f * font);
    polyline(draw, at, size, plot.hardDisk, kHardDiskColor, 0.1f * font);
    for (const std::vector<Vec2>& line : plot.measured)
        polyline(draw, at, size, line, kMeasuredColor, 0.13f * font);
    draw.PopClipRect();
    // The vertical scale: its top and its bottom, 0.
    const ImU32 text = ImGui::GetColorU32(ImGuiCol_TextDisabled);
    const PlotScaleLabels labels = plotScaleLabels(size.y, font);
    draw.AddText(ImVec2(at.x + labels.x, at.y + labels.top), text,
                 quantity(plot.top, "N/m", false).c_str());
    draw.AddText(ImVec2(at.x + labels.x, at.y + labels.bottom), text, "0 N/m");
    const std::string t0 = quantity(plot.t0, "s"), t1 = quantity(plot.t1, "s");
    ImGui::TextDisabled("%s", t0.c_str());
    ImGui::SameLine(std::max(0.f, size.x - ImGui::CalcTextSize(t1.c_str()).x));
    ImGui::TextDisabled("%s", t1.c_str());
    // The key on one line where it fits, else each name on the next line: at 200 % or more in
    // a narrow panel its last name ran past the panel's edge.
    const float right = ImGui::GetCursorScreenPos().x + size.x;
    bool first = true;
    for (const auto& [colour, name] :
         {std::pair{kMeasuredColor, "measured"}, std::pair{kHardDiskColor, "hard discs"},
          std::pair{kIdealColor, "ideal gas"}}) {
        if (!first) {
            const float next = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x +
                               ImGui::CalcTextSize(name).x;
            if (next <= right) ImGui::SameLine();
        }
        first = false;
        ImGui::TextColored(ImColor(colour), "%s", name);
    }
}

void ControlPanel::engine(const Session& s, const FrameStats& stats) {
    const bool open = ImGui::CollapsingHeader("Engine");
    mark("section Engine");
    if (!open) return;
    const World& w = s.world();
    if (widgets::beginRows("engine")) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.0f", stats.fps);
        row("Frames per second", buf);
        std::snprintf(buf, sizeof buf, "%.2f ms", stats.stepMs);
        row("Simulation per frame", buf);
        std::snprintf(buf, sizeof buf, "%.2f ms", stats.drawMs);
        row("Drawing per frame", buf);
        row("Renderer", stats.renderer);
        row("Mode", modeName(w.solver()));
        row("Broadphase",
            w.solver().mode == StepMode::Exact ? std::string("event cells")
                                               : std::string(toString(w.broadPhaseInUse())),
            "How pairs that may touch are found: all pairs for a few particles, a grid of cells "
            "for many");
        row("Threads", std::to_string(w.threads()));
        std::snprintf(buf, sizeof buf, "%g ms", s.meta().dt * 1000.0);
        row("Time step", buf);
        ImGui::EndTable();
    }
    bool profile = s.profileShown();
    if (ImGui::Checkbox("Profile beside the box", &profile)) {
        out_.emplace_back(cmd::SetShow{cmd::ShowOption::Profile, profile});
    }
    mark("Profile");
    tip("The last step's stages with their times, in a panel beside the box (keys O, F3)");
    const StepProfile& p = w.profile();
    if (p.stageCount > 0 && widgets::beginRows("profile")) {
        char buf[32];
        for (int k = 0; k < p.stageCount; ++k) {
            std::snprintf(buf, sizeof buf, "%.3f ms", p.stages[k].ms);
            row(std::string(p.stages[k].name).c_str(), buf);
        }
        std::snprintf(buf, sizeof buf, "%.3f ms", p.total);
        row("step total", buf);
        ImGui::EndTable();
    }
}

}  // namespace psb::app
