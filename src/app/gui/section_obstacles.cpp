// The control panel's obstacle fields (in Tools): the sizes the Peg and Wall tools make, and the
// selected obstacle with a button that removes it.

#include <cstdio>

#include <imgui.h>

#include "gui/control_panel.hpp"
#include "gui/widgets.hpp"
#include "session/session.hpp"
#include "session/units.hpp"

namespace psb::app {

using widgets::tip;

void ControlPanel::obstacleTools(const Session& s) {
    const ObstacleSizes& now = s.obstacleSizes();
    double peg = now.pegRadius, wall = now.wallThickness;
    bool changed = false;
    ImGui::TextUnformatted("New obstacles:");
    ImGui::SetNextItemWidth(widgets::fieldWidth(120.f, "peg radius (m)"));
    changed |= ImGui::InputDouble("peg radius (m)", &peg, 0.0, 0.0, "%.3g",
                                  ImGuiInputTextFlags_AutoSelectAll);
    mark("peg radius");
    tip("The radius of the pegs the Peg tool places (at first the scene's typical particle's)");
    ImGui::SetNextItemWidth(widgets::fieldWidth(120.f, "wall thickness (m)"));
    changed |= ImGui::InputDouble("wall thickness (m)", &wall, 0.0, 0.0, "%.3g",
                                  ImGuiInputTextFlags_AutoSelectAll);
    mark("wall thickness");
    tip("How thick the walls the Wall tool draws are; their ends are round");
    // A size being typed passes through 0 ("0.2"): nothing is sent until both are positive.
    if (changed && peg > 0.0 && wall > 0.0) out_.emplace_back(cmd::SetObstacleSizes{peg, wall});

    const auto selected = s.selectedObstacle();
    if (!selected || *selected >= s.world().obstacles().size()) return;
    const Obstacle& o = s.world().obstacles()[*selected];
    char buf[160];
    if (o.isPeg()) {
        std::snprintf(buf, sizeof buf, "Selected peg: radius %s", quantity(o.radius, "m").c_str());
    } else {
        std::snprintf(buf, sizeof buf, "Selected wall: %s long, %s thick",
                      quantity((o.b - o.a).norm(), "m").c_str(),
                      quantity(o.thickness(), "m").c_str());
    }
    ImGui::TextUnformatted(buf);
    if (widgets::stateButton("delete obstacle", o.isPeg() ? "Delete peg" : "Delete wall")) {
        out_.emplace_back(cmd::RemoveObstacle{*selected});
    }
    mark("delete obstacle");
    tip("Remove the selected obstacle (Delete or Backspace; Ctrl+Z brings it back)");
}

}  // namespace psb::app
