// The control panel's Last collision section: the card (session/last_collision.hpp) as a table
// of before and after, with what the collision kept and lost. Shown while J (or the Show
// section's checkbox) has the card on.

#include <algorithm>

#include <imgui.h>

#include "gui/control_panel.hpp"
#include "gui/widgets.hpp"
#include "session/session.hpp"
#include "view/collision_card_lines.hpp"

namespace psb::app {

void ControlPanel::lastCollision(const Session& s) {
    const bool turnedOn = s.view().collision && !cardShown_;
    cardShown_ = s.view().collision;
    if (!s.view().collision) return;
    if (turnedOn) ImGui::SetNextItemOpen(true);
    const float top = ImGui::GetCursorPosY();
    const bool open = ImGui::CollapsingHeader("Last collision", ImGuiTreeNodeFlags_DefaultOpen);
    mark("section Last collision");
    if (open) card(s);
    if (turnedOn) {  // into view, once: the user may scroll away from it after
        const float bottom = ImGui::GetCursorPosY(), scroll = ImGui::GetScrollY();
        const float shown = ImGui::GetWindowHeight() - ImGui::GetStyle().WindowPadding.y;
        if (top < scroll || bottom > scroll + shown)
            ImGui::SetScrollY(std::min(top, bottom - shown));
    }
}

void ControlPanel::card(const Session& s) {
    const std::optional<CollisionCard>& card = s.lastCollision();
    const std::optional<Particle> selected = s.selected();
    if (!card) {
        widgets::wrappedDisabled(
            selected ? "Particle " + std::to_string(particleNumber(selected->id)) +
                           " has not collided since the card was shown: run time (Space)"
                     : std::string("No collision between two particles yet: run time (Space), "
                                   "or select a particle to follow its collisions"));
        return;
    }
    const CollisionCardText text = collisionCardText(*card);
    widgets::wrapped(text.title);
    mark("collision title");
    widgets::wrappedDisabled(card->follows != 0 ? "The selected particle's last collision"
                                                : "The last collision between two particles "
                                                  "(select one to follow it)");
    if (ImGui::BeginTable("collision", 3, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("before", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("after", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableHeadersRow();
        for (const CollisionCardText::Row& r : text.rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(r.name.c_str());
            if (!r.unit.empty()) ImGui::TextDisabled("%s", r.unit.c_str());
            widgets::tip(r.help.c_str());
            ImGui::TableNextColumn();
            widgets::wrapped(r.before);
            mark("collision " + r.name + " before");
            ImGui::TableNextColumn();
            widgets::wrapped(r.after);
            mark("collision " + r.name + " after");
        }
        ImGui::EndTable();
    }
    for (const std::string& note : text.notes)
        widgets::wrapped(note);
}

}  // namespace psb::app
