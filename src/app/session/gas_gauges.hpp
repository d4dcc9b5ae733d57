#pragma once
// The gas instruments: a reader of the core's measurement (particle_sandbox/observables.hpp,
// docs/observables.md) over the last few seconds of simulated time, beside what the ideal gas
// and the hard-disc equation of state predict for the same particles. The numbers are the
// core's, in its one convention, so they are what `particle-sim --observables` reports for the
// same stretch of the same run:
//
// - kT, the mean kinetic energy per particle (two translational degrees of freedom: ½ kT each).
//   It is shown in joules: the scenes' particles are balls of grams to kilograms, whose
//   "temperature" in kelvin (kT / k_B, about 10²³ K) would mean nothing to a class.
// - the pressure of a 2-D gas, a force per unit length, N/m: in a box with walls the walls'
//   normal impulse per second per length of the line the centres reach,
//   L′ = 2(w − 2r̄ + h − 2r̄) (a centre comes no closer to a wall than a radius); in a periodic
//   box (no walls) the collision virial's. ± the standard error of the core's block averages.
//
//   ideal gas     P = N kT / A′                               A′ = (w − 2r̄)(h − 2r̄), the area
//   hard discs    P = N kT / A′ · (1 + η²/8) / (1 − η)²       the centres move in (all of a
//                 (Henderson 1975; η = Σ π r² / A)            periodic box)
//
// The window. The core measures over a window its caller opens and closes; the gauges open one
// when the world starts to run on and another every kWindow / kStagger seconds after, drop each
// once it spans more than kWindow, and read the oldest: the last 3.75 to 5 s of simulated time
// (all of it in the first five seconds), a value shown once it spans kMinWindow. The windows
// start over whenever the world does not simply run on (an edit, an undo, a new scene, time
// going back, particles added or removed), so a reading never mixes two set-ups.
//
// The pressure plot's history: every kHistoryEvery seconds of simulated time the reading is
// kept (measured, its error, the two predictions), so a plot shows both over time. An edit (heat,
// cool) keeps the history: the plot shows the pressure's step; time going back drops what came
// after, and a new scene starts it over.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>

#include <particle_sandbox/observables.hpp>
#include <particle_sandbox/world.hpp>

namespace psb::app {

struct GasReading {
    std::size_t particles = 0;
    double kT = 0.0;        ///< J: the mean kinetic energy per particle (the core's kT)
    double area = 0.0;      ///< m², the box's
    double reach = 0.0;     ///< m², the area the centres move in (A′)
    double coverage = 0.0;  ///< η: the fraction of the box the discs cover
    double window = 0.0;    ///< s of simulated time the measured values average
    /// A periodic box: the pressure is the collision virial's (no walls to push).
    bool periodic = false;
    /// The pressure measured, N/m; nullopt until the window spans kMinWindow seconds and has
    /// blocks enough for an error.
    std::optional<double> pressure;
    double pressureError = 0.0;     ///< its standard error, N/m
    double idealPressure = 0.0;     ///< N kT / A′, N/m
    double hardDiskPressure = 0.0;  ///< Henderson's, N/m
    double pairRate = 0.0;          ///< particle–particle collisions per second over the window
    double wallRate = 0.0;          ///< wall rebounds per second over the window (0: periodic)
};

/// One point of the pressure plot.
struct GasHistoryPoint {
    double time = 0.0;               ///< s, simulated
    std::optional<double> pressure;  ///< measured, N/m (none while the window is short)
    double pressureError = 0.0;      ///< N/m
    double idealPressure = 0.0;      ///< N/m
    double hardDiskPressure = 0.0;   ///< N/m
};

/// What the gauges show for the core's measurement `measured` of `world`: the pressure once the
/// window spans `minWindow` seconds (the walls', or in a periodic box the virial's).
[[nodiscard]] GasReading gasReading(const ObservablesResult& measured, const World& world,
                                    double minWindow);

class GasGauges {
  public:
    static constexpr double kWindow = 5.0;     ///< s of simulated time averaged, at most
    static constexpr double kMinWindow = 0.5;  ///< s before a measured value is shown
    static constexpr int kStagger = 4;         ///< windows opened per kWindow
    /// Samples (frames) between two readings of the particles (kT): every open window reading
    /// every particle every frame cost three quarters of a discrete step at 10⁴ particles.
    static constexpr std::uint32_t kStateEvery = 8;
    static constexpr double kHistoryEvery = 0.25;        ///< s of simulated time between points
    static constexpr std::size_t kHistoryPoints = 1200;  ///< kept: the last 5 minutes

    /// The world will not simply run on from here: the windows start over (the history stays,
    /// up to the world's time; `newScene` clears it).
    void restart(bool newScene = false) {
        windows_.clear();
        if (newScene) history_.clear();
    }
    /// The world after a frame's steps: each open window samples it (the core reads the
    /// counters, which the Monitor clears before each frame, and the particles), and a window
    /// opens as the top of this file says. Where the gauges do not apply the windows close, and
    /// the world's virial counter with them.
    void sample(World& world);
    /// What the gauges read for `world` now: the oldest window's measurement. Before any sample
    /// (a past frame shown, the frame before the first), a window opened on a copy of the world:
    /// its state, nothing measured over time.
    [[nodiscard]] GasReading reading(const World& world) const;
    /// The pressure plot's points, oldest first.
    [[nodiscard]] const std::deque<GasHistoryPoint>& history() const { return history_; }

  private:
    struct Window {
        ObservablesWindow measure;
        double opened = 0.0;  ///< s, simulated
    };
    void open(World& world);

    std::deque<Window> windows_;  ///< oldest first
    double lastTime_ = 0.0;       ///< the last sample's
    std::size_t particles_ = 0;   ///< the world's when the windows opened
    std::deque<GasHistoryPoint> history_;
};

/// Particles a gas needs for its gauges: two balls colliding are a collision, not a gas, and
/// their "pressure" (no wall hit yet: zero) and "temperature" would only confuse the lesson.
inline constexpr std::size_t kGasMinParticles = 10;

/// Whether the gas gauges apply to `world`: walls all round, or a periodic box without fixed
/// obstacles (whose pressure the collision virial measures: obstacles would need their own), no
/// gravity (whose weight the walls would carry too), and at least kGasMinParticles particles.
[[nodiscard]] bool gasGaugesApply(const World& world);

}  // namespace psb::app
