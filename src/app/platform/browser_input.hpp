#pragma once
// When the pointer's events happened, in a web page (the web build only). SDL stamps an event
// with the time its browser handler runs, and a page's main thread runs the handlers when it
// is free: the moves of a finger or a mouse are held for the next animation frame, a finger's
// lift is not, and a slow frame (a big scene on a school tablet) delays some reports more than
// others. A fling measured on those times can read as a hand that stopped before it let go.
// The browser knows when each report arrived (the DOM event's timeStamp): the page tells the
// program how late its handler runs (web/index.html, psbEventLag), and the pointer's events
// (mouse and finger) are stamped that much earlier as SDL queues them.

namespace psb::app {

/// From now on the pointer's SDL events carry the time the browser received them.
void stampPointerEventsWithBrowserTimes();

}  // namespace psb::app
