#pragma once
// Draws a world, read through a const reference, onto any SDL_Renderer: the window's in the
// app, a software renderer over an offscreen surface in the tests.
//
// Each layer is one batched SDL_RenderGeometry call whatever the particle count: discs are
// quads over one anti-aliased circle texture tinted by vertex colour (with the spoke of each
// turning disc, spin_mark.hpp, in a world that keeps rotation), arrows are untextured
// triangles, labels are glyph quads over the font atlas with their black boxes in one more
// batch. Particles outside the viewport are skipped before any geometry is built.
//
// Discs a few pixels across are not worth two triangles each: SDL's software rasteriser pays a
// fixed price per triangle (0.25-0.5 us), which at 5·10⁴ particles is most of a frame. They are
// written as pixels into one image with their arrows as one-pixel lines (the trails' method),
// and the image is shown with one texture copy.

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <SDL.h>

#include <particle_sandbox/world.hpp>

#include "render/geometry_batch.hpp"
#include "render/trails.hpp"
#include "session/camera.hpp"
#include "session/view_options.hpp"
#include "view/label_places.hpp"
#include "view/mass_shade.hpp"
#include "view/palette.hpp"
#include "view/periodic_box.hpp"

namespace psb::app {

class Font;

/// Screen rectangles labels keep clear of (the HUD and the panels), pixels.

/// What the last draw() did, for the HUD.
struct DrawStats {
    std::size_t drawn = 0;          ///< particles inside the viewport
    std::size_t labelled = 0;       ///< particles that got labels
    std::size_t labelsCrowded = 0;  ///< particles whose label found no free place
    /// Particles whose label has no side inside the window at all (a disc nearly the window's
    /// size): left out for want of room in the window, not for other labels.
    std::size_t labelsOffWindow = 0;
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

    /// Clears to the theme's background (options.theme) and draws the box walls, the particles
    /// (in the theme's colours: palette.hpp) and the enabled overlays.
    /// `frame` is the length of the world's steps (the scene's dt): a particle slower than one
    /// step of gravity gives it rests, and has no arrow (restingSpeed). When `trails` is given
    /// they are drawn under the discs as options.trails says, `selected` naming the particle of
    /// TrailMode::Selected. Labels go at whole pixels (glyphs drawn at fractions of a pixel are
    /// resampled into garble), where view/label_places.hpp says: clear of every disc, peg,
    /// other label and rectangle of `avoid`, across no wall of the scene nor of `avoid`; a label
    /// with no such place is left out.
    /// `underlay` (drawn with the circle texture) goes over the walls and obstacles and under
    /// the trails and discs: the grid's lines. `periodic` (a periodic box: view/periodic_box.hpp)
    /// draws the box's edges as its dashes instead of walls, and each of its images as its disc
    /// again (fill, spin mark and arrow; no label) at the offset.
    DrawStats draw(const World& world, double frame, const Camera& camera,
                   const ViewOptions& options, Trails* trails = nullptr,
                   ParticleId selected = kNullParticle, const LabelKeepOut* avoid = nullptr,
                   const GeometryBatch* underlay = nullptr,
                   const PeriodicBoxView* periodic = nullptr);

    /// A translucent disc of `radius` metres at `centre`: where a launched particle will appear.
    void drawGhost(const Camera& camera, const Vec2& centre, double radius,
                   const Palette& colours = palette(Theme::Dark));
    /// Draws `batch` over the circle texture (obstacle shapes: obstacle_drawing.hpp).
    void drawBatch(const GeometryBatch& batch) { batch.draw(renderer_, circle_); }

    /// Discs smaller than this on screen (radius, pixels) and their arrows are drawn as pixels
    /// into one image (see the top of this file).
    static constexpr double kSmallDiscPixels = 2.5;

  private:
    /// A streaming texture the size of an image, and the image copied through it.
    struct ImageLayer {
        SDL_Texture* texture = nullptr;
        int width = 0, height = 0;
    };
    void drawWalls(const World& world, const Camera& camera, const Palette& colours);
    /// A periodic box's edges: its dashes, in the walls' colour.
    void drawDashes(const PeriodicBoxView& box, const Palette& colours);
    void drawImage(const TrailImage& image, ImageLayer& layer);

    SDL_Renderer* renderer_;
    const Font* labelFont_;
    SDL_Texture* circle_ = nullptr;
    GeometryBatch discs_, arrows_, labelBoxes_, labelText_;
    ImageLayer trailLayer_, smallLayer_;
    TrailImage small_;                 ///< discs under kSmallDiscPixels and their arrows
    std::vector<double> arrowLength_;  ///< per visible particle, pixels; 0: none
    std::vector<Vec2> visibleShift_;   ///< per visible particle, metres: an image's offset
    GeometryBatch obstacles_;          ///< the world's pegs and segments (obstacle_drawing.hpp)
    /// Each colour's mass shades (view/mass_shade.hpp) on shadesTheme_, by 0xRRGGBB.
    std::unordered_map<std::uint32_t, MassShades> shades_;
    Theme shadesTheme_ = Theme::Dark;
};

}  // namespace psb::app
