// The session's clock: stepping the world in real time (an accumulator of real time × the time
// speed, a catch-up budget per frame) and stepping back through the recorded past.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <particle_sandbox/diagnostics.hpp>

#include "session/physics_controls.hpp"
#include "session/session.hpp"
#include "session/session_text.hpp"
#include "session/stopwatch.hpp"
#include "session/units.hpp"

namespace psb::app {

// ---------------------------------------------------------------------------------------------
// Step back in time.

TimelineView Session::timeline() const {
    TimelineView v;
    v.current = v.earliest = v.latest = world_.time();
    if (timeline_.empty()) return v;
    v.earliest = timeline_.timeOf(timeline_.firstFrame());
    v.latest = std::max(world_.time(), timeline_.timeOf(timeline_.lastFrame()));
    if (viewing_) {
        v.latest = timeline_.timeOf(timeline_.lastFrame());
        v.current = timeline_.timeOf(*viewing_);
        v.viewingPast = true;
    }
    return v;
}

void Session::show(std::int64_t frame) {
    world_ = timeline_.seek(frame);
    viewing_.reset();
    if (frame < timeline_.lastFrame()) viewing_ = frame;
    accumulator_ = 0.0;
    changedSinceMeasure_ = true;
    now_ = sampleObservables(world_);
    accuracy_.resetReference(monitoredEnergy(world_));
}

void Session::leavePast() {
    if (!viewing_) return;
    // The world is the rebuilt frame (and what was done to it since): it carries on from there.
    timeline_.discardAfter(*viewing_);
    viewing_.reset();
    timeline_.edited();
}

void Session::stepBack() {
    seek(world_.time(), true);
}

void Session::stepForward() {
    if (!viewing_) {
        if (paused_) {
            stepRequested_ = true;  // the present: one new step
        } else {
            say("Pause (Space) to step through time");
        }
        return;
    }
    show(*viewing_ + 1);
}

void Session::seek(double seconds, bool oneFrameBack) {
    if (interaction_.mode() != Interaction::Mode::Idle) {
        say("Release the mouse button to step through time");
        return;
    }
    if (!std::isfinite(seconds)) {
        say("Cannot go to that time: it is not a number", Notice::Level::Warning);
        return;
    }
    if (!paused_) {
        paused_ = true;
        say("Paused");
    }
    if (!viewing_) timeline_.record(world_);  // the present, with any edit since the frame
    if (timeline_.empty()) return;
    const std::int64_t at = viewing_.value_or(timeline_.lastFrame());
    std::int64_t target = timeline_.frameAt(seconds);
    if (oneFrameBack) target = at - 1;
    if (target < timeline_.firstFrame()) {
        say(fmt("The recorded past starts at %.2f s (%.1f s kept)",
                timeline_.timeOf(timeline_.firstFrame()), timeline_.coveredSeconds()));
        return;
    }
    if (target != at) show(target);
}

void Session::toggleHelp() {
    const int pages = layout_.helpPages;
    if (!showHelp_) {
        showHelp_ = true;
        helpPage_ = 0;
    } else if (static_cast<int>(helpPage_) + 1 < pages) {
        ++helpPage_;
    } else {
        showHelp_ = false;
    }
}

void Session::back() {
    if (quitPending_) {
        running_ = false;
    } else if (showHelp_) {
        showHelp_ = false;
    } else if (prompt_.active()) {
        closeEdit();
        say("Edit cancelled");
    } else {
        quit();
    }
}

void Session::quit() {
    if (!dirty_ || quitPending_) {
        running_ = false;
        return;
    }
    quitPending_ = true;
    say("Unsaved changes: Esc again quits without saving, Ctrl+S saves, any other key stays",
        Notice::Level::Warning);
}

// ---------------------------------------------------------------------------------------------
// Time.

void Session::holdParticle(double now) {
    // Through the timeline's setters, so that a past frame replays the hand's moves.
    if (const auto h = interaction_.hold(world_, now, launchSettings())) {
        timeline_.setPosition(world_, h->id, h->position);
        timeline_.setVelocity(world_, h->id, h->velocity);
    }
}

void Session::setTimeScale(double value) {
    if (!std::isfinite(value)) return;
    timeScale_ = std::clamp(value, kMinTimeScale, kMaxTimeScale);
    reached_ = timeScale_;
    say("Time speed " + speedText(timeScale_));
}

void Session::stepOnce(double now) {
    holdParticle(now);
    const double dt = world_.solver().dt;
    world_.step(dt);
    timeline_.stepped(dt);
}

void Session::update(double realSeconds, double now, double budgetMs) {
    const auto t0 = std::chrono::steady_clock::now();
    const double dt = world_.solver().dt;
    const double simBefore = world_.time();
    lastNow_ = now;
    accuracy_.beginSteps(world_);
    if (!paused_) {
        accumulator_ += realSeconds * timeScale_;
        while (accumulator_ >= dt) {
            stepOnce(now);
            accumulator_ -= dt;
            // Catching up must not take longer than a frame, or each frame would fall further
            // behind: drop the backlog and let the simulation run slower than real time.
            if (msSince(t0) > budgetMs) {
                accumulator_ = 0.0;
                behindUntil_ = now + 1.0;
                break;
            }
        }
        if (realSeconds > 0.0) {
            // Smoothed over about half a second at 60 frames per second.
            const double rate = (world_.time() - simBefore) / realSeconds;
            reached_ += 0.1 * (rate - reached_);
        }
    } else if (stepRequested_) {
        stepOnce(now);
    }
    stepRequested_ = false;
    accuracy_.endSteps(world_);
    // Arrows shorten when the motion speeds up (a bullet scattering a crowd) but never grow
    // back on their own, so their lengths stay comparable over time; opening a scene resets it.
    view_.arrowSeconds = std::min(view_.arrowSeconds, arrowSecondsFor(world_));
    // Show the held particle exactly at the hand, paused or not.
    holdParticle(now);
    // The state as drawn is measured when the steps' own detection did not see it: nothing
    // stepped (paused, or a held particle moved), the exact mode (its events meet overlaps only
    // at collisions), or the user changed the world since. Running in discrete or substep mode
    // the steps' maximum already bounds it, and a broadphase pass a frame would cost ~2 ms at
    // 5·10⁴ particles.
    if (world_.counters().steps == 0 || world_.solver().mode == StepMode::Exact ||
        changedSinceMeasure_) {
        accuracy_.measureState(world_);
        changedSinceMeasure_ = false;
    } else {
        accuracy_.clearState();
    }
    checkSelection();
    // Always recorded (three compensated sums over the particles), so the plots and the centre
    // of mass path have a history the moment they are switched on. The accuracy monitor clears
    // the world's counters before each frame's steps; the series wants a running total.
    collisions_ += world_.counters().collisions;
    now_ = sampleObservables(world_);
    now_.collisions = collisions_;
    // A past frame shown is neither the present nor a new sample.
    if (!viewing_) {
        series_.record(now_);
        timeline_.record(world_);
    }
    lastStepMs_ = msSince(t0);
}

}  // namespace psb::app
