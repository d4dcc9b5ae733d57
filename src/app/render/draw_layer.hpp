#pragma once
// The drawing layer: the only code that calls SDL's drawing functions. It draws a FrameView,
// in this order: the world (walls, trails, discs, arrows, labels; renderer.hpp), the bins the
// scene counts marked on the board (bin_marks.hpp), the droppers, the selection ring, the selected
// obstacle and the obstacle tool's preview, the analysis overlays (analysis_overlays.hpp), the
// grid's labels and the ruler (lab_marks_drawing.hpp; the grid's lines go under the discs), the
// launch preview, the marker of an off-screen box, then the text panels (overlay_drawing.hpp). The
// files it calls (renderer, text, overlay_drawing, analysis_overlays, momentum_drawing, plot_chart,
// speed_chart, bin_chart, selection_outline, geometry_batch) are its parts and are called from
// nowhere else.
//
// It keeps what drawing caches between frames: the circle texture, the glyph atlases (in the
// fonts), the trails' history and raster, the plots' buffers.

#include <cstdint>

#include <SDL.h>

#include "render/analysis_overlays.hpp"
#include "render/bin_marks.hpp"
#include "render/renderer.hpp"
#include "render/trails.hpp"
#include "view/frame_view.hpp"

namespace psb::app {

class Font;

class DrawLayer {
  public:
    /// Throws std::runtime_error when the Renderer's textures cannot be made.
    DrawLayer(SDL_Renderer* renderer, const Font& hudFont, const Font& labelFont);

    /// Draws `frame` into the renderer's back buffer (the caller presents it).
    DrawStats draw(const FrameView& frame);
    /// The recording mark (a red dot and its label), drawn after the frame is captured for the
    /// video so that the video does not show it.
    void drawRecordingMark(const RecordingMarkView& mark);
    /// The messages and the HUD's key hints of a frame that waits for the capture (Overlays::
    /// messagesAfterCapture): drawn after the video has taken the frame.
    void drawMessagesAfterCapture(const FrameView& frame);

  private:
    void drawLaunch(const Camera& camera, const LaunchPreviewView& launch, const Palette& colours);
    void drawBoxMarker(const BoxMarkerView& marker, const Palette& colours);
    void drawDropper(const Camera& camera, const DropperView& dropper, const Palette& colours);
    /// The selected obstacle highlighted and the tool's preview, over the world.
    void drawObstacleMarks(const Camera& camera, const FrameView& frame);
    /// The grid's labels and the ruler (lab_marks_drawing.hpp), over the world.
    void drawLabMarks(const FrameView& frame, const Palette& colours);

    SDL_Renderer* sdl_;
    const Font& hudFont_;
    const Font& labelFont_;
    Renderer renderer_;
    AnalysisOverlays analysis_;
    BinMarks binMarks_;
    Trails trails_;
    std::uint64_t trailsGeneration_ = 0;
    GeometryBatch text_;
    GeometryBatch obstacleMarks_;
    GeometryBatch gridLines_, rulerMarks_;
};

}  // namespace psb::app
