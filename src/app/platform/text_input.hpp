#pragma once
// Typed text on or off: the one place that starts and stops SDL's text input. On a desktop that
// is all. In a web page SDL's text comes from the keys pressed while the page has the keyboard,
// and a touch device shows its on-screen keyboard only for a focused element that takes text:
// the canvas is none. So while a field takes text the page focuses its typing field
// (web/index.html, an invisible <input>), which brings the keyboard up; what is typed there comes
// back as SDL's text events (psb_web_type, psb_web_backspace below), and the keys of a real
// keyboard reach SDL as before. The typing field lies over the field being typed in
// (placeTextInput), so that the browser keeps it in view above the keyboard.

namespace psb::app {

/// Starts (`on`) or stops SDL's text input, and in a page brings the on-screen keyboard up or
/// sends it away.
void setTextInput(bool on);

/// Where the text being typed is: `x`, `y`, `w`, `h` window points (CSS pixels in a page). In a
/// page the typing field is put there, over the program's field, so that the browser keeps that
/// spot in view when the on-screen keyboard comes up (at the page's top-left it scrolled
/// nothing, and the keyboard could cover the field). Nothing on a desktop.
void placeTextInput(float x, float y, float w, float h);

}  // namespace psb::app
