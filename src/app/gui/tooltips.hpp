#pragma once
// When the panel's tooltips show. ImGui 1.86 shows a tooltip the frame a control is hovered,
// for as long as the pointer rests there: a finger's tap left one standing over the controls
// below it (the pointer SDL makes of a finger stays where it lifted), and one popped over the
// particle's fields while a value was typed in. A tooltip here waits for a real hover:
//
//   - a mouse (never a finger) resting on the same control for kDelaySeconds;
//   - nothing held or typed in: no control active, no field taking text.
//
// GuiContext owns the state and opens each frame with startFrame; widgets::tip reads it
// through ImGui's io.UserData (null: every hover shows its tooltip, as ImGui does, for panels
// built without a GuiContext). What was shown is kept for --log-controls. The same state carries
// the one other thing a widget tells GuiContext about the pointer: a slider is under it (a
// finger on the panel presses a slider only by a drag across it, panel_touch.hpp).

#include <string>

namespace psb::app {

struct TooltipState {
    static constexpr double kDelaySeconds = 0.5;

    bool allowed = true;  ///< this frame's pointer may show tooltips (a mouse)
    double now = 0.0;     ///< seconds
    std::string hovered;  ///< the tip of the control hovered, and since when
    double since = 0.0;
    bool hoveredThisFrame = false;
    std::string shown;           ///< the tooltip shown this frame (empty: none)
    bool sliderHovered = false;  ///< a slider was hovered in the frame (widgets::slider)

    void startFrame(double seconds, bool pointerIsMouse) {
        sliderHovered = false;
        if (!hoveredThisFrame) hovered.clear();
        hoveredThisFrame = false;
        shown.clear();
        now = seconds;
        allowed = pointerIsMouse;
    }
    /// Whether the control with tip `text`, hovered now, shows it.
    [[nodiscard]] bool show(const char* text) {
        hoveredThisFrame = true;
        if (hovered != text) {
            hovered = text;
            since = now;
        }
        return allowed && now - since >= kDelaySeconds;
    }
};

}  // namespace psb::app
