#pragma once
// Small widgets the control panel's sections share: text wrapped at spaces, a tooltip on the
// last item, sliders whose value reads over their handle (a double's reporting whether this
// change continues a drag), and a
// two-column row of a readout.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

#include <imgui.h>

#include "gui/slider.hpp"
#include "gui/tooltips.hpp"
#include "session/view_options.hpp"
#include "view/palette.hpp"
#include "view/word_wrap.hpp"

namespace psb::app::widgets {

/// The width of a checkbox or radio button labelled `label`, points.
[[nodiscard]] inline float checkWidth(const char* label) {
    return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x +
           ImGui::CalcTextSize(label, nullptr, true).x;
}

/// The width of a button labelled `label`, points.
[[nodiscard]] inline float buttonWidth(const char* label) {
    return ImGui::CalcTextSize(label, nullptr, true).x + 2.f * ImGui::GetStyle().FramePadding.x;
}

/// ImGui::SameLine(0, `spacing`) where the next item, `width` points wide, fits whole before
/// the panel's edge; else the item starts the next line (the panel narrows with the window:
/// kControlsMinWidth).
inline void sameLineIfRoom(float width, float spacing = -1.f) {
    const float right = ImGui::GetWindowContentRegionMax().x;
    ImGui::SameLine(0.f, spacing);
    if (ImGui::GetCursorPosX() + width > right) ImGui::NewLine();
}

/// Puts the next item, `width` points wide, on the line of the item before, at `column` (points
/// from the window's left, as ImGui::SameLine's) where it fits there whole, clear of the item
/// before and of the panel's edge (where the panel clips, half its padding right of the
/// content); else just after the item before, where it fits; else at the start of the next
/// line. A row of check boxes at fixed fractions of the panel drew the next box over the end
/// of a long label at 200 % ("Velocity arro", "Labe"); now the row wraps.
inline void besideIfRoom(float column, float width) {
    const float right =
        ImGui::GetWindowContentRegionMax().x + ImGui::GetStyle().WindowPadding.x / 2.f;
    ImGui::SameLine();
    const float after = ImGui::GetCursorPosX();
    if (column >= after && column + width <= right) {
        ImGui::SameLine(column);
    } else if (after + width > right) {
        ImGui::NewLine();
    }
}

/// A field's width: `most` points, less where its label `label` beside it would run past the
/// panel's edge.
[[nodiscard]] inline float fieldWidth(float most, const char* label) {
    const float room = ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemInnerSpacing.x -
                       ImGui::CalcTextSize(label, nullptr, true).x;
    return std::max(40.f, std::min(most, room));
}

/// `text` wrapped at spaces (never inside "9.81") to `width` points, or to the room left in
/// the window when `width` is 0, in the current text colour; one item (for a tooltip) however
/// many lines it takes.
inline void wrapped(std::string_view text, float width = 0.f) {
    if (!(width > 0.f)) width = ImGui::GetContentRegionAvail().x;
    const MeasureText measure = [](std::string_view t) {
        return ImGui::CalcTextSize(t.data(), t.data() + t.size()).x;
    };
    ImGui::BeginGroup();
    for (const std::string& line : wrapAtSpaces(text, width, measure))
        ImGui::TextUnformatted(line.c_str(), line.c_str() + line.size());
    ImGui::EndGroup();
}

/// `c` as ImGui's colour.
[[nodiscard]] inline ImVec4 colour(Rgba c) {
    return {c.r / 255.f, c.g / 255.f, c.b / 255.f, c.a / 255.f};
}
/// The theme's amber for notes and red for problems, as ImGui's colours.
/// `over` laid over `under` (each with its alpha), opaque: a frozen column's cells in a table
/// that scrolls sideways, which the scrolled cells' numbers must not show through.
[[nodiscard]] inline ImVec4 opaqueOver(const ImVec4& under, const ImVec4& over) {
    const auto mix = [&](float a, float b) { return a * (1.f - over.w) + b * over.w; };
    return {mix(under.x, over.x), mix(under.y, over.y), mix(under.z, over.z), 1.f};
}

[[nodiscard]] inline ImVec4 caution(Theme theme) {
    return colour(palette(theme).caution);
}
[[nodiscard]] inline ImVec4 problem(Theme theme) {
    return colour(palette(theme).warning);
}

/// wrapped() in the colour of greyed-out text.
inline void wrappedDisabled(std::string_view text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    wrapped(text);
    ImGui::PopStyleColor();
}
/// wrapped() in `color`.
inline void wrappedColored(const ImVec4& color, std::string_view text) {
    ImGui::PushStyleColor(ImGuiCol_Text, color);
    wrapped(text);
    ImGui::PopStyleColor();
}

/// A button whose words change with the state it switches ("Play" / "Pause"). ImGui knows an
/// item by its label: with new words it would be a new item, and the keyboard's cursor, left on
/// the old one, would be on nothing (a second Space did nothing). Its identity is `id` instead.
inline bool stateButton(const char* id, const char* words, const ImVec2& size = ImVec2(0.f, 0.f)) {
    const std::string label = std::string(words) + "###" + id;
    return ImGui::Button(label.c_str(), size);
}
/// A small button (no frame padding above and below its words), except on a touch screen
/// (`touchWidth` > 0), where it is a finger's target: as tall as any other button and at least
/// `touchWidth` points wide.
inline bool smallButton(const char* label, float touchWidth = 0.f) {
    if (!(touchWidth > 0.f)) return ImGui::SmallButton(label);
    const float words = ImGui::CalcTextSize(label, nullptr, true).x;
    return ImGui::Button(
        label, ImVec2(std::max(touchWidth, words + 2.f * ImGui::GetStyle().FramePadding.x), 0.f));
}
/// stateButton() as a small button.
inline bool smallStateButton(const char* id, const char* words, float touchWidth = 0.f) {
    const std::string label = std::string(words) + "###" + id;
    return smallButton(label.c_str(), touchWidth);
}

/// A tooltip for the item just drawn (also while it is disabled), after a real hover
/// (tooltips.hpp): never for a finger, nor while a control is held or a field typed in.
inline void tip(const char* text) {
    if (!ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) return;
    const float wrapWidth = ImGui::GetFontSize() * 22.f;
    if (auto* state = static_cast<TooltipState*>(ImGui::GetIO().UserData)) {
        if (!state->show(text) || ImGui::IsAnyItemActive() || ImGui::GetIO().WantTextInput) return;
        state->shown = text;
        if (!state->avoid.empty()) {
            const ImGuiIO& io = ImGui::GetIO();
            const ImVec2 pad = ImGui::GetStyle().WindowPadding;
            const ImVec2 text_size = ImGui::CalcTextSize(text, nullptr, false, wrapWidth);
            const TipRect at = tooltipPosition(io.MousePos.x, io.MousePos.y,
                                               text_size.x + 2.f * pad.x, text_size.y + 2.f * pad.y,
                                               io.DisplaySize.x, io.DisplaySize.y, state->avoid);
            ImGui::SetNextWindowPos(ImVec2(at.x, at.y));
        }
    }
    ImGui::BeginTooltip();
    wrapped(text, wrapWidth);
    ImGui::EndTooltip();
}

/// Tells GuiContext that the pointer is over the slider just drawn (panel_touch.hpp).
inline void markSliderHovered() {
    if (!ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) return;
    if (auto* state = static_cast<TooltipState*>(ImGui::GetIO().UserData)) {
        state->sliderHovered = true;
    }
}

/// A slider of `value` in [lo, hi]; true when the user changed it, with `continues` set when
/// the change is part of a drag that started in an earlier frame (one user action per drag).
/// Its value reads wherever its handle is (slider.hpp).
/// Narrows the next item, a slider or field labelled `label`, where its label beside it would
/// run past the panel's edge (a panel narrowed to its share of the window cut "Restitution").
inline void keepLabelInside(const char* label) {
    const float text = ImGui::CalcTextSize(label, nullptr, true).x;
    if (!(text > 0.f)) return;
    const float room =
        ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemInnerSpacing.x - text;
    if (ImGui::CalcItemWidth() > room) ImGui::SetNextItemWidth(std::max(40.f, room));
}

inline bool slider(const char* label, double& value, double lo, double hi, const char* format,
                   bool& continues, ImGuiSliderFlags flags = 0) {
    keepLabelInside(label);
    const float width = ImGui::CalcItemWidth();
    bool changed = false;
    {
        const SliderHandleStyle narrow;
        changed = ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &lo, &hi, format, flags);
    }
    markSliderHovered();
    continues = !ImGui::IsItemActivated();
    std::array<char, 64> text{};
    std::snprintf(text.data(), text.size(), format, value);
    const bool logarithmic = (flags & ImGuiSliderFlags_Logarithmic) != 0 && lo > 0.0;
    const double fraction =
        logarithmic ? std::log(value / lo) / std::log(hi / lo) : (value - lo) / (hi - lo);
    valueBesideHandle(text.data(), width, static_cast<float>(fraction));
    return changed;
}

