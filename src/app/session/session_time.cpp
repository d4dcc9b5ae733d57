// The session's clock: pause, single steps, the time speed, and update(), which steps the world
// in real time (sim_clock.hpp) and measures the frame (monitor.hpp).

#include <algorithm>
#include <chrono>

#include "session/frame_step.hpp"
#include "session/session.hpp"
#include "session/session_text.hpp"
#include "session/units.hpp"

namespace psb::app {

double Session::stepOnce(double now) {
    tools_.hold(doc_.world, history_.timeline, now, view_.camera());
    const double dt = doc_.meta.dt;  // the scene's frame length
    // Whether the card listens is decided as the step starts, and holds for its records.
    const std::optional<ParticleId> selected = tools_.selection.id();
    const bool card = Instruments::cardListens(view_.options().collision, doc_.world);
    instruments_.beforeStep(doc_, card, selected);
    const double simulated = stepFrame(doc_.world, dt);
    // The time series samples on simulated time, whatever the frames (monitor.hpp).
    if (monitor_.stepped(doc_.world)) instruments_.data.sample(monitor_.series().back());
    instruments_.afterStep(doc_, card, selected);
    history_.timeline.stepped(dt);
    return simulated;
}

void Session::update(double realSeconds, double now, double budgetMs) {
    const auto t0 = std::chrono::steady_clock::now();
    monitor_.beginSteps(doc_.world);
    clock_.run(realSeconds, now, doc_.meta.dt, budgetMs, t0, [this, now] { return stepOnce(now); });
    monitor_.endSteps(doc_.world);
    // The arrow scale does not change by itself while a scene runs (launches, a bullet
    // scattering a crowd): arrow lengths stay comparable over time. A scene opened chooses one;
    // the Show section's slider sets it.
    // Show the held particle exactly at the hand, paused or not.
    tools_.hold(doc_.world, history_.timeline, now, view_.camera());
    tools_.checkSelection(doc_.world, notices_);
    instruments_.lastCollision.follow(tools_.selection.id());
    instruments_.lastCollision.dropAfter(doc_.world.time());
    // A past frame shown is neither the present nor a new sample. At a sample's instant (paused
    // there) the sample is the world as drawn, edits before Play included.
    if (monitor_.frameDone(doc_.world, !history_.viewing))
        instruments_.data.sample(monitor_.series().back());
    if (!history_.viewing) history_.timeline.record(doc_.world);
    if (const std::string why = instruments_.data.takeStopReason(); !why.empty()) {
        notices_.say("Recording stopped: " + why, Notice::Level::Warning);
    }
    clock_.frameDone(t0);
}

}  // namespace psb::app
