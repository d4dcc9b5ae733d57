#pragma once
// The simulation clock: how much simulated time the session owes the world. Real time times
// the time speed accumulates, and whole frames of the scene's frame length are stepped from
// it; a frame that cannot catch up within its budget of wall-clock time drops the backlog (the
// simulation then runs slower than real time, and reachedScale() says how much slower). While
// paused only a requested single step runs.

#include <algorithm>
#include <chrono>
#include <cmath>

#include "session/command.hpp"
#include "session/stopwatch.hpp"

namespace psb::app {

struct Document;
class EditReport;
struct History;
class Monitor;
class Notices;

class SimClock {
  public:
    /// What the clock's commands reach beyond it: Play makes the set-up (the document), a step
    /// while a past frame is shown shows the next (the history).
    struct Context {
        Document& doc;
        History& history;
        Monitor& monitor;
        Notices& notices;
        EditReport& edit;
    };
    /// Space: pause, or run (from the past frame shown, forgetting the frames after it).
    void handle(const cmd::TogglePause& c, Context& x);
    /// N: one step while paused; while a past frame is shown, the next recorded frame.
    void handle(const cmd::SingleStep& c, Context& x);
    void handle(const cmd::SetTimeScale& c, Context& x);

    static constexpr double kMinScale = 1.0 / 16.0, kMaxScale = 8.0;
    /// Real seconds the first frame after a pause counts at most: one frame at 60 Hz.
    static constexpr double kResumeSeconds = 1.0 / 60.0;

    /// Requested simulated seconds per real second.
    [[nodiscard]] double scale() const { return scale_; }
    /// The time speed set to `value` within [kMinScale, kMaxScale]; false (and unchanged) for
    /// a value that is not a number.
    bool setScale(double value) {
        if (!std::isfinite(value)) return false;
        scale_ = reached_ = std::clamp(value, kMinScale, kMaxScale);
        return true;
    }
    /// Simulated seconds per real second the last frames reached (smoothed) while the steps
    /// cannot keep up (a backlog was dropped within the last second); otherwise scale(), which
    /// the accumulator then keeps to on average.
    [[nodiscard]] double reachedScale() const {
        return lastNow_ < behindUntil_ ? reached_ : scale_;
    }
    /// Wall-clock ms the last frame's stepping took.
    [[nodiscard]] double lastStepMs() const { return lastStepMs_; }
    /// The pointer clock's `now` at the last frame.
    [[nodiscard]] double lastNow() const { return lastNow_; }

    /// Forgets the real time owed (a new world, a mode change, a pause): the next frame starts
    /// afresh.
    void restart() { accumulator_ = 0.0; }

    /// One frame: `realSeconds` of real time at `now` on the pointer clock. Calls `step()` once
    /// per frame length `dt` owed (once if paused and a single step was requested), spending
    /// at most `budgetMs` of wall-clock time from `start`. `step()` returns the simulated
    /// seconds it covered: dt, or less when it could not finish (the exact mode's event
    /// budget), which counts as falling behind.
    template <class Step>
    void run(double realSeconds, double now, double dt, double budgetMs,
             std::chrono::steady_clock::time_point start, Step&& step) {
        lastNow_ = now;
        // The real time since the last frame was spent paused (an idle paused window draws
        // a frame every quarter second): it owes the world nothing but one frame's worth.
        if (!paused && pausedLastFrame_) realSeconds = std::min(realSeconds, kResumeSeconds);
        pausedLastFrame_ = paused;
        if (!paused) {
            accumulator_ += realSeconds * scale_;
            double simulated = 0.0;
            while (accumulator_ >= dt) {
                const double covered = step();
                simulated += covered;
                accumulator_ -= dt;
                // Catching up must not take longer than a frame, or each frame would fall
                // further behind: drop the backlog and run slower than real time. A step that
                // could not cover its frame is as far as this frame gets.
                if (covered < dt || msSince(start) > budgetMs) {
                    accumulator_ = 0.0;
                    behindUntil_ = now + 1.0;
                    break;
                }
            }
            // Smoothed over about half a second at 60 frames per second.
            if (realSeconds > 0.0) reached_ += 0.1 * (simulated / realSeconds - reached_);
        } else if (stepRequested) {
            (void)step();
        }
        stepRequested = false;
    }
    /// The frame's stepping and what followed it took until now.
    void frameDone(std::chrono::steady_clock::time_point start) { lastStepMs_ = msSince(start); }

    bool paused = false;
    bool stepRequested = false;  ///< one step at the next frame, while paused

  private:
    double scale_ = 1.0;
    double reached_ = 1.0;
    double behindUntil_ = -1.0;  ///< `now` until which the steps count as falling behind
    double lastNow_ = 0.0;
    double accumulator_ = 0.0;  ///< simulated seconds owed
    double lastStepMs_ = 0.0;
    bool pausedLastFrame_ = false;
};

}  // namespace psb::app
