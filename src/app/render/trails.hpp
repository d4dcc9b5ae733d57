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
// Drawing: every trail is rasterised on the CPU into one ARGB image the size of the viewport
// (a DDA line per step, its alpha fading from tail to head), which the Renderer shows with one
// blended texture copy of the rectangle that holds trail pixels. SDL's software renderer pays a
// fixed price per line call (about 0.4 us) and per triangle (about 0.25 us, and a temporary
// surface per blended triangle), so 10^4 trails of 31 steps cost 17 ms as line calls and over
// 20 ms as thin quads even after merging straight runs; as pixels they cost the pixels drawn
// plus one copy (see docs/app.md, "Frame time").

#include <cstddef>
#include <cstdint>
#include <vector>

#include <SDL.h>

#include <particle_sandbox/particle_id.hpp>
#include <particle_sandbox/world.hpp>

#include "session/camera.hpp"
#include "session/view_options.hpp"

namespace psb::app {

/// The trails' pixels: `width` × `height` ARGB8888 words (alpha not premultiplied), zero
/// where no trail is, and the rectangle that holds every non-zero pixel.
class TrailImage {
  public:
    /// Makes the image `width` × `height` pixels (all clear); a no-op when it already is.
    void resize(int width, int height);
    /// Clears the pixels drawn since the last clear.
    void clear();
    /// A filled disc of radius `r` pixels centred at (cx, cy): the pixels whose centres lie
    /// within r + 0.5 of it, and at least the pixel under the centre; clipped to the image.
    void disc(float cx, float cy, float r, std::uint32_t argb);
    /// A one-pixel line from (x0, y0) to (x1, y1), pixels, clipped to the image. Where lines
    /// cross, the more opaque colour stays.
    void line(float x0, float y0, float x1, float y1, std::uint32_t argb);

    [[nodiscard]] int width() const { return width_; }
    [[nodiscard]] int height() const { return height_; }
    [[nodiscard]] const std::uint32_t* pixels() const { return pixels_.data(); }
    /// The pixel at (x, y); both inside the image.
    [[nodiscard]] std::uint32_t at(int x, int y) const {
        return pixels_[static_cast<std::size_t>(y) * width_ + x];
    }
    /// Holds every drawn pixel; w == 0 when nothing is drawn.
    [[nodiscard]] SDL_Rect dirty() const;

  private:
    std::vector<std::uint32_t> pixels_;
    int width_ = 0, height_ = 0;
    int minX_ = 0, minY_ = 0, maxX_ = -1, maxY_ = -1;  // inclusive bounds of the drawn pixels
};

class Trails {
  public:
    static constexpr int kLength = 32;          ///< positions kept per particle
    static constexpr int kSampleFrames = 2;     ///< frames between samples
    static constexpr float kMinSegment = 0.5f;  ///< shorter steps join the next one, pixels
    static constexpr float kTailAlpha = 0.15f;  ///< the oldest step's opacity (the head's is 1)
    /// The followed trail's: drawn over a crowd, its whole minute must stay visible.
    static constexpr float kFollowedTailAlpha = 0.45f;

    /// Positions kept for the followed particle (the selected one), a minute at 60 frames per
    /// second: a slow particle's wandering, like the Brownian disc's, shows beyond its rim.
    static constexpr int kFollowedLength = 1800;

    /// Forgets every trail (a new scene).
    void reset();
    /// Keeps the long trail of `id` from now on (the selected particle; an invalid id: none).
    /// Another id starts its long trail over.
    void follow(ParticleId id);
    /// Positions in the followed particle's long trail (0 when it has none).
    [[nodiscard]] std::size_t followedLength() const { return followedCount_; }
    /// Called once per frame: samples every kSampleFrames-th frame in which the world's time
    /// moved (a paused world keeps its trails as they are).
    void update(const World& world);
    /// Appends every live particle's position to its trail now.
    void sample(const World& world);

    /// Positions stored for `id` (0 when it has no trail), at most kLength.
    [[nodiscard]] std::size_t length(ParticleId id) const;
    /// The k-th stored position of `id`, 0 = the oldest; k < length(id). Metres.
    [[nodiscard]] Vec2 point(ParticleId id, std::size_t k) const;

    /// Draws the trails of `mode` (the one of `selected` for Selected; none when it is null)
    /// into the image, the size of the camera's viewport, each ending at its particle's current
    /// position; `drawn` (when given) receives the number of trails drawn. Allocates only when
    /// the viewport or the world grows.
    const TrailImage& rasterise(const World& world, const Camera& camera, TrailMode mode,
                                ParticleId selected, std::size_t* drawn = nullptr);

  private:
    [[nodiscard]] bool has(ParticleId id) const {
        return id.slot < generation_.size() && generation_[id.slot] == id.generation &&
               count_[id.slot] > 0;
    }
    void rasteriseOne(const World& world, const Camera& camera, std::size_t index);
    /// The polyline through `n` ring positions (xs, ys of `ringLength`, the oldest at
    /// `oldest`) and then the particle `index` now, in `rgb`, fading from `tailAlpha` at the
    /// tail to opaque at the head; `bold`: two pixels wide.
    void rasterisePath(const World& world, const Camera& camera, std::size_t index, const float* xs,
                       const float* ys, std::size_t ringLength, std::size_t oldest, std::size_t n,
                       std::uint32_t rgb, float tailAlpha = kTailAlpha, bool bold = false);

    // Row `slot` of xs_/ys_ holds kLength positions (float metres: a trail is only drawn),
    // head_ the next write position, count_ how many are valid.
    std::vector<float> xs_, ys_;
    std::vector<std::uint32_t> generation_;
    std::vector<std::uint8_t> head_, count_;
    ParticleId followed_;
    std::vector<float> followedXs_, followedYs_;  // kFollowedLength each, a ring
    std::size_t followedHead_ = 0, followedCount_ = 0;
    TrailImage image_;
    double lastTime_ = -1.0;
    int frames_ = 0;
};

}  // namespace psb::app
