#pragma once
// Drawing the measuring marks (view/lab_marks.hpp): the grid's lines, batched to go under the
// discs, and over the world the grid's labels and the ruler (a translucent band with its ticks,
// a handle at each end and its reading).

#include <SDL.h>

#include "render/geometry_batch.hpp"
#include "view/lab_marks.hpp"

namespace psb::app {

class Font;

/// Colours, for the tests to look for.
inline constexpr SDL_Color kGridColor{55, 66, 84, 255};
inline constexpr SDL_Color kGridStrongColor{84, 100, 126, 255};
inline constexpr SDL_Color kRulerColor{250, 215, 110, 255};

/// Appends the grid's lines to `batch` (not cleared), to be drawn with the circle texture.
void batchGridLines(const GridView& grid, GeometryBatch& batch);
/// Appends the ruler's band, edge, ticks and handles to `batch` (not cleared), to be drawn with
/// the circle texture.
void batchRuler(const RulerView& ruler, GeometryBatch& batch);
/// Lays out the grid's labels and the ruler's reading (either may be null) in `font` into
/// `text` (cleared first), for font.draw.
void layoutMarkLabels(const GridView* grid, const RulerView* ruler, const Font& font,
                      GeometryBatch& text);

}  // namespace psb::app
