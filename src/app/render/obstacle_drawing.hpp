#pragma once
// Drawing the world's fixed obstacles: pegs as discs, segments as bars with round ends, in one
// batch over the renderer's circle texture.

#include <SDL.h>

#include <particle_sandbox/world.hpp>

#include "render/geometry_batch.hpp"
#include "session/camera.hpp"
#include "view/palette.hpp"

namespace psb::app {

/// Appends every obstacle of `world` to `batch` (cleared first), at least a pixel wide so that a
/// thin wall never vanishes when zoomed out. `batch` is drawn with the circle texture: discs
/// use the whole texture, bars its opaque centre.
void batchObstacles(const World& world, const Camera& camera, GeometryBatch& batch,
                    const Palette& colours = palette(Theme::Dark));
/// Appends one obstacle to `batch` in `color` (not cleared): the selected obstacle's highlight,
/// the preview of one being drawn.
void batchObstacle(const Obstacle& obstacle, const Camera& camera, SDL_Color color,
                   GeometryBatch& batch);

}  // namespace psb::app
