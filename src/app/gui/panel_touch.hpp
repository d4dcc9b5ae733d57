#pragma once
// A finger on the control panel. Dear ImGui 1.86 knows only a mouse: a finger that came down on
// the panel pressed whatever was under it at once, so a drag up the panel dragged that control
// (or nothing) and the panel scrolled only by its thin scrollbar. A touch page scrolls under a
// finger, so the press is held back until the finger says what it means:
//
//   moved up or down (more than across) by kSlop     ─► a scroll: the window under the finger
//                                                       follows it, nothing is pressed, and it
//                                                       coasts on a little after the lift
//   moved across by kSlop, or held still kHoldSeconds ─► pressed where it came down, then it
//                                                       follows the finger (a slider drags)
//   lifted before either                              ─► a tap: pressed and released where it
//                                                       came down
//
// A slider under the finger (the frames that show the finger's hover say so: sliderUnder) is
// pressed only by a drag across it: a tap or a finger held still on it presses nothing (ImGui
// would set the value to where it came down), so a finger that rests on a slider before it
// scrolls the panel changes nothing. A tap lifted before any frame showed its hover is shown
// hovered for one frame first, to learn what is under it. A second finger on the panel ends
// the gesture (cancel): nothing is pressed or scrolled by it, and the first finger's events
// stay the gesture's, doing nothing, until it lifts.
//
// After the lift ImGui sees no pointer at all: no hover, tooltip or highlight stays where the
// finger was. The gesture is plain state over positions (window points) and times (seconds);
// GuiContext feeds it the mouse events SDL makes of a finger and gives ImGui what frame() says.

#include <optional>

#include <imgui.h>

namespace psb::app {

class PanelTouch {
  public:
    /// How far a finger moves, window points, before it is a scroll or a drag (a resting
    /// finger wobbles by a few).
    static constexpr float kSlop = 8.f;
    /// A finger held this long without moving presses (a long press, for a held button).
    static constexpr double kHoldSeconds = 0.4;
    /// How quickly a scroll's coasting after the lift dies away, seconds.
    static constexpr double kCoastSeconds = 0.25;

    /// What ImGui sees in a frame while a finger is (or just was) on the panel.
    struct Pointer {
        std::optional<ImVec2> at;  ///< where the pointer is; none after the lift and in a scroll
        bool down = false;         ///< the left button
        float scroll = 0.f;        ///< window points to scroll the window under `scrollFrom`
        ImVec2 scrollFrom;         ///< where the finger came down
    };

    void down(ImVec2 at, double seconds);
    void move(ImVec2 at, double seconds);
    void up(ImVec2 at, double seconds);
    /// A second finger came down: the gesture does nothing more (see the top of this file).
    void cancel();
    /// What the last frame showed under the finger's hover: a slider or not. Call before
    /// frame(); read while the finger has not pressed.
    void sliderUnder(bool slider);
    /// A finger on the panel is down now: its mouse events are the gesture's.
    [[nodiscard]] bool fingerDown() const {
        return phase_ == Phase::Waiting || phase_ == Phase::Pressing ||
               phase_ == Phase::Scrolling || phase_ == Phase::Cancelled;
    }
    /// A finger on the panel whose gesture is not done: down, or lifted from a tap or a press
    /// whose release ImGui has not seen yet (read after frame(): the frame of the release too).
    [[nodiscard]] bool held() const {
        return fingerDown() || phase_ == Phase::Releasing || phase_ == Phase::Lifted;
    }
    /// What ImGui sees in the frame that starts at `seconds`, or nothing when no finger is on
    /// the panel (the mouse is ImGui's as usual).
    [[nodiscard]] std::optional<Pointer> frame(double seconds);

  private:
    enum class Phase { None, Waiting, Pressing, Scrolling, Releasing, Coasting, Cancelled, Lifted };

    Phase phase_ = Phase::None;
    ImVec2 origin_, last_;
    double downAt_ = 0.0, lastAt_ = 0.0, frameAt_ = 0.0;
    bool pressShown_ = false;  ///< ImGui has seen the button down in a frame
    int hoverFrames_ = 0;      ///< frames that showed the finger's hover where it came down
    bool overSlider_ = false;  ///< a slider is under the finger (from those frames)
    float pendingScroll_ = 0.f;
    float velocity_ = 0.f;  ///< the scroll's, window points a second
};

/// Scrolls the window at `at` (window points; ImGui's points are these over `scale`) by `by`
/// window points, positive: the content moves up. A window that cannot move that way any more
/// (a list at its end) passes the scroll to the window around it, as nested lists do on a touch
/// page. Call between ImGui frames.
void scrollWindowAt(ImVec2 at, float by, float scale);

}  // namespace psb::app
