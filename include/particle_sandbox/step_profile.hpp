#pragma once
/// \file
/// What a step did and where its time went.

#include <array>
#include <cstdint>
#include <string_view>

namespace psb {

/// One timed stage of a step: its name and the wall-clock milliseconds it took.
struct StageTime {
    std::string_view name;
    double ms = 0.0;
};

/// The stages of the last call to World::step, each under the name its stepper gives it, in
/// the order they run, summed over substeps:
///   - discrete and substep: "reorder" (sorting storage by grid cell, every few steps in
///     large worlds), "gravity", "move", "find pairs", "resolve", "separate", "obstacles"
///     (particles against fixed obstacles, skipped without any), "walls";
///   - exact: "rebuild" (the event state made afresh after a change), "events" (the event
///     loop), "sync" (writing the state into the world's arrays, done at the first read after
///     the step, so it is added when that read happens).
/// Every stage of the mode is listed, a skipped one (no gravity, no walls, no rebuild) at 0.
/// A world with ball droppers lists "drop" first, in every mode (releasing the balls that are
/// due); a world without droppers has no such stage.
struct StepProfile {
    static constexpr int kMaxStages = 9;
    std::array<StageTime, kMaxStages> stages{};
    int stageCount = 0;
    double total = 0.0;       ///< milliseconds, every stage together
    std::uint64_t pairs = 0;  ///< overlapping pairs the broadphase found (summed over substeps)

    /// Milliseconds of the stage called `name`, 0 if the last step had none.
    [[nodiscard]] double ms(std::string_view name) const {
        for (int k = 0; k < stageCount; ++k) {
            if (stages[k].name == name) return stages[k].ms;
        }
        return 0.0;
    }
    /// The accumulator of stage `name`, added at the end if it is not listed yet (a stepper
    /// lists its stages in pipeline order; at most kMaxStages).
    double& stage(std::string_view name) {
        for (int k = 0; k < stageCount; ++k) {
            if (stages[k].name == name) return stages[k].ms;
        }
        if (stageCount == kMaxStages) return stages[kMaxStages - 1].ms;  // never by design
        stages[stageCount] = {name, 0.0};
        return stages[stageCount++].ms;
    }
};

/// Running totals since the world was made (or since resetCounters).
struct StepCounters {
    std::uint64_t steps = 0;       ///< calls of the discrete step (substeps count each)
    std::uint64_t collisions = 0;  ///< particle–particle collisions resolved (approaching pairs)
    std::uint64_t wallCollisions = 0;  ///< wall rebounds (outward-moving particle turned inward)
    double wallImpulse = 0.0;          ///< sum of |normal impulse| delivered by walls, kg·m/s
    double maxOverlap = 0.0;           ///< deepest pair overlap found by detection, metres
    std::uint64_t events = 0;          ///< exact mode: events processed (collisions, walls, cells)
    std::uint64_t obstacleCollisions = 0;  ///< rebounds off fixed obstacles (pegs, segments)
    /// Exact mode: steps the event budget cut short (World::setExactEventBudget; none is set
    /// unless the caller sets one). Such a step ended at its first event left: its state is
    /// exact, but at an earlier time than asked (World::time() says which).
    std::uint64_t cutShort = 0;
    /// Σ r_ij·J_ij over the pair collisions, kg·m²/s: r_ij the centre of i minus that of j at
    /// contact, J_ij the impulse j gave i (each pair once). Counted only while the world measures
    /// it (World::setMeasureVirial; the observables turn it on), else 0. The pressure's collision
    /// virial (observables.hpp).
    double pairVirial = 0.0;
};

}  // namespace psb
