#pragma once
// When the panel's tooltips show. ImGui 1.86 shows a tooltip the frame a control is hovered,
// for as long as the pointer rests there: a finger's tap left one standing over the controls
// below it (the pointer SDL makes of a finger stays where it lifted), and one popped over the
// particle's fields while a value was typed in. A tooltip here waits for a real hover:
//
//   - a mouse (never a finger) resting on the same control for kDelaySeconds;
//   - the pointer moved since that control came under it: a control that comes under a still
//     pointer (a key moved the panel's layout or its keyboard cursor: ImGui counts the control
//     the keyboard is on as hovered) waits for the pointer to move (after Space on the panel,
//     Play's tooltip stood at the pointer, over the values table's totals);
//   - nothing held or typed in: no control active, no field taking text.
//
// GuiContext owns the state and opens each frame with startFrame; widgets::tip reads it
// through ImGui's io.UserData (null: every hover shows its tooltip, as ImGui does, for panels
// built without a GuiContext). What was shown is kept for --log-controls. The same state carries
// the one other thing a widget tells GuiContext about the pointer: a slider is under it (a
// finger on the panel presses a slider only by a drag across it, panel_touch.hpp).
//
// A tooltip never covers the message line (what the program just said, at the bottom right of
// the panel): where ImGui would put it over that band, tooltipPosition moves it above the band
// (or below, where above has no room).

#include <algorithm>
#include <string>

namespace psb::app {

/// A rectangle in the panel's points (ImGui's coordinates): x, y its top-left corner.
struct TipRect {
    float x = 0.f, y = 0.f, w = 0.f, h = 0.f;
    [[nodiscard]] bool empty() const { return w <= 0.f || h <= 0.f; }
    [[nodiscard]] bool overlaps(const TipRect& o) const {
        return !empty() && !o.empty() && x < o.x + o.w && o.x < x + w && y < o.y + o.h &&
               o.y < y + h;
    }
};

/// Where a tooltip of `width` × `height` points goes for a pointer at (mouseX, mouseY) in a
/// display `displayW` × `displayH`: right of and below the pointer as ImGui puts it (above it
/// where below has no room), kept on the display, and off `avoid` (the message band): moved
/// above the band, or below it where above has no room.
[[nodiscard]] inline TipRect tooltipPosition(float mouseX, float mouseY, float width, float height,
                                             float displayW, float displayH, const TipRect& avoid) {
    constexpr float kOffsetX = 16.f, kOffsetY = 10.f;
    TipRect r{mouseX + kOffsetX, mouseY + kOffsetY, width, height};
    if (r.y + height > displayH) r.y = mouseY - kOffsetY - height;
    r.x = std::clamp(r.x, 0.f, std::max(0.f, displayW - width));
    r.y = std::clamp(r.y, 0.f, std::max(0.f, displayH - height));
    if (r.overlaps(avoid)) {
        const float above = avoid.y - height - 1.f;
        r.y = above >= 0.f ? above : std::min(avoid.y + avoid.h + 1.f, displayH - height);
    }
    return r;
}

struct TooltipState {
    static constexpr double kDelaySeconds = 0.5;

    bool allowed = true;  ///< this frame's pointer may show tooltips (a mouse)
    double now = 0.0;     ///< seconds
    std::string hovered;  ///< the tip of the control hovered, and since when
    double since = 0.0;
    /// The pointer moved since `hovered` came under it: a real hover, not a control brought
    /// under a still pointer.
    bool reached = false;
    bool hoveredThisFrame = false;
    float pointerX = 0.f, pointerY = 0.f;  ///< where the pointer was last frame
    bool moved = false;                    ///< it moved since the last frame
    std::string shown;                     ///< the tooltip shown this frame (empty: none)
    TipRect avoid;               ///< the message band, in the panel's points (empty: none)
    bool sliderHovered = false;  ///< a slider was hovered in the frame (widgets::slider)

    /// A frame at `seconds` with the pointer at (x, y), the panel's points (no pointer: far
    /// off, as ImGui has it).
    void startFrame(double seconds, bool pointerIsMouse, float x, float y) {
        sliderHovered = false;
        if (!hoveredThisFrame) hovered.clear();
        hoveredThisFrame = false;
        shown.clear();
        now = seconds;
        allowed = pointerIsMouse;
        moved = x != pointerX || y != pointerY;
        pointerX = x;
        pointerY = y;
    }
    /// Whether the control with tip `text`, hovered now, shows it.
    [[nodiscard]] bool show(const char* text) {
        hoveredThisFrame = true;
        if (hovered != text) {
            hovered = text;
            since = now;
            reached = moved;
        } else if (!reached && moved) {
            // The pointer moves on it: from now on a real hover.
            reached = true;
            since = now;
        }
        return allowed && reached && now - since >= kDelaySeconds;
    }
};

}  // namespace psb::app
