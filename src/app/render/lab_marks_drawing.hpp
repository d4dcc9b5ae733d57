#pragma once
// Drawing the measuring marks (view/lab_marks.hpp): the grid's lines, batched to go under the
// discs, and over the world the grid's labels and the ruler (a translucent band with its ticks,
// a handle at each end and its reading).

#include <SDL.h>

#include "render/geometry_batch.hpp"
#include "view/lab_marks.hpp"
#include "view/palette.hpp"

namespace psb::app {

class Font;

/// Appends the grid's lines to `batch` (not cleared), to be drawn with the circle texture.
void batchGridLines(const GridView& grid, GeometryBatch& batch, const Palette& colours);
/// Appends the ruler's band, edge, ticks and handles to `batch` (not cleared), to be drawn with
/// the circle texture.
void batchRuler(const RulerView& ruler, GeometryBatch& batch, const Palette& colours);
/// Lays out the grid's labels and the ruler's reading (either may be null) in `font` into
/// `text` (cleared first), for font.draw.
void layoutMarkLabels(const GridView* grid, const RulerView* ruler, const Font& font,
                      const Palette& colours, GeometryBatch& text);

}  // namespace psb::app
