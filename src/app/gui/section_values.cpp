// The values table's window (view/values_table.hpp): every particle's signed position,
// velocity, momentum, kinetic energy and mass with units in the headers, the totals, the cells
// of position, velocity and mass editable in place (type, then Enter or click elsewhere, as the
// Selected particle section's fields), Copy and Export. A window of its own, movable and
// resizable, as eight columns do not fit the panel; I or the Show section's checkbox opens it.

#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "gui/control_panel.hpp"
#include "gui/widgets.hpp"
#include "session/session.hpp"
#include "view/values_table.hpp"

namespace psb::app {

void ControlPanel::valuesWindow(const Session& s, float height) {
    if (!s.view().values) {
        valuesEditing_.reset();
        return;
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float left = s.controlsShown() ? kControlsWidth + 8.f : kControlsFoldedWidth + 8.f;
    const float tall = std::min(260.f, 0.4f * height);
    // Above the message band (bottom left), which it would hide.
    ImGui::SetNextWindowPos(ImVec2(left, height - tall - 64.f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(std::max(320.f, display.x - left - 8.f), tall),
                             ImGuiCond_FirstUseEver);
    bool open = true;
    const bool shown = ImGui::Begin("Values table (I)", &open);
    mark("values window");
    if (!open) out_.emplace_back(cmd::SetShow{cmd::ShowOption::Values, false});
    if (!shown) {
        ImGui::End();
        return;
    }
    const ValuesTable t = valuesTable(s.world(), s.selection().id(), s.axes());
    if (ImGui::SmallButton("Copy")) out_.emplace_back(cmd::CopyTable{cmd::DataTable::Values});
    mark("values Copy");
    widgets::tip("Every particle's values as tab-separated text, to paste into a spreadsheet");
    ImGui::SameLine();
    if (ImGui::SmallButton("Export CSV")) {
        out_.emplace_back(cmd::ExportTable{cmd::DataTable::Values, {}});
    }
    mark("values Export");
    widgets::tip("Write every particle's values as a CSV file (values.csv)");
    ImGui::SameLine();
    ImGui::TextDisabled(s.world().rotationInUse()
                            ? "click a number to select; type in x, y, vx, vy, \u03c9 or mass"
                            : "click a number to select; type in x, y, vx, vy or mass");
    if (!t.note.empty()) widgets::wrappedDisabled(t.note);
    widgets::wrappedDisabled(t.axes);

    const std::vector<ValuesColumn>& columns = t.columns;
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                  ImGuiTableFlags_SizingStretchSame | ImGuiTableFlags_ScrollY;
    if (!ImGui::BeginTable("values", static_cast<int>(columns.size()) + 1, flags)) {
        ImGui::End();
        return;
    }
    ImGui::TableSetupScrollFreeze(0, 2);
    ImGui::TableSetupColumn("#", ImGuiTableColumnFlags_WidthFixed);
    // Names in the header, units in a row under it: "px (kg m/s)" would not fit a column.
    for (const ValuesColumn& c : columns)
        ImGui::TableSetupColumn(c.name);
    ImGui::TableHeadersRow();
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    for (const ValuesColumn& c : columns) {
        ImGui::TableNextColumn();
        ImGui::TextDisabled("%s", c.unit);
    }
    const auto selectedId = s.selection().id();
    bool editingSeen = false;
    for (const ValuesRow& r : t.rows) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        const std::string number = std::to_string(r.number);
        if (ImGui::Selectable(number.c_str(), selectedId && *selectedId == r.id)) {
            out_.emplace_back(cmd::Select{r.id});
        }
        mark("values row " + number);
        for (std::size_t k = 0; k < columns.size(); ++k) {
            ImGui::TableNextColumn();
            if (!columns[k].field) {
                ImGui::TextUnformatted(valuesCell(r.values[k]).c_str());
                continue;
            }
            const ParticleField field = *columns[k].field;
            const bool editing =
                valuesEditing_ && valuesEditing_->first == r.id && valuesEditing_->second == field;
            std::array<char, 64> shownText{};
            std::array<char, 64>& text = editing ? valuesText_ : shownText;
            // Four figures, as the read-only cells show three: six were cut off at 200 %.
            if (!editing) std::snprintf(text.data(), text.size(), "%.4g", r.values[k]);
            ImGui::SetNextItemWidth(-1.f);
            ImGui::PushID(static_cast<int>(r.number * kValuesColumns + k));
            const bool enter = ImGui::InputText("##cell", text.data(), text.size(),
                                                ImGuiInputTextFlags_EnterReturnsTrue |
                                                    ImGuiInputTextFlags_CharsScientific |
                                                    ImGuiInputTextFlags_AutoSelectAll);
            const bool leftField = ImGui::IsItemDeactivatedAfterEdit();
            if (ImGui::IsItemActivated()) {  // typing starts here: keep the text across frames
                valuesEditing_ = {r.id, field};
                valuesText_ = text;
            }
            if (ImGui::IsItemActive()) editingSeen = true;
            mark("values " + number + " " + columns[k].name);
            if (enter || leftField) {
                out_.emplace_back(cmd::EditParticle{r.id, field, text.data()});
                valuesEditing_.reset();
            }
            ImGui::PopID();
        }
    }
    if (!editingSeen) valuesEditing_.reset();
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("total");
    widgets::tip(
        "The sums over every particle: the total momentum (a vector), kinetic energy (and, "
        "for discs that turn, rotational kinetic energy) and mass");
    for (std::size_t k = 0; k < columns.size(); ++k) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(valuesCell(t.totals[k]).c_str());
        mark(std::string("values total ") + columns[k].name);
    }
    ImGui::EndTable();
    ImGui::End();
}

}  // namespace psb::app
