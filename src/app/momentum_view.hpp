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

#include <SDL.h>

#include <particle_sandbox/time_series.hpp>
#include <particle_sandbox/world.hpp>

#include "camera.hpp"
#include "geometry_batch.hpp"

namespace psb::app {

class Font;

/// Colours of the momentum view, for the tests to look for.
inline constexpr SDL_Color kMomentumArrowColor{255, 150, 30, 255};  ///< per particle, orange
inline constexpr SDL_Color kTotalMomentumColor{255, 255, 0, 255};   ///< Σ m v, yellow
inline constexpr SDL_Color kCentreOfMassColor{0, 230, 255, 255};    ///< marker and path, cyan

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

/// The legend's lines: the total momentum's value, then what the colours mean.
[[nodiscard]] std::vector<std::string> momentumLegend(const World& world,
                                                      const ObservablesSample& now,
                                                      double arrowSeconds);

class MomentumView {
  public:
    /// Draws the per-particle arrows, the centre of mass path from `series` (its samples'
    /// centreOfMass, oldest first), the marker, the total arrow, and the legend in `legend`
    /// (pixels; not drawn when w == 0).
    void draw(SDL_Renderer* renderer, const Font& font, const World& world,
              const ObservablesSample& now, const Camera& camera, const TimeSeries& series,
              double arrowSeconds, const SDL_Rect& legend);

  private:
    GeometryBatch arrows_, text_;
    std::vector<SDL_FPoint> path_;
};

}  // namespace psb::app
