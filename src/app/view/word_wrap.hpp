#pragma once
// Breaking text into lines at spaces only. ImGui's own wrapping also breaks after punctuation,
// which splits numbers ("9. 81 m/s²"); the panel's tooltips and sentences, and the text panels
// beside the box, wrap here instead.

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace psb::app {

/// The width of a piece of text, in whatever unit the room is given in.
using MeasureText = std::function<float(std::string_view)>;

/// `text` in lines no wider than `room` by `measure`, broken only at spaces (and at '\n'); a
/// file's path (a word with two separators '/' or '\\') that does not fit after the words
/// before it, or any word wider than the room, is broken after a separator where one leaves a
/// piece that fits (the path goes on on the next line), else stands alone on its line,
/// unbroken. Lines after the first
/// of a paragraph start with `indent` in place of the spaces they were broken at.
[[nodiscard]] std::vector<std::string> wrapAtSpaces(std::string_view text, float room,
                                                    const MeasureText& measure,
                                                    std::string_view indent = "");

}  // namespace psb::app
