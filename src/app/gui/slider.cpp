#include "gui/slider.hpp"

#include <algorithm>
#include <cmath>

#include <imgui_internal.h>

namespace psb::app::widgets {

namespace {

/// The handle's colour: a bar in the text's colour, bold enough to find (the theme's handle is
/// a faint one, for digits written over it).
ImVec4 handleColour(bool active) {
    ImVec4 bar = ImGui::GetStyleColorVec4(ImGuiCol_Text);
    bar.w = active ? 0.85f : 0.6f;
    return bar;
}

/// ImGui's room either side of a slider's handle, points (imgui_widgets.cpp, SliderBehaviorT).
constexpr float kGrabPadding = 2.f;

}  // namespace

SliderHandleStyle::SliderHandleStyle() {
    // ImGui's handle is hidden: valueBesideHandle draws it, after the patch over ImGui's
    // writing of the value. Its width still sets where ImGui takes the pointer.
    ImGui::PushStyleColor(ImGuiCol_SliderGrab, ImVec4(0.f, 0.f, 0.f, 0.f));
    ImGui::PushStyleColor(ImGuiCol_SliderGrabActive, ImVec4(0.f, 0.f, 0.f, 0.f));
    ImGui::PushStyleVar(ImGuiStyleVar_GrabMinSize, kSliderHandleWidth);
}

SliderHandleStyle::~SliderHandleStyle() {
    ImGui::PopStyleVar();
    ImGui::PopStyleColor(2);
}

float sliderValueX(float frame0, float frame1, float handle0, float handle1, float textWidth,
                   float gap) {
    const float centred = frame0 + (frame1 - frame0 - textWidth) * 0.5f;
    if (centred + textWidth + gap <= handle0 || centred >= handle1 + gap) return centred;
    const float leftRoom = handle0 - frame0, rightRoom = frame1 - handle1;
    const float edge = 0.5f * gap;
    if (leftRoom >= rightRoom) {
        // Centred in [frame0, handle0 - gap], never closer to the handle than gap, nor to the
        // frame's edge than half of it where there is the room.
        const float x = frame0 + (leftRoom - gap - textWidth) * 0.5f;
        const float least = std::min(frame0 + edge, handle0 - gap - textWidth);
        return std::max({frame0, least, std::min(x, handle0 - gap - textWidth)});
    }
    const float x = handle1 + gap + (rightRoom - gap - textWidth) * 0.5f;
    const float most = std::max(handle1 + gap, frame1 - edge - textWidth);
    return std::min(
        {std::max(x, handle1 + gap), most, std::max(handle1 + gap, frame1 - textWidth)});
}

void valueBesideHandle(const char* text, float width, float fraction) {
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    const ImGuiID id = ImGui::GetItemID();
    if (ImGui::TempInputIsActive(id)) return;  // a field, being typed in
    const ImVec2 min = ImGui::GetItemRectMin();
    const ImRect frame(min, ImVec2(min.x + width, min.y + ImGui::GetFrameHeight()));
    // Where ImGui centred it (RenderTextClipped): hidden under a patch of the slider's colour.
    const ImVec2 size = ImGui::CalcTextSize(text);
    const ImVec2 at(std::max(frame.Min.x, frame.Min.x + (frame.GetWidth() - size.x) * 0.5f),
                    std::max(frame.Min.y, frame.Min.y + (frame.GetHeight() - size.y) * 0.5f));
    const float border = g.Style.FrameBorderSize;
    ImRect patch(ImVec2(at.x - 1.f, at.y), ImVec2(at.x + size.x + 1.f, at.y + size.y));
    patch.ClipWith(ImRect(frame.Min.x + border, frame.Min.y + border, frame.Max.x - border,
                          frame.Max.y - border));
    // The slider's colour as ImGui filled it (faded while disabled) over the window's
    // background, made opaque.
    const ImGuiCol fill = g.ActiveId == id    ? ImGuiCol_FrameBgActive
                          : g.HoveredId == id ? ImGuiCol_FrameBgHovered
                                              : ImGuiCol_FrameBg;
    const ImVec4 f = ImGui::GetStyleColorVec4(fill);
    const ImVec4 back = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
    const float a = f.w * g.Style.Alpha;
    const auto mix = [a](float over, float under) { return a * over + (1.f - a) * under; };
    const ImVec4 opaque(mix(f.x, back.x), mix(f.y, back.y), mix(f.z, back.z), 1.f);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(patch.Min, patch.Max, ImGui::ColorConvertFloat4ToU32(opaque));
    // The handle where ImGui has it: a bar of kSliderHandleWidth over the usable width.
    const float t = std::clamp(std::isfinite(fraction) ? fraction : 0.f, 0.f, 1.f);
    const float usable = frame.GetWidth() - 2.f * kGrabPadding - kSliderHandleWidth;
    const float h0 = frame.Min.x + kGrabPadding + t * std::max(usable, 0.f);
    const float h1 = h0 + kSliderHandleWidth;
    draw->AddRectFilled(ImVec2(h0, frame.Min.y + kGrabPadding),
                        ImVec2(h1, frame.Max.y - kGrabPadding),
                        ImGui::GetColorU32(handleColour(g.ActiveId == id)), g.Style.GrabRounding);
    // The value beside it, a third of a line away.
    const float x =
        sliderValueX(frame.Min.x + border, frame.Max.x - border, h0, h1, size.x, 0.3f * g.FontSize);
    draw->PushClipRect(frame.Min, frame.Max, true);
    draw->AddText(ImVec2(x, at.y), ImGui::GetColorU32(ImGuiCol_Text), text);
    draw->PopClipRect();
}

}  // namespace psb::app::widgets
