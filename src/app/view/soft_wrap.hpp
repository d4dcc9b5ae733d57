#pragma once
// A text being typed, wrapped in a field that does not wrap (Dear ImGui 1.86's multi-line field
// scrolls a long line sideways: the start of a description went off the field's left edge).
// The spaces where the lines break become '\n', "soft" breaks: the text keeps its length, so the
// cursor and the selection stay on the same characters, and the breaks the user typed
// (Ctrl+Enter) stay theirs. text() gives the text back with its soft breaks spaces again.
//
//   start(text)      the text as the field first shows it, wrapped
//   edited(shown)    after each change the field makes: the soft breaks followed through it
//                    (those outside the change stay, those it touched go) and the text wrapped
//                    again in place
//   text(shown)      what was typed, for the scene

#include <string>
#include <vector>

#include "view/word_wrap.hpp"

namespace psb::app {

class SoftWrap {
  public:
    /// `text` (no soft breaks) wrapped within `room` by `measure`: what the field starts with.
    [[nodiscard]] std::string start(const std::string& text, float room,
                                    const MeasureText& measure);
    /// The field's text after a change: wrapped again within `room`, in place (same length).
    /// Returns whether a character changed.
    bool edited(std::string& shown, float room, const MeasureText& measure);
    /// `shown` (the field's text) with its soft breaks spaces again.
    [[nodiscard]] std::string text(const std::string& shown) const;

  private:
    /// Breaks the lines of `shown_` (no soft breaks in it) within `room`, marking them in soft_.
    void wrap(float room, const MeasureText& measure);

    std::string shown_;       // the field's text as last wrapped
    std::vector<bool> soft_;  // for each byte of shown_: a soft break
};

}  // namespace psb::app
