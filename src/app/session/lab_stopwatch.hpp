#pragma once
// The stopwatch a student times motion with (the Time section, key U): it runs on simulated
// time, so it stops while the simulation is paused and reads the same at any time speed. Start,
// stop (and start again: the time stopped is left out), lap (a split while running), reset.
// Its reading is the simulated time since its start, less what it was stopped for: a step back
// or an undo takes it back as far as the clock went, and before its start it says so instead of
// showing a time it never measured.

#include <optional>
#include <string>
#include <vector>

namespace psb::app {

class LabStopwatch {
  public:
    /// Laps kept at most; the oldest go first.
    static constexpr std::size_t kMaxLaps = 100;

    [[nodiscard]] bool used() const { return start_.has_value(); }
    [[nodiscard]] bool running() const { return used() && !stoppedAt_; }

    /// Starts it at the simulated time `now`, or starts it again after a stop.
    void start(double now);
    void stop(double now);
    /// A split at `now`, while running (else nothing).
    void lap(double now);
    void reset();

    /// Simulated seconds measured at `now` (negative before its start: see beforeStart()).
    [[nodiscard]] double reading(double now) const;
    /// The clock was taken back before the stopwatch started (a step back, an undo).
    [[nodiscard]] bool beforeStart(double now) const { return used() && reading(now) < 0.0; }
    /// Readings at each lap, oldest first.
    [[nodiscard]] const std::vector<double>& laps() const { return laps_; }

  private:
    /// The simulated time the reading counts from: the start, moved later by each stop.
    std::optional<double> start_;
    std::optional<double> stoppedAt_;
    std::vector<double> laps_;
};

/// The stopwatch as the HUD shows it: "Stopwatch 1.234 s", then "(stopped)" or the last lap;
/// empty when not used. Time gone back before its start names what resets it: Shift+U, or on a
/// touch screen (`touch`: Session::touch) the panel's Reset.
[[nodiscard]] std::string stopwatchLine(const LabStopwatch& watch, double now, bool touch = false);

}  // namespace psb::app
