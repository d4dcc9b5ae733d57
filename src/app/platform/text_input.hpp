#pragma once
// Typed text on or off: the one place that starts and stops SDL's text input. On a desktop that
// is all. In a web page SDL's text comes from the keys pressed while the page has the keyboard,
// and a touch device shows its on-screen keyboard only for a focused element that takes text:
// the canvas is none. So while a field takes text the page focuses its typing field
// (web/index.html, an invisible <input>), which brings the keyboard up; what is typed there comes
// back as SDL's text events (psb_web_type, psb_web_backspace below), and the keys of a real
// keyboard reach SDL as before.

namespace psb::app {

/// Starts (`on`) or stops SDL's text input, and in a page brings the on-screen keyboard up or
/// sends it away.
void setTextInput(bool on);

}  // namespace psb::app
