#pragma once
// Fading path traces behind particles (the L key: off -> the selected particle -> all).
//
// Cheap at 10^4 particles: each particle's recent positions live in a fixed-size ring inside
// flat arrays (structure of arrays, one row of kLength floats per id slot), sampled every
// kSampleFrames frames, so a sample is one O(N) pass and allocates nothing once the arrays have
// grown to the world. Rows are keyed by the particle's stable id: a slot whose generation
// changed (the particle was deleted and the slot reused) starts an empty trail, a dead id is
// never drawn, and a new scene resets everything.
//
// Each trail is drawn as kBands polylines of fading colour; the lines are SDL's
// (SDL_RenderDrawLinesF: Bresenham on the software renderer), whose cost grows with the pixels
// drawn, where thin triangles would each scan their whole bounding box.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <SDL.h>

#include <particle_sandbox/particle_id.hpp>
#include <particle_sandbox/world.hpp>

#include "camera.hpp"

namespace psb::app {

/// What L shows.
enum class TrailMode { Off, Selected, All };

/// Off -> Selected -> All -> Off.
[[nodiscard]] TrailMode nextTrailMode(TrailMode mode);
/// "off", "selected", "all".
[[nodiscard]] const char* toString(TrailMode mode);

class Trails {
  public:
    static constexpr int kLength = 32;       ///< positions kept per particle
    static constexpr int kSampleFrames = 2;  ///< frames between samples
    static constexpr int kBands = 4;         ///< fading steps from tail to head

    /// Forgets every trail (a new scene).
    void reset();
    /// Called once per frame: samples every kSampleFrames-th frame in which the world's time
    /// moved (a paused world keeps its trails as they are).
    void update(const World& world);
    /// Appends every live particle's position to its trail now.
    void sample(const World& world);

    /// Positions stored for `id` (0 when it has no trail), at most kLength.
    [[nodiscard]] std::size_t length(ParticleId id) const;
    /// The k-th stored position of `id`, 0 = the oldest; k < length(id). Metres.
    [[nodiscard]] Vec2 point(ParticleId id, std::size_t k) const;

    /// Draws the trails of `mode` (the one of `selected` for Selected; none when it is null),
    /// each ending at its particle's current position. Returns the number of trails drawn.
    std::size_t draw(SDL_Renderer* renderer, const World& world, const Camera& camera,
                     TrailMode mode, ParticleId selected);

  private:
    [[nodiscard]] bool has(ParticleId id) const {
        return id.slot < generation_.size() && generation_[id.slot] == id.generation &&
               count_[id.slot] > 0;
    }
    void drawOne(SDL_Renderer* renderer, const World& world, const Camera& camera,
                 std::size_t index);

    // Row `slot` of xs_/ys_ holds kLength positions (float metres: a trail is only drawn),
    // head_ the next write position, count_ how many are valid.
    std::vector<float> xs_, ys_;
    std::vector<std::uint32_t> generation_;
    std::vector<std::uint8_t> head_, count_;
    std::vector<SDL_FPoint> line_;  // scratch for one trail's screen points
    double lastTime_ = -1.0;
    int frames_ = 0;
};

}  // namespace psb::app
