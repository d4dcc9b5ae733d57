#pragma once
// A periodic box (WorldDef::periodic) as the window draws it: its edges dashed, since they are
// no walls, and each disc that crosses an edge drawn a second time at the opposite edge, where
// the joined edges put the part of it that is over the edge (a disc over a corner four times).
// The view lists the dashes and the images; the drawing layer (render/renderer.hpp) draws them.

#include <cstddef>
#include <optional>
#include <vector>

#include <particle_sandbox/world.hpp>

#include "session/camera.hpp"

namespace psb::app {

/// A disc drawn again at the opposite edge of a periodic box.
struct PeriodicImage {
    std::size_t index = 0;       ///< the particle's storage index in World::particles()
    Vec2 offset = Vec2::Zero();  ///< metres added to its centre: ±width, ±height or both
};

/// One dash of a periodic box's edge, screen pixels, along the edge's line.
struct BoxDash {
    Vec2 from = Vec2::Zero();
    Vec2 to = Vec2::Zero();
};

struct PeriodicBoxView {
    static constexpr double kDashPixels = 10.0;  ///< a dash's length
    static constexpr double kGapPixels = 6.0;    ///< between two dashes
    std::vector<BoxDash> dashes;                 ///< those in the window
    double thickness = 0.0;                      ///< pixels, across the edge
    std::vector<PeriodicImage> images;
};

/// The images of `world`'s discs that cross an edge of its periodic box, in storage order;
/// none in a box that is not periodic.
[[nodiscard]] std::vector<PeriodicImage> periodicImages(const World& world);

/// The dashes of the edges of the box [0, width] × [0, height] metres as `camera` shows it:
/// kDashPixels long with kGapPixels between, each edge's first dash at a corner, only those
/// that reach into the window.
[[nodiscard]] std::vector<BoxDash> boxDashes(const Camera& camera, double width, double height);

/// The frame's periodic box, or nullopt for a world whose box is not periodic.
[[nodiscard]] std::optional<PeriodicBoxView> periodicBoxView(const World& world,
                                                             const Camera& camera);

}  // namespace psb::app
