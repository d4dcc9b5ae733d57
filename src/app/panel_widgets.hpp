#pragma once
// Small widgets the control panel's sections share: a tooltip on the last item, a slider of a
// double that reports whether this change continues a drag, and a two-column row of a readout.

#include <string>

#include <imgui.h>

namespace psb::app::widgets {

/// A tooltip for the item just drawn (also while it is disabled).
inline void tip(const char* text) {
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 22.f);
        ImGui::TextUnformatted(text);
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}

/// A slider of `value` in [lo, hi]; true when the user changed it, with `continues` set when
/// the change is part of a drag that started in an earlier frame (one user action per drag).
inline bool slider(const char* label, double& value, double lo, double hi, const char* format,
                   bool& continues, ImGuiSliderFlags flags = 0) {
    const bool changed =
        ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &lo, &hi, format, flags);
    continues = !ImGui::IsItemActivated();
    return changed;
}

/// "name   value" in a two-column table row.
inline void row(const char* name, const std::string& value, const char* help = nullptr) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(name);
    if (help != nullptr) tip(help);
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(value.c_str());
    if (help != nullptr) tip(help);
}

}  // namespace psb::app::widgets
