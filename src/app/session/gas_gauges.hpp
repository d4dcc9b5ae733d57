#pragma once
// The gas instruments: temperature from the particles' mean kinetic energy, and the pressure
// measured on the walls from the momentum the particles give them, beside what the ideal gas
// and the hard-disk equation of state predict for the same particles, and the collision rates.
//
// In two dimensions, equipartition gives each particle kT of kinetic energy on average (½ kT per
// degree of freedom, two of them), so kT = ⟨½ m v²⟩. It is shown in joules: the scenes' particles
// are balls of grams to kilograms, whose "temperature" in kelvin (kT / k_B, about 10²³ K) would
// mean nothing to a class. The pressure of a 2-D gas is a force per unit length of wall, N/m:
// the walls' normal impulse (StepCounters::wallImpulse, every mode counts it) per second, over
// the box's perimeter, averaged over the last kWindow seconds of simulated time. Its uncertainty
// is the standard error of kBlocks block averages over that window (successive blocks are close
// to independent once a block is longer than a particle's time between wall hits).
//
//   ideal gas     P = N kT / A'
//   hard disks    P = N kT / A' · (1 + η²/8) / (1 − η)²   (Henderson 1975; η = Σ π r² / A, the
//                 fraction of the box the discs cover: within about 1 % of simulations up to
//                 η ≈ 0.6)
//
// where A is the box's area and A' = (w − 2 r̄)(h − 2 r̄) the area the discs' centres move in
// (r̄ their mean radius): a centre comes no closer to a wall than a radius, which for the gas
// preset's 2.5 cm discs in 7 m raises the pressure by 1.4 %.
//
// The window starts over whenever the world does not simply run on (an edit, an undo, a new
// scene, time going back), so a reading never mixes two set-ups.
//
// The pressure plot's history: every kHistoryEvery seconds of simulated time the reading is
// kept (measured, its error, the two predictions), so a plot shows both over time. An edit (heat,
// cool) keeps the history: the plot shows the pressure's step; time going back drops what came
// after, and a new scene starts it over.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>

#include <particle_sandbox/world.hpp>

namespace psb::app {

struct GasReading {
    std::size_t particles = 0;
    double kT = 0.0;        ///< J: the mean kinetic energy per particle
    double area = 0.0;      ///< m², the box's
    double reach = 0.0;     ///< m², the area the centres move in (A')
    double coverage = 0.0;  ///< η: the fraction of the box the discs cover
    double window = 0.0;    ///< s of simulated time the measured values average
    /// The pressure measured on the walls, N/m; nullopt until kMinWindow seconds have run.
    std::optional<double> pressure;
    double pressureError = 0.0;     ///< its standard error, N/m
    double idealPressure = 0.0;     ///< N kT / A, N/m
    double hardDiskPressure = 0.0;  ///< Henderson's, N/m
    double pairRate = 0.0;          ///< particle–particle collisions per second over the window
    double wallRate = 0.0;          ///< wall rebounds per second over the window
};

/// One point of the pressure plot.
struct GasHistoryPoint {
    double time = 0.0;               ///< s, simulated
    std::optional<double> pressure;  ///< measured, N/m (none while the window is short)
    double pressureError = 0.0;      ///< N/m
    double idealPressure = 0.0;      ///< N/m
    double hardDiskPressure = 0.0;   ///< N/m
};

class GasGauges {
  public:
    static constexpr double kWindow = 5.0;     ///< s of simulated time averaged, at most
    static constexpr double kMinWindow = 0.5;  ///< s before a measured value is shown
    static constexpr int kBlocks = 8;
    static constexpr double kHistoryEvery = 0.25;        ///< s of simulated time between points
    static constexpr std::size_t kHistoryPoints = 1200;  ///< kept: the last 5 minutes

    /// The world will not simply run on from here: the window starts over (the history stays,
    /// up to the world's time; `newScene` clears it).
    void restart(bool newScene = false) {
        samples_.clear();
        if (newScene) history_.clear();
    }
    /// The world after a frame's steps, its counters (World::counters) holding those steps' only
    /// (the Monitor clears them before each frame's steps).
    void sample(const World& world);
    /// What the gauges read for `world` now (the measured values from the window sampled).
    [[nodiscard]] GasReading reading(const World& world) const;
    /// The pressure plot's points, oldest first.
    [[nodiscard]] const std::deque<GasHistoryPoint>& history() const { return history_; }

  private:
    /// Running totals since the window started over.
    struct Sample {
        double time;
        double wallImpulse;
        std::uint64_t collisions;
        std::uint64_t wallCollisions;
    };
    std::deque<Sample> samples_;
    std::deque<GasHistoryPoint> history_;
};

/// Particles a gas needs for its gauges: two balls colliding are a collision, not a gas, and
/// their "pressure" (no wall hit yet: zero) and "temperature" would only confuse the lesson.
inline constexpr std::size_t kGasMinParticles = 10;

/// Whether the gas gauges apply to `world`: walls all round, no gravity (whose weight the walls
/// would carry too), and at least kGasMinParticles particles.
[[nodiscard]] bool gasGaugesApply(const World& world);

}  // namespace psb::app
