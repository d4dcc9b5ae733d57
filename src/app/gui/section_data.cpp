// The control panel's Data section: recording the particles' paths and collisions, and each
// table (values, time series, trajectories, collisions) exported to a CSV file or copied to the
// clipboard.

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>

#include <imgui.h>

#include "gui/control_panel.hpp"
#include "gui/widgets.hpp"
#include "session/session.hpp"

namespace psb::app {

using widgets::tip;

namespace {

struct TableRow {
    cmd::DataTable table;
    const char* label;
    const char* about;
};

constexpr std::array<TableRow, 4> kTables{{
    {cmd::DataTable::Values, "values",
     "Every particle now: number, x, y, vx, vy, px, py, kinetic energy, mass, radius (SI)"},
    {cmd::DataTable::TimeSeries, "time series",
     "What the plots (K) show, from the start of the run: time, kinetic energy, momentum, "
     "centre of mass, collisions and their rate"},
    {cmd::DataTable::Trajectories, "trajectories",
     "The recorded particles' t, x, y, vx, vy at every sample"},
    {cmd::DataTable::Collisions, "collisions",
     "Each collision of the recorded particles: time, who with, velocities before and after, "
     "impulse (N s)"},
}};

}  // namespace

void ControlPanel::data(const Session& s) {
    const bool open = ImGui::CollapsingHeader("Data");
    mark("section Data");
    if (!open) return;
    const DataRecorder& d = s.data();
    if (widgets::stateButton("Record", d.recording() ? "Stop recording" : "Record")) {
        out_.emplace_back(cmd::SetRecording{!d.recording(), recordEvery_});
    }
    mark("Record");
    tip("Record the selected particle's path and collisions (with none selected: every "
        "particle, up to 100), from now until stopped (key X)");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90.f);
    if (recordEvery_ == 0) recordEvery_ = d.every();
    ImGui::InputInt("steps", &recordEvery_);
    recordEvery_ = std::clamp(recordEvery_, 1, DataRecorder::kMaxEvery);
    mark("record every");
    tip("A trajectory sample every this many steps (1: every step)");
    const std::size_t particles = d.trajectory().ids().size();
    const std::size_t hits = d.collisions().size();
    const char* plural = hits == 1 ? "" : "s";
    if (d.recording()) {
        ImGui::TextColored(
            widgets::problem(s.view().theme), "REC %zu particle%s: %zu samples, %zu collision%s",
            particles, particles == 1 ? "" : "s", d.trajectory().samples().size(), hits, plural);
    } else if (!d.trajectory().samples().empty()) {
        ImGui::TextWrapped("Recorded %zu samples, %zu collision%s", d.trajectory().samples().size(),
                           hits, plural);
    }

    ImGui::TextUnformatted(s.inPage() ? "File name (downloaded)"
                                      : "File (in the screenshot folder)");
    ImGui::SetNextItemWidth(-1.f);
    ImGui::InputTextWithHint("##export", "empty: values.csv, ...", exportName_.data(),
                             exportName_.size());
    mark("export name");
    tip(s.inPage()
            ? "A file name for Export; empty: the table's own name. The browser downloads it"
            : ("A file name for Export; empty: the table's own name. A relative name goes into " +
               s.exportDir().string() + "; an existing file is kept and NAME-2.csv, ... written")
                  .c_str());
    for (const TableRow& row : kTables) {
        ImGui::PushID(row.label);
        if (ImGui::Button("Export")) {
            out_.emplace_back(
                cmd::ExportTable{row.table, std::filesystem::path(exportName_.data())});
        }
        mark(std::string("Export ") + row.label);
        tip("Write this table as CSV (comma-separated, a header naming each unit)");
        ImGui::SameLine();
        if (ImGui::Button("Copy")) out_.emplace_back(cmd::CopyTable{row.table});
        mark(std::string("Copy ") + row.label);
        tip("Copy this table to the clipboard, tab-separated: paste it into a spreadsheet");
        ImGui::SameLine();
        ImGui::TextUnformatted(row.label);
        tip(row.about);
        ImGui::PopID();
    }
    if (!s.exportError().empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, widgets::problem(s.view().theme));
        ImGui::TextWrapped("%s", s.exportError().c_str());
        ImGui::PopStyleColor();
    } else if (s.lastExport()) {
        // In a page the path is in the page's own memory: the download is what the user has.
        const std::string exported =
            s.inPage() ? "Exported " + s.lastExport()->filename().string() +
                             ", a download: in your downloads (or where the browser asked)"
                       : "Exported to " + s.lastExport()->string();
        widgets::wrapped(exported);
        mark("exported", exported);
    }
}

}  // namespace psb::app
