// The values table's window (view/values_table.hpp): every particle's signed position,
// velocity, momentum, kinetic energy and mass with units in the headers, the totals, the cells
// of position, velocity and mass editable in place (type, then Enter or click elsewhere, as the
// Selected particle section's fields), Copy and Export. I or the Show section's checkbox shows
// it, docked in the band the view keeps for it along the window's bottom (valuesTableRect):
// its columns as wide as their numbers, scrolled sideways where the band is narrower than
// them, the particles' numbers staying at the left; its rows scrolled where there are more
// than the band holds.

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <string>

#include <imgui.h>

#include "gui/control_panel.hpp"
#include "gui/widgets.hpp"
#include "session/session.hpp"
#include "session/units.hpp"
#include "view/box_area.hpp"
#include "view/values_table.hpp"

namespace psb::app {

namespace {

/// An editable cell's text: as the read-only cells and every readout write the quantity
/// (fieldNumber: -2.5 m/s is "-2.50" here as on the card), more figures where it has them.
std::array<char, 64> fieldText(double value) {
    std::array<char, 64> text{};
    const std::string digits = fieldNumber(value);
    digits.copy(text.data(), text.size() - 1);
    return text;
}

}  // namespace

void ControlPanel::valuesWindow(const Session& s, float pointPixels) {
    if (!s.view().values) {
        valuesEditing_.reset();
        return;
    }
    // The band in pixels, the window in the UI's points.
    const PixelRect band =
        valuesTableRect(s, controlsWidth(pointPixels, ImGui::GetIO().DisplaySize.x * pointPixels));
    ImGui::SetNextWindowPos(
        ImVec2(static_cast<float>(band.x) / pointPixels, static_cast<float>(band.y) / pointPixels));
    ImGui::SetNextWindowSize(
        ImVec2(static_cast<float>(band.w) / pointPixels, static_cast<float>(band.h) / pointPixels));
    const ImGuiWindowFlags windowFlags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove |
                                         ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                         ImGuiWindowFlags_NoSavedSettings |
                                         ImGuiWindowFlags_NoScrollbar;
    const bool shown = ImGui::Begin("Values table (I)", nullptr, windowFlags);
    {
        const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        items_.push_back({"values window", at.x, at.y, at.x + size.x, at.y + size.y,
                          ImGui::GetID("Values table (I)")});
    }
    if (!shown) {
        ImGui::End();
        return;
    }
    ImGui::TextUnformatted("Values table");
    widgets::tip(
        s.world().rotationInUse()
            ? "Click a particle's number to select it; type in x, y, vx, vy, \u03c9 or mass"
            : "Click a particle's number to select it; type in x, y, vx, vy or mass");
    const ImGuiStyle& style = ImGui::GetStyle();
    // The next small button on this line where it fits whole, else on the next: in a column
    // at the right the line is narrower than the name and its three buttons.
    const auto besideIfRoom = [&style](const char* label) {
        const float width = ImGui::CalcTextSize(label).x + 2.f * style.FramePadding.x;
        const float right = ImGui::GetWindowContentRegionMax().x;
        ImGui::SameLine();
        if (ImGui::GetCursorPosX() + width > right) ImGui::NewLine();
    };
    besideIfRoom("Copy");
    const ValuesTable t = valuesTable(s.world(), s.selection().id(), s.axes());
    if (ImGui::SmallButton("Copy")) out_.emplace_back(cmd::CopyTable{cmd::DataTable::Values});
    mark("values Copy");
    widgets::tip("Every particle's values as tab-separated text, to paste into a spreadsheet");
    besideIfRoom("Export CSV");
    if (ImGui::SmallButton("Export CSV")) {
        out_.emplace_back(cmd::ExportTable{cmd::DataTable::Values, {}});
    }
    mark("values Export");
    widgets::tip("Write every particle's values as a CSV file (values.csv)");
    besideIfRoom("Hide");
    if (ImGui::SmallButton("Hide")) out_.emplace_back(cmd::SetShow{cmd::ShowOption::Values, false});
    mark("values Hide");
    widgets::tip("Hide the values table (key I)");
    // Which way y counts, and why rows are missing: the band keeps a line for them
    // (kValuesChromePoints); in a narrow one they wrap and the rows scroll.
    widgets::wrappedDisabled(t.note.empty() ? t.axes : t.axes + "; " + t.note);

    const std::vector<ValuesColumn>& columns = t.columns;
    // Each column as wide as its name, its unit and its widest number (the fields with their
    // frames), so no number is cut; the band scrolls sideways when they are wider than it.
    std::vector<float> widths(columns.size(), 0.f);
    const auto widen = [&widths](std::size_t k, const std::string& text, float extra) {
        widths[k] = std::max(widths[k], ImGui::CalcTextSize(text.c_str()).x + extra);
    };
    // A column's name and unit with a space's air, on top of the cells' padding: the units row
    // draws no border between its cells, and "kg m/s" beside "kg m/s" read as one at 200 %.
    const float air = ImGui::CalcTextSize(" ").x;
    for (std::size_t k = 0; k < columns.size(); ++k) {
        const float frame = columns[k].field ? 2.f * style.FramePadding.x : 0.f;
        widen(k, columns[k].name, air);
        widen(k, columns[k].unit, air);
        widen(k, valuesCell(t.totals[k]), 0.f);
        for (const ValuesRow& r : t.rows) {
            widen(k,
                  columns[k].field ? std::string(fieldText(r.values[k]).data())
                                   : valuesCell(r.values[k]),
                  frame);
        }
        // A field at least as wide as a signed value of four figures ("-1.235", "-12.35"), and
        // a number as wide as one of three ("-0.123", "-1 230"), so that columns do not jump
        // while values change (the kinetic energy's was as narrow as "KE" at rest, and its
        // numbers ran into the next column once the bodies moved); a longer one typed scrolls
        // within its field.
        widen(k, "-0.000", frame);
    }
    // Wider than the room: say so where it is seen, and which columns are out of sight (the
    // particles' numbers stay at the left as the table scrolls).
    {
        const float cell = 2.f * std::ceil(style.CellPadding.x / 2.f) + 1.f;  // and a border
        float x = std::max(ImGui::CalcTextSize("total").x,
                           ImGui::CalcTextSize(std::to_string(t.particles).c_str()).x) +
                  cell;
        const float room = ImGui::GetContentRegionAvail().x;
        std::string hidden;
        for (std::size_t k = 0; k < columns.size(); ++k) {
            x += widths[k] + cell;
            if (x > room) hidden += std::string(hidden.empty() ? "" : ", ") + columns[k].name;
        }
        if (!hidden.empty()) {
            widgets::wrappedColored(widgets::caution(s.view().theme),
                                    "Scroll sideways (the bar below the rows) for " + hidden);
            mark("values more columns");
        }
    }
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                  ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX |
                                  ImGuiTableFlags_ScrollY;
    // Fields as tall as a line of text with a pixel either side: the rows the band counts
    // (kValuesRowPoints).
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(style.FramePadding.x, 1.f));
    // Cells half as far apart as ImGui's default (the borders between columns part them):
    // nine columns gain the room of a tenth, which the lesson's mass needed at 200 %.
    ImGui::PushStyleVar(ImGuiStyleVar_CellPadding,
                        ImVec2(std::ceil(style.CellPadding.x / 2.f), style.CellPadding.y));
    if (!ImGui::BeginTable("values", static_cast<int>(columns.size()) + 1, flags)) {
        ImGui::PopStyleVar(2);
        ImGui::End();
        return;
    }
    // A table laid out anew (another scale, another band) starts at its top left: a scroll
    // kept from before showed the middle of a table that now fits.
    const std::pair<float, float> laidOut{band.w / pointPixels, band.h / pointPixels};
    if (laidOut != valuesLaidOut_) {
        ImGui::SetScrollX(0.f);
        ImGui::SetScrollY(0.f);
        valuesLaidOut_ = laidOut;
    }
    ImGui::TableSetupScrollFreeze(1, 2);
    ImGui::TableSetupColumn("#", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("total").x);
    // Names in the header, units in a row under it: "px (kg m/s)" would not fit a column.
    for (std::size_t k = 0; k < columns.size(); ++k)
        ImGui::TableSetupColumn(columns[k].name, ImGuiTableColumnFlags_WidthFixed, widths[k]);
    ImGui::TableHeadersRow();
    // The frozen "#" column is opaque: scrolled sideways, the numbers slid under it and showed
    // through. Its cells take the row's stripe over the window's background, at full alpha.
    int row = 0;
    const auto frozenCell = [&row, &style] {
        const ImVec4 stripe =
            style.Colors[row % 2 == 1 ? ImGuiCol_TableRowBgAlt : ImGuiCol_TableRowBg];
        ImGui::TableSetBgColor(
            ImGuiTableBgTarget_CellBg,
            ImGui::GetColorU32(widgets::opaqueOver(style.Colors[ImGuiCol_WindowBg], stripe)));
        ++row;
    };
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    frozenCell();
    for (const ValuesColumn& c : columns) {
        ImGui::TableNextColumn();
        ImGui::TextDisabled("%s", c.unit);
        mark(std::string("values unit ") + c.name);
    }
    const auto selectedId = s.selection().id();
    bool editingSeen = false;
    for (const ValuesRow& r : t.rows) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        frozenCell();
        const std::string number = std::to_string(r.number);
        if (ImGui::Selectable(number.c_str(), selectedId && *selectedId == r.id)) {
            out_.emplace_back(cmd::Select{r.id});
        }
        mark("values row " + number);
        for (std::size_t k = 0; k < columns.size(); ++k) {
            ImGui::TableNextColumn();
            if (!columns[k].field) {
                ImGui::TextUnformatted(valuesCell(r.values[k]).c_str());
                mark("values " + number + " " + columns[k].name);
                continue;
            }
            const ParticleField field = *columns[k].field;
            const bool editing =
                valuesEditing_ && valuesEditing_->first == r.id && valuesEditing_->second == field;
            std::array<char, 64> shownText = fieldText(r.values[k]);
            std::array<char, 64>& text = editing ? valuesText_ : shownText;
            ImGui::SetNextItemWidth(-FLT_MIN);
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
    frozenCell();
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
    ImGui::PopStyleVar(2);
    ImGui::End();
}

}  // namespace psb::app
