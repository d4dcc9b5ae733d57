#include "gui/slider.hpp"

#include <algorithm>

#include <imgui_internal.h>

namespace psb::app::widgets {

SliderHandleStyle::SliderHandleStyle() {
    // A bar in the text's colour, bold enough to find (the theme's handle is a faint one, for
    // digits written over it).
    ImVec4 bar = ImGui::GetStyleColorVec4(ImGuiCol_Text);
    bar.w = 0.6f;
    ImGui::PushStyleColor(ImGuiCol_SliderGrab, bar);
    bar.w = 0.85f;
    ImGui::PushStyleColor(ImGuiCol_SliderGrabActive, bar);
    ImGui::PushStyleVar(ImGuiStyleVar_GrabMinSize, kSliderHandleWidth);
}

SliderHandleStyle::~SliderHandleStyle() {
    ImGui::PopStyleVar();
    ImGui::PopStyleColor(2);
}

void valueOverHandle(const char* text, float width) {
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    const ImGuiID id = ImGui::GetItemID();
    if (ImGui::TempInputIsActive(id)) return;  // a field, being typed in
    const ImVec2 min = ImGui::GetItemRectMin();
    const ImRect frame(min, ImVec2(min.x + width, min.y + ImGui::GetFrameHeight()));
    // Where ImGui centred it (RenderTextClipped), so that the two writings coincide.
    const ImVec2 size = ImGui::CalcTextSize(text);
    const ImVec2 at(std::max(frame.Min.x, frame.Min.x + (frame.GetWidth() - size.x) * 0.5f),
                    std::max(frame.Min.y, frame.Min.y + (frame.GetHeight() - size.y) * 0.5f));
    // The patch spans the digits' height (a digit's glyph box, from the font), so the bar shows
    // above and below them, and a little beyond each end of the text.
    float top = at.y, bottom = at.y + size.y;
    if (const ImFontGlyph* digit = g.Font->FindGlyphNoFallback('0')) {
        const float scale = g.FontSize / g.Font->FontSize;
        top = at.y + digit->Y0 * scale - 1.f;
        bottom = at.y + digit->Y1 * scale + 1.f;
    }
    const float border = g.Style.FrameBorderSize;
    const float pad = 0.15f * g.FontSize;
    ImRect patch(ImVec2(at.x - pad, top), ImVec2(at.x + size.x + pad, bottom));
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
    draw->PushClipRect(frame.Min, frame.Max, true);
    draw->AddText(at, ImGui::GetColorU32(ImGuiCol_Text), text);
    draw->PopClipRect();
}

}  // namespace psb::app::widgets
