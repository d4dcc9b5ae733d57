#pragma once
// Window pixels as the view lays them out. The view names its own rectangles rather than
// SDL's so that it compiles without SDL; the fields are SDL_Point's and SDL_Rect's, and the
// drawing layer converts where it hands one to SDL (render/sdl_rect.hpp).

namespace psb::app {

/// A point, or a box's size (x wide, y high), in pixels.
struct PixelPoint {
    int x = 0;
    int y = 0;
};

/// A rectangle in pixels: top-left corner (x, y), w wide and h high; w == 0 for none.
struct PixelRect {
    int x = 0;
    int y = 0;
    int w = 0;
    int h = 0;

    friend bool operator==(const PixelRect&, const PixelRect&) = default;
};

}  // namespace psb::app
