#pragma once
// The exact stepper's jam guards: what keeps a particle that has no room to move from stalling
// the event loop.
//
// Squeezed by held particles. A free particle crushed between a held particle and a wall or
// another held one would collide infinitely often: after kJamLimit collisions with held
// particles in one step it passes through held particles (kJammed) for the rest of that step.
// The counts (Cold::heldHits, which also count hits on sleepers, see resting.hpp) are reset at
// the start of every step, for the particles counted in the last one only.
//
// Jammed between placed overlaps. A particle surrounded by bodies placed overlapping it (walls,
// obstacles, discs wider than the box) has no room, and the rules for invalid states would
// bounce it between them for ever: after kJamHits collisions in a row without time or room
// between them it is jammed, and the stepper absorbs its velocity. The runs are counted by
// storage index, stable while the stepper re-sorts its own.

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "exact/body.hpp"

namespace psb::exact {

/// Collisions with held particles after which a squeezed particle passes through them for the
/// rest of the step.
inline constexpr std::uint32_t kJamLimit = 1000;

/// Collisions of one particle in a row without time or room between them (each within
/// kJamTime of its last change, having moved less than kJamRoom of its radius since) after
/// which it is jammed: placed overlapping bodies that surround it (walls, obstacles, discs
/// wider than the box), it has no room to move, and the rules for invalid states would bounce
/// it between them for ever. Its velocity is absorbed (under gravity it falls asleep where it
/// is), and while its hits keep coming without time between it is as fixed as a sleeper.
/// Squeezes by held particles are kJamLimit's. Found by the world mutation fuzzer. Legitimate
/// runs are far shorter: at most 6,800 in a row in the exact mode's pile, Galton, funnel and
/// hourglass tests (a disc settling in a pocket with e = 0), and a disc that can leave a wedge,
/// however narrow, leaves after about π/θ bounces.
inline constexpr std::uint32_t kJamHits = 100000;
inline constexpr double kJamTime = 1e-9;  ///< seconds: 10⁻⁴ of the contact duration t_c
inline constexpr double kJamRoom = 1e-9;  ///< of the radius

class JamGuard {
  public:
    /// Forgets every count (a rebuild).
    void reset() {
        counted_.clear();
        repeats_.clear();
    }
    /// At the start of a step: clears the per-step counts (and kJammed) of the particles
    /// counted in the last one.
    void startStep(std::vector<Body>& bodies, std::vector<Cold>& cold);
    /// Counts a hit of particle i (its record `c`) on a held particle or a sleeper this step;
    /// returns the count.
    std::uint32_t countHit(std::uint32_t i, Cold& c) {
        if (c.heldHits++ == 0) counted_.push_back(i);
        return c.heldHits;
    }
    /// Counts a hit of particle i on a held particle: past kJamLimit in this step it passes
    /// through held particles.
    void countHeldHit(std::uint32_t i, Body& b, Cold& c) {
        if (countHit(i, c) >= kJamLimit) b.flags |= kJammed;
    }
    /// Before a collision at time t of particle i (its record `a`, free and awake; `order` the
    /// storage indices): counts it if it comes without time or room since i's last change, and
    /// ends the run if not. True once the run reaches kJamHits, and for every hit of the run
    /// after that: i is jammed.
    bool jams(const Body& a, std::uint32_t i, const std::vector<std::uint32_t>& order, double t) {
        // Without time or room since its last change: within kJamTime, moved less than kJamRoom
        // of its radius (the speed it had since then times the time).
        const double h = t - a.t;
        const bool stuck = h <= kJamTime && h * std::hypot(a.vx, a.vy) <= kJamRoom * a.r;
        if (!stuck && repeats_.empty()) return false;  // the usual case: nothing to count
        return countRun(order[i], stuck);
    }
    /// Follows a renumbering of the particles: particle i is now to[i].
    void renumber(const std::vector<std::uint32_t>& to) {
        for (std::uint32_t& i : counted_)
            i = to[i];
    }

  private:
    bool countRun(std::uint32_t who, bool stuck);

    // Particles with heldHits > 0 this step.
    std::vector<std::uint32_t> counted_;
    // The particles whose last collisions came without time or room between, by storage index,
    // and how many in a row.
    std::unordered_map<std::uint32_t, std::uint32_t> repeats_;
};

}  // namespace psb::exact
