// The session's clock: pause, single steps, the time speed, and update(), which steps the world
// in real time (sim_clock.hpp) and measures the frame (monitor.hpp).

#include <algorithm>
#include <chrono>

#include "session/collision_feed.hpp"
#include "session/frame_step.hpp"
#include "session/session.hpp"
#include "session/session_text.hpp"
#include "session/units.hpp"

namespace psb::app {

void Session::handle(const cmd::Stopwatch& c) {
    using A = cmd::Stopwatch::Action;
    const double t = doc_.world.time();
    A action = c.action;
    if (action == A::LapOrReset) action = stopwatch_.running() ? A::Lap : A::Reset;
    switch (action) {
        case A::StartStop:
            if (stopwatch_.running()) {
                stopwatch_.stop(t);
                notices_.say(fmt("Stopwatch stopped at %.3f s", stopwatch_.reading(t)));
            } else {
                stopwatch_.start(t);
                notices_.say(clock_.paused
                                 ? "Stopwatch started: it runs with simulated time (Space)"
                                 : "Stopwatch started");
            }
            break;
        case A::Lap:
            if (!stopwatch_.running()) return;
            stopwatch_.lap(t);
            notices_.say(
                fmt("Lap %zu: %.3f s", stopwatch_.laps().size(), stopwatch_.laps().back()));
            break;
        case A::Reset:
        case A::LapOrReset:
            if (!stopwatch_.used()) return;
            stopwatch_.reset();
            notices_.say("Stopwatch reset");
            break;
    }
}

double Session::stepOnce(double now) {
    holdParticle(now);
    const double dt = doc_.meta.dt;  // the scene's frame length
    // One collision log for the instruments that read it (collision_feed.hpp).
    const std::optional<ParticleId> selected = tools_.selection.id();
    const bool card = LastCollision::listening(view_.collision, doc_.world.size());
    listen(doc_.world,
           mergeWanted(data_.collisionsWanted(), LastCollision::wanted(card, selected)));
    data_.beforeStep(doc_.world);
    const double simulated = stepFrame(doc_.world, dt);
    // The time series samples on simulated time, whatever the frames (monitor.hpp).
    if (monitor_.stepped(doc_.world)) data_.sample(monitor_.series().back());
    const std::vector<Collision> records = heard(doc_.world);
    data_.afterStep(doc_.world, records);
    if (card) lastCollision_.heard(records, doc_.world, selected);
    history_.timeline.stepped(dt);
    return simulated;
}

void Session::listenForCollisions() {
    // One collision log for the instruments that read it (collision_feed.hpp).
    const bool card = LastCollision::listening(view_.collision, doc_.world.size());
    listen(doc_.world, mergeWanted(data_.collisionsWanted(),
                                   LastCollision::wanted(card, tools_.selection.id())));
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
    holdParticle(now);
    checkSelection();
    lastCollision_.follow(tools_.selection.id());
    lastCollision_.dropAfter(doc_.world.time());
    // A past frame shown is neither the present nor a new sample. At a sample's instant (paused
    // there) the sample is the world as drawn, edits before Play included.
    if (monitor_.frameDone(doc_.world, !history_.viewing)) data_.sample(monitor_.series().back());
    if (!history_.viewing) history_.timeline.record(doc_.world);
    if (const std::string why = data_.takeStopReason(); !why.empty()) {
        notices_.say("Recording stopped: " + why, Notice::Level::Warning);
    }
    clock_.frameDone(t0);
}

}  // namespace psb::app
