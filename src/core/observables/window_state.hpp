#pragma once
// What an open observables window keeps (observables.hpp): the world's particles and box as
// opened, the counters and clock at the last sample, and the chunks of data.

#include <cstdint>
#include <string>
#include <vector>

#include <particle_sandbox/observables.hpp>
#include <particle_sandbox/particle_id.hpp>
#include <particle_sandbox/step_profile.hpp>

#include "observables/observation_chunk.hpp"
#include "observables/pair_distribution.hpp"
#include "observables/time_correlation.hpp"

namespace psb {

struct ObservablesWindow::State {
    explicit State(int blocks) : chunks(blocks) {}

    // The world as opened.
    std::vector<ParticleId> ids;
    std::vector<std::uint32_t> slotIndex;  ///< the window's index of each id's slot
    std::size_t n = 0;
    double width = 0.0, height = 0.0, meanRadius = 0.0;
    bool walls = false, gravity = false, obstacles = false;
    bool periodic = false;  ///< a periodic box: the centres move in all of it, and no walls
    /// Pairs of translational degrees of freedom: N, or N − 1 where the total momentum is
    /// conserved (a periodic box without obstacles or gravity), whose kinetic energy is then
    /// measured in the frame of the centre of mass.
    double freedom = 0.0;
    bool equalDiscs = false;  ///< one radius and one mass: σ and m mean something
    double sigma = 0.0, mass = 0.0;
    double coveredArea = 0.0;  ///< Σ π r², m²
    std::size_t turning = 0;   ///< particles that can turn (worlds that keep rotation)

    // The last sample.
    double openTime = 0.0, lastTime = 0.0;
    StepCounters last;
    std::uint64_t lastResets = 0;                     ///< World::counterResets() at the last sample
    std::uint64_t samples = 0;                        ///< sample intervals so far
    std::uint64_t stateSamples = 0;                   ///< state samples so far (the first at open)
    double lastStateTime = 0.0, stateInterval = 0.0;  ///< s; 0 until the second state sample
    bool particlesChanged = false;

    observables::Chunks chunks;
    observables::PairDistribution pairs;
    observables::TimeCorrelation correlation;
    std::vector<double> x, y, vx, vy;  ///< scratch, in the window's particle order
    std::vector<std::string> notes;
};

}  // namespace psb