/// A slider of a whole number `value` in [lo, hi], as ImGui::SliderInt, its value reading
/// wherever its handle is (slider.hpp).
inline bool sliderInt(const char* label, int& value, int lo, int hi, const char* format = "%d",
                      ImGuiSliderFlags flags = 0) {
    keepLabelInside(label);
    const float width = ImGui::CalcItemWidth();
    bool changed = false;
    {
        const SliderHandleStyle narrow;
        changed = ImGui::SliderInt(label, &value, lo, hi, format, flags);
    }
    markSliderHovered();
    std::array<char, 64> text{};
    std::snprintf(text.data(), text.size(), format, value);
    valueBesideHandle(text.data(), width,
                      hi > lo ? static_cast<float>(value - lo) / static_cast<float>(hi - lo) : 0.f);
    return changed;
}

/// Starts a table of "name   value" rows: the names' column as wide as its widest name, the
/// values' column the rest, their text wrapped at spaces within it, so that a name and its
/// value never overlap, whatever the panel's width. With `names` > 0 the names' column is
/// that wide and a longer name wraps in it (rowNames gives the width that leaves the values
/// their room). End it with ImGui::EndTable().
inline bool beginRows(const char* id, float names = 0.f) {
    if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_SizingFixedFit)) return false;
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed, std::max(0.f, names));
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
    return true;
}

