// The clock's commands: pause, single steps and the time speed.

#include "session/sim_clock.hpp"

#include "session/document.hpp"
#include "session/edit_report.hpp"
#include "session/history.hpp"
#include "session/notices.hpp"
#include "session/session_text.hpp"

namespace psb::app {

void SimClock::handle(const cmd::TogglePause&, Context& x) {
    if (paused && x.history.viewing) {
        const double t = x.doc.world.time();
        x.history.leavePast();
        x.notices.say(fmt("Resumed from %.2f s: the later frames are forgotten", t));
    } else if (!paused) {
        x.notices.say("Paused");
    } else {
        // Play after an edit: the world as it is becomes the set-up Restart returns to.
        x.notices.say(x.doc.play() ? "Resumed; R restarts from this set-up" : "Resumed");
    }
    paused = !paused;
    restart();
}

void SimClock::handle(const cmd::SingleStep&, Context& x) {
    if (x.history.viewing) {
        x.history.show(*x.history.viewing + 1, x.doc, *this, x.monitor);
    } else if (paused) {
        stepRequested = true;
    }
}

void SimClock::handle(const cmd::SetTimeScale& c, Context& x) {
    const double before = scale();
    if (!setScale(c.value)) return;
    x.notices.say("Time speed " + speedText(scale()));
    if (scale() != before) x.edit.remember("set time speed");
}

}  // namespace psb::app
