#pragma once
// The system clipboard: the session makes the text (Session::takeClipboardText), the app hands
// it over here, the one place that calls SDL's clipboard, and tells the session what became of
// it (cmd::ClipboardResult), so that "Copied" is said only of text that is on the clipboard.
//
// In a web page SDL's clipboard is the program's own (nothing reaches the system's), so the
// page copies instead (web/index.html, psbCopy): the browser's clipboard API, within the
// user's gesture (the press of Copy, a frame ago), or a selected text copied the older way when
// the API is missing or refuses. The browser answers later: psb_web_copied() posts an SDL event
// that clipboardResult() reads.

#include <optional>
#include <string>

#include <SDL.h>

#include "session/command.hpp"

namespace psb::app {

/// Puts `text` on the clipboard: what became of it, or nullopt in a page, whose answer comes
/// later as an SDL event (clipboardResult).
[[nodiscard]] std::optional<cmd::ClipboardResult> putOnClipboard(const std::string& text);

/// The page's answer to putOnClipboard, if `e` is one (its text freed); nullopt otherwise.
[[nodiscard]] std::optional<cmd::ClipboardResult> clipboardResult(const SDL_Event& e);

/// The clipboard's text now (empty when it holds none).
[[nodiscard]] std::string clipboardText();

}  // namespace psb::app
