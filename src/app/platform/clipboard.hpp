#pragma once
// The system clipboard: the session makes the text (Session::takeClipboardText), the app hands
// it over here, the one place that calls SDL's clipboard.

#include <optional>
#include <string>

namespace psb::app {

/// Puts `text` on the clipboard. Returns why it could not (SDL's error), or nullopt.
[[nodiscard]] std::optional<std::string> putOnClipboard(const std::string& text);

/// The clipboard's text now (empty when it holds none).
[[nodiscard]] std::string clipboardText();

}  // namespace psb::app
