#pragma once
// The momentum view (the V key): every particle's momentum m v as an arrow, the centre of mass
// with its recent path, and the total momentum Σ m v as a thick arrow from the centre of mass.
//
// Scale: a particle's momentum arrow is as long as its velocity arrow would be if its mass were
// the mean mass, i.e. arrowSeconds · |m v| / m̄ metres. Equal masses therefore give the same
// lengths as the velocity arrows (A), and a heavy particle's arrow is longer in proportion. The
// total would be N times longer on that scale, so its arrow is capped at 40 % of the box's
// smaller side and labelled with its value.

#include <string>
#include <vector>

#include <particle_sandbox/axes.hpp>
#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/world.hpp>

#include "session/camera.hpp"

namespace psb::app {

/// What the total momentum arrow looks like, in world units: from the centre of mass, metres.
struct TotalMomentumArrow {
    Vec2 from = Vec2::Zero();  ///< the centre of mass, m
    Vec2 to = Vec2::Zero();    ///< m
    bool capped = false;       ///< shortened to 40 % of the box's smaller side
};

/// The total momentum arrow for `world` at `arrowSeconds` (see the file comment); `now` is the
/// world's current sample (its momentum and centre of mass), so that they are summed once a frame.
[[nodiscard]] TotalMomentumArrow totalMomentumArrow(const World& world,
                                                    const ObservablesSample& now,
                                                    double arrowSeconds);

/// The mean mass of `p` (kg), 1 when it is empty: what sets the arrows' scale.
[[nodiscard]] double meanMass(const ParticleArrays& p);

/// The legend's lines: the total momentum's value (in `axes`, the y up option), then what the
/// colours mean.
[[nodiscard]] std::vector<std::string> momentumLegend(const World& world,
                                                      const ObservablesSample& now,
                                                      double arrowSeconds, const Axes& axes = {});

}  // namespace psb::app