/// The names' column for beginRows: as wide as the widest of `names`, but no more than 45 % of
/// the room, so that a value keeps room for a line of its own (at 200 % "Pressure, measured"
/// left "12.2 N/m \u00b1 0.362 N/m" a third of the panel, over three lines).
template <typename Names>
[[nodiscard]] float rowNames(const Names& names) {
    float widest = 0.f;
    for (const auto& n : names)
        widest = std::max(
            widest, ImGui::CalcTextSize(std::string_view(n).data(),
                                        std::string_view(n).data() + std::string_view(n).size())
                        .x);
    return std::ceil(std::min(widest, 0.45f * ImGui::GetContentRegionAvail().x));
}

/// Where a row's name and value were drawn, window points.
struct RowRects {
    ImVec2 name0, name1, value0, value1;
};

/// "name   value" in a row of a beginRows() table; the name wrapped at spaces within its
/// column when `wrapName` (a table whose names' column has a width: beginRows(id, names)).
inline RowRects row(const char* name, const std::string& value, const char* help = nullptr,
                    bool wrapName = false) {
    RowRects r;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    if (wrapName) {
        wrapped(name);
    } else {
        ImGui::TextUnformatted(name);
    }
    r.name0 = ImGui::GetItemRectMin();
    r.name1 = ImGui::GetItemRectMax();
    if (help != nullptr) tip(help);
    ImGui::TableNextColumn();
    wrapped(value);
    r.value0 = ImGui::GetItemRectMin();
    r.value1 = ImGui::GetItemRectMax();
    if (help != nullptr) tip(help);
    return r;
}

}  // namespace psb::app::widgets
