#pragma once
// A slider whose value reads wherever its handle is. ImGui writes a slider's value centred over
// it and draws its handle, as wide as a digit, under the text: in the middle of its range
// (Roughness 0 of -1 to 1) the handle sat on a digit, "0.▮00" from the back of a room. Here the
// handle is a narrow bar in the text's colour, and the value is written again over a patch of
// the slider's own colour as tall as its digits: the bar passes under the digits and shows above
// and below them, and the digits read the same wherever it is.

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

/// Writes `text`, the value of the slider just drawn with a frame `width` points wide, over a
/// patch of the slider's colour where ImGui wrote it (nothing while the slider is typed in).
void valueOverHandle(const char* text, float width);

}  // namespace psb::app::widgets
