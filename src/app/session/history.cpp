// Stepping back through the recorded frames (the rules are timeline.hpp's).

#include "session/history.hpp"

#include <algorithm>
#include <cmath>

#include "session/document.hpp"
#include "session/monitor.hpp"
#include "session/notices.hpp"
#include "session/session_text.hpp"
#include "session/sim_clock.hpp"
#include "session/tools.hpp"

namespace psb::app {

TimelineView History::view(const World& world) const {
    const Timeline& t = timeline;
    TimelineView v;
    v.current = v.earliest = v.latest = world.time();
    if (t.empty()) return v;
    v.earliest = t.timeOf(t.firstFrame());
    v.latest = std::max(world.time(), t.timeOf(t.lastFrame()));
    if (viewing) {
        v.latest = t.timeOf(t.lastFrame());
        v.current = t.timeOf(*viewing);
        v.viewingPast = true;
    }
    return v;
}

void History::show(std::int64_t frame, Document& doc, SimClock& clock, Monitor& monitor) {
    doc.world = timeline.seek(frame);
    viewing.reset();
    if (frame < timeline.lastFrame()) viewing = frame;
    clock.restart();
    monitor.showFrame(doc.world);
}

void History::leavePast() {
    if (!viewing) return;
    // The world is the rebuilt frame (and what was done to it since): it carries on from there.
    timeline.discardAfter(*viewing);
    viewing.reset();
    timeline.edited();
}

void History::handle(const cmd::StepBack&, Context& x) {
    seek(x.doc.world.time(), x, true);
}

void History::handle(const cmd::StepForward&, Context& x) {
    if (!viewing) {
        if (x.clock.paused) {
            x.clock.stepRequested = true;  // the present: one new step
        } else {
            x.notices.say(x.notices.touch ? "Pause to step through time"
                                          : "Pause (Space) to step through time");
        }
        return;
    }
    show(*viewing + 1, x.doc, x.clock, x.monitor);
}

void History::handle(const cmd::Seek& c, Context& x) {
    seek(c.seconds, x);
}

void History::handle(const cmd::SeekBy& c, Context& x) {
    seek(view(x.doc.world).current + c.seconds, x);
}

void History::seek(double seconds, Context& x, bool oneFrameBack) {
    Timeline& t = timeline;
    if (x.tools.hand.mode() != Interaction::Mode::Idle) {
        x.notices.say("Release the mouse button to step through time");
        return;
    }
    if (!std::isfinite(seconds)) {
        x.notices.say("Cannot go to that time: it is not a number", Notice::Level::Warning);
        return;
    }
    if (!x.clock.paused) {
        x.clock.paused = true;
        x.notices.say("Paused");
    }
    if (!viewing) t.record(x.doc.world);  // the present, with any edit since the frame
    if (t.empty()) return;
    const std::int64_t at = viewing.value_or(t.lastFrame());
    std::int64_t target = t.frameAt(seconds);
    if (oneFrameBack) target = at - 1;
    if (target < t.firstFrame()) {
        x.notices.say(fmt("The recorded past starts at %.2f s (%.1f s kept)",
                          t.timeOf(t.firstFrame()), t.coveredSeconds()));
        return;
    }
    if (target != at) show(target, x.doc, x.clock, x.monitor);
}

}  // namespace psb::app
