#pragma once
// Draws a world, read through a const reference, onto any SDL_Renderer: the window's in the
// app, a software renderer over an offscreen surface in the tests.
//
// Each layer is one batched SDL_RenderGeometry call whatever the particle count: discs are
// quads over one anti-aliased circle texture tinted by vertex colour, arrows are untextured
// triangles, labels are glyph quads over the font atlas with their black boxes in one more
// batch. Particles outside the viewport are skipped before any geometry is built.

#include <cstddef>

#include <SDL.h>

#include <particle_sandbox/world.hpp>

#include "camera.hpp"
#include "geometry_batch.hpp"
#include "trails.hpp"

namespace psb::app {

class Font;

/// What to draw besides the discs.
struct ViewOptions {
    bool arrows = true;   ///< velocity arrows
    bool labels = false;  ///< XVel, YVel, Momentum, Mass above each particle
    /// Arrow length per unit speed, seconds: an arrow reaches where the particle will be after
    /// this time. The original drew 20 × the per-frame displacement at 60 fps, i.e. 1/3 s.
    double arrowSeconds = 1.0 / 3.0;
    // Analysis overlays (see docs/app.md, "Seeing the physics").
    bool momentum = false;              ///< V: momentum arrows, centre of mass, Σ m v
    TrailMode trails = TrailMode::Off;  ///< L: path traces
    bool plots = false;                 ///< K: energy, momentum and collision rate against time
    bool speeds = false;                ///< D: speed histogram against Maxwell–Boltzmann
};

/// An arrow scale for `world` (seconds, see ViewOptions::arrowSeconds): the original's 1/3 s,
/// shortened when that would make the root-mean-square arrow longer than a fifth of the box or
/// three quarters of the mean spacing between particles (a dense gas would be hidden under its
/// arrows).
[[nodiscard]] double arrowSecondsFor(const World& world);

/// What the last draw() did, for the HUD.
struct DrawStats {
    std::size_t drawn = 0;          ///< particles inside the viewport
    std::size_t labelled = 0;       ///< particles that got labels
    bool labelsSuppressed = false;  ///< too many particles on screen for labels
};

class Renderer {
  public:
    /// Above this many particles on screen, labels are not drawn (they would cover the view).
    static constexpr std::size_t kMaxLabels = 400;

    /// `labelFont` may be null (then labels are never drawn). Throws std::runtime_error when
    /// the circle texture cannot be made.
    Renderer(SDL_Renderer* renderer, const Font* labelFont);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Clears to black and draws the box walls, the particles and the enabled overlays. When
    /// `trails` is given they are drawn under the discs as options.trails says, `selected`
    /// naming the particle of TrailMode::Selected.
    DrawStats draw(const World& world, const Camera& camera, const ViewOptions& options,
                   Trails* trails = nullptr, ParticleId selected = kNullParticle);

    /// A translucent disc of `radius` metres at `centre`: where a launched particle will appear.
    void drawGhost(const Camera& camera, const Vec2& centre, double radius);

  private:
    void drawWalls(const World& world, const Camera& camera);
    void drawTrails(const TrailImage& image);

    SDL_Renderer* renderer_;
    const Font* labelFont_;
    SDL_Texture* circle_ = nullptr;
    GeometryBatch discs_, arrows_, labelBoxes_, labelText_;
    GeometryBatch obstacles_;  ///< the world's pegs and segments (obstacle_drawing.hpp)
    SDL_Texture* trailTexture_ = nullptr;  // streaming, the viewport's size
    int trailWidth_ = 0, trailHeight_ = 0;
};

}  // namespace psb::app
