#pragma once
// A slider whose value reads wherever its handle is. ImGui writes a slider's value centred over
// it and draws its handle, as wide as a digit, under the text: in the middle of its range
// (Roughness 0 of -1 to 1) the handle sat on a digit, "0.▮00" from the back of a room. A narrow
// bar passing under the digits still read "0.0|0" and "200|%" at 200 %. Here the handle is a
// narrow bar in the text's colour, and the value is written beside it, never across it: centred
// when the handle is clear of it, else centred in the wider part of the slider beside the handle
// (ImGui's own writing is hidden under a patch of the slider's colour).

#include <imgui.h>

namespace psb::app::widgets {

/// The handle's width, points.
inline constexpr float kSliderHandleWidth = 4.f;

/// The narrow handle's style, for the slider drawn while it lives.
class SliderHandleStyle {
  public:
    SliderHandleStyle();
    ~SliderHandleStyle();
    SliderHandleStyle(const SliderHandleStyle&) = delete;
    SliderHandleStyle& operator=(const SliderHandleStyle&) = delete;
};

/// The left edge of a value `textWidth` wide in a slider's frame [frame0, frame1] whose handle
/// spans [handle0, handle1] (points): centred when it keeps `gap` from the handle, else centred
/// in the wider part beside the handle, kept `gap` from it and inside the frame, half a `gap`
/// from the frame's edge where the part has the room ("200 %" touched the UI scale's frame).
[[nodiscard]] float sliderValueX(float frame0, float frame1, float handle0, float handle1,
                                 float textWidth, float gap);

/// Writes `text`, the value of the slider just drawn with a frame `width` points wide whose
/// handle is at `fraction` (0 to 1) of its range, beside the handle, hiding ImGui's writing
/// under a patch of the slider's colour, and draws the handle (nothing while it is typed in).
void valueBesideHandle(const char* text, float width, float fraction);

}  // namespace psb::app::widgets
