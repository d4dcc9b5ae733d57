// The control panel's Physics section: how the world is stepped and what its collisions and
// forces are.

#include <cmath>
#include <string>

#include <imgui.h>

#include "gui/control_panel.hpp"
#include "gui/widgets.hpp"
#include "session/physics_controls.hpp"
#include "session/session.hpp"
#include "session/units.hpp"

namespace psb::app {

using widgets::tip;

namespace {

/// What a press of Heat multiplies every speed by (Cool divides).
constexpr double kHeatFactor = 1.1;
/// What a press of Squeeze multiplies the box's area by (Expand divides).
constexpr double kSqueezeArea = 0.9;

/// What each mode trades, in a sentence a student can read.
const char* modeSentence(StepMode mode) {
    switch (mode) {
        case StepMode::Discrete:
            return "Discrete: moves everything one step, then separates what overlaps. The "
                   "fastest; a very fast particle can pass through another.";
        case StepMode::Substep:
            return "Substeps: the same in k smaller steps. About k times slower; fast particles "
                   "pass through others k times less often.";
        case StepMode::Exact:
            return "Exact: finds the moment of every collision, in order. No overlaps and "
                   "energy kept to rounding; slower in dense scenes.";
    }
    return "";
}

}  // namespace

void ControlPanel::physics(const Session& s) {
    const bool open = ImGui::CollapsingHeader("Physics", ImGuiTreeNodeFlags_DefaultOpen);
    mark("section Physics");
    if (!open) return;
    const World& w = s.world();
    const SolverSettings& solver = w.solver();
    if (solver.mode == StepMode::Substep) substeps_ = solver.substeps;

    const auto modeButton = [&](const char* label, StepMode m) {
        if (ImGui::RadioButton(label, solver.mode == m)) {
            out_.emplace_back(cmd::SetMode{m, substeps_});
        }
        mark(std::string("mode ") + label);
        tip(modeSentence(m));
    };
    // A touch screen has no T: the buttons alone.
    const char* modeLine = s.touch() ? "Mode:" : "Mode (key T):";
    ImGui::TextUnformatted(modeLine);
    mark("mode line", modeLine);
    modeButton("Discrete", StepMode::Discrete);
    widgets::sameLineIfRoom(widgets::checkWidth("Substeps"));
    modeButton("Substeps", StepMode::Substep);
    widgets::sameLineIfRoom(widgets::checkWidth("Exact"));
    modeButton("Exact", StepMode::Exact);
    if (solver.mode == StepMode::Substep) {
        ImGui::SetNextItemWidth(150.f);
        int k = substeps_;
        if (widgets::sliderInt("k substeps", k, 2, kMaxPanelSubsteps)) {
            substeps_ = k;
            out_.emplace_back(cmd::SetMode{StepMode::Substep, k});
        }
        mark("substeps");
        tip("Smaller steps per time step: more accurate, k times the work");
    }
    widgets::wrappedDisabled(modeSentence(solver.mode));

    const WorldDef& d = w.def();
    double e = d.restitution;
    bool continues = false;
    if (widgets::slider("Restitution", e, 0.0, 1.0, "%.2f", continues)) {
        out_.emplace_back(cmd::SetRestitution{e, continues});
    }
    mark("Restitution");
    tip("How bouncy collisions are: 1 keeps all the energy of the approach, 0 keeps none (the "
        "particles stick together for that instant). Keys E and Shift+E.");
    double mu = d.friction;
    if (widgets::slider("Friction", mu, 0.0, 1.0, "%.2f", continues)) {
        out_.emplace_back(cmd::SetFriction{mu, continues});
    }
    mark("Friction");
    tip("Friction where surfaces touch: 0 is ice; higher values take more of the sliding "
        "along the contact away in each collision, and turn discs that touch: a ball on a "
        "slope rolls.");
    double beta = d.tangentialRestitution;
    if (widgets::slider("Roughness", beta, -1.0, 1.0, "%.2f", continues)) {
        out_.emplace_back(cmd::SetTangentialRestitution{beta, continues});
    }
    mark("Roughness");
    tip("Tangential restitution \u03b2: what a gripping contact does to the slip of the touching "
        "surfaces. 0 stops it (the usual choice), 1 reverses it (perfectly rough discs that "
        "keep their energy, like a superball), -1 leaves it (smooth discs). Acts only with "
        "friction.");

    const bool gravityOn = d.gravity != Vec2::Zero();
    bool on = gravityOn;
    double g = gravityOn ? d.gravity.norm() : kEarthGravity;
    if (ImGui::Checkbox("Gravity", &on)) out_.emplace_back(cmd::SetGravity{on, g, false});
    mark("Gravity");
    tip("A steady pull downwards (key G). Earth's is 9.81 m/s\xc2\xb2.");
    ImGui::SameLine();
    ImGui::BeginDisabled(!gravityOn);
    ImGui::SetNextItemWidth(-1.f);
    if (widgets::slider("##g", g, 0.1, 30.0, "%.2f m/s\xc2\xb2", continues,
                        ImGuiSliderFlags_Logarithmic)) {
        out_.emplace_back(cmd::SetGravity{true, g, continues});
    }
    mark("g");
    ImGui::EndDisabled();
    tip("The strength of gravity: Earth 9.81, the Moon 1.62, Jupiter 24.8 m/s\xc2\xb2");
    bool walls = d.walls;
    if (ImGui::Checkbox("Walls", &walls)) out_.emplace_back(cmd::SetWalls{walls});
    mark("Walls");
    tip("The four walls of the box; without them particles fly away");
    widgets::sameLineAt(ImGui::GetContentRegionAvail().x * 0.55f);
    bool turn = s.spawn().turn;
    if (ImGui::Checkbox("Discs turn", &turn)) out_.emplace_back(cmd::SetDiscsTurn{turn});
    mark("Discs turn");
    tip("Whether the particles you launch or add from now on turn: friction spins them and they "
        "roll. Unticked they have fixed rotation and slide without turning, as a block or a "
        "puck. The particles already there keep theirs.");
    // Heat and cool: every speed times a factor, so the temperature changes by its square.
    if (ImGui::Button("Heat")) out_.emplace_back(cmd::ScaleSpeeds{kHeatFactor});
    mark("Heat");
    tip("Every particle a tenth faster: the temperature (mean kinetic energy) up by 21 %");
    ImGui::SameLine();
    if (ImGui::Button("Cool")) out_.emplace_back(cmd::ScaleSpeeds{1.0 / kHeatFactor});
    mark("Cool");
    tip("Every particle a tenth slower (divided by 1.1): the temperature down by 17 %");
    // The volume: the box squeezed or expanded with the particles in it.
    const double width = w.def().width, height = w.def().height;
    const bool fixedBox = !w.obstacles().empty() || !w.droppers().empty();
    widgets::sameLineIfRoom(widgets::buttonWidth("Squeeze"));
    ImGui::BeginDisabled(fixedBox);
    const double side = std::sqrt(kSqueezeArea);
    if (ImGui::Button("Squeeze")) out_.emplace_back(cmd::ResizeBox{width * side, height * side});
    mark("Squeeze");
    std::string box = "Box ";
    box += quantity(width, "m");
    box += " x ";
    box += quantity(height, "m");
    box += ", area ";
    box += quantity(width * height, "m\u00b2", false);
    widgets::tip((box + (fixedBox ? ". This scene's walls, pegs or spouts are fixed in the box: "
                                    "it keeps its size"
                                  : ". Squeeze: 10 % less area, the particles moved in with it "
                                    "and their speeds kept: at the same temperature the gas's "
                                    "pressure goes up (Boyle). Ctrl+Z undoes it"))
                     .c_str());
    widgets::sameLineIfRoom(widgets::buttonWidth("Expand"));
    if (ImGui::Button("Expand")) out_.emplace_back(cmd::ResizeBox{width / side, height / side});
    mark("Expand");
    widgets::tip((box + ". Expand: 10 % more area (divided by 0.9), the particles moved out with "
                        "it")
                     .c_str());
    ImGui::EndDisabled();
}

}  // namespace psb::app
