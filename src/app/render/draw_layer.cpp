#include "render/draw_layer.hpp"

#include <algorithm>
#include <cmath>

#include "render/lab_marks_drawing.hpp"
#include "render/obstacle_drawing.hpp"
#include "render/overlay_drawing.hpp"
#include "render/sdl_color.hpp"
#include "render/sdl_rect.hpp"
#include "render/selection_outline.hpp"
#include "render/text.hpp"

namespace psb::app {

DrawLayer::DrawLayer(SDL_Renderer* renderer, const Font& hudFont, const Font& labelFont)
    : sdl_(renderer), hudFont_(hudFont), labelFont_(labelFont), renderer_(renderer, &labelFont) {}

DrawStats DrawLayer::draw(const FrameView& frame) {
    const World& world = *frame.world;
    const Camera& camera = *frame.camera;
    // Trails follow particles by id: a new scene, or trails switched off, starts them over.
    if (frame.sceneGeneration != trailsGeneration_ || frame.view.trails == TrailMode::Off) {
        trails_.reset();
        trailsGeneration_ = frame.sceneGeneration;
    }
    if (frame.view.trails == TrailMode::Selected) trails_.follow(frame.trailParticle);
    if (frame.view.trails != TrailMode::Off) trails_.update(world);

    const LabelKeepOut avoid = labelKeepOut(frame, labelFont_);
    const Palette& colours = palette(frame.view.theme);
    gridLines_.clear();
    if (frame.grid) batchGridLines(*frame.grid, gridLines_, colours);
    const DrawStats stats =
        renderer_.draw(world, frame.frameLength, camera, frame.view, &trails_, frame.trailParticle,
                       &avoid, &gridLines_, frame.periodic ? &*frame.periodic : nullptr);
    if (frame.bins) {
        binMarks_.draw(sdl_, labelFont_, camera, frame.bins->bins, world.def().height, colours);
    }
    for (const DropperView& d : frame.droppers)
        drawDropper(camera, d, colours);
    if (frame.selected) {
        drawSelectionOutline(sdl_, camera, *frame.selected, colours);
        for (const Vec2& offset : frame.selectedImages) {
            Particle image = *frame.selected;
            image.position += offset;
            drawSelectionOutline(sdl_, camera, image, colours);
        }
    }
    if (frame.selectedObstacle || frame.obstaclePreview) drawObstacleMarks(camera, frame);
    analysis_.draw(sdl_, labelFont_, world, frame.now, camera, *frame.series, frame.rateWindow,
                   frame.view, frame.layout, frame.bins);
    if (frame.grid || frame.ruler) drawLabMarks(frame, colours);
    if (frame.launch) drawLaunch(camera, *frame.launch, colours);
    if (frame.boxMarker) drawBoxMarker(*frame.boxMarker, colours);
    drawOverlays(sdl_, hudFont_, frame.overlays, frame.layout, colours);
    return stats;
}

void DrawLayer::drawLabMarks(const FrameView& frame, const Palette& colours) {
    if (frame.grid && !frame.grid->labels.empty()) {
        // A plate behind each of the grid's numbers, so that they read over the discs.
        rulerMarks_.clear();
        for (const PixelRect& r : gridLabelPlates(*frame.grid, labelFont_)) {
            rulerMarks_.quad(static_cast<float>(r.x), static_cast<float>(r.y),
                             static_cast<float>(r.x + r.w), static_cast<float>(r.y + r.h),
                             sdlColor(colours.labelBox), 0.5f, 0.5f, 0.5f, 0.5f);
        }
        renderer_.drawBatch(rulerMarks_);
    }
    if (frame.ruler) {
        rulerMarks_.clear();
        batchRuler(*frame.ruler, rulerMarks_, colours);
        // A box behind the reading, so that it reads over discs and their labels.
        const PixelRect r = labelRect(frame.ruler->label, labelFont_, kReadingPad);
        rulerMarks_.quad(static_cast<float>(r.x), static_cast<float>(r.y),
                         static_cast<float>(r.x + r.w), static_cast<float>(r.y + r.h),
                         sdlColor(colours.labelBox), 0.5f, 0.5f, 0.5f, 0.5f);
        renderer_.drawBatch(rulerMarks_);
    }
    layoutMarkLabels(frame.grid ? &*frame.grid : nullptr, frame.ruler ? &*frame.ruler : nullptr,
                     labelFont_, colours, text_);
    labelFont_.draw(text_);
}

void DrawLayer::drawLaunch(const Camera& camera, const LaunchPreviewView& launch,
                           const Palette& colours) {
    // The ghost disc where the particle will appear and the velocity arrow it will have.
    const Vec2 a = camera.worldToScreen(launch.from);
    const Vec2 b = camera.worldToScreen(launch.to);
    setDrawColor(sdl_, colours.launchArrow);
    SDL_RenderDrawLineF(sdl_, static_cast<float>(a.x()), static_cast<float>(a.y()),
                        static_cast<float>(b.x()), static_cast<float>(b.y()));
    renderer_.drawGhost(camera, launch.from, launch.radius, colours);
    text_.clear();
    labelFont_.layout(launch.label, static_cast<float>(b.x() + 8.0),
                      static_cast<float>(b.y() - labelFont_.lineHeight() / 2),
                      sdlColor(colours.text), text_);
    labelFont_.draw(text_);
}

void DrawLayer::drawDropper(const Camera& camera, const DropperView& d, const Palette& colours) {
    const SDL_Color spout = sdlColor(colours.dropper);
    // A spout: a funnel narrowing down to just above where a ball starts; its words to the
    // where the view placed them (beside it in the box: dropper_mark.hpp).
    const DropperSpout s = dropperSpout(camera, d);
    const auto pt = [&spout](double x, double y) {
        return SDL_Vertex{{static_cast<float>(x), static_cast<float>(y)}, spout, {0.f, 0.f}};
    };
    const SDL_Vertex quad[4] = {pt(s.x - s.high, s.top), pt(s.x + s.high, s.top),
                                pt(s.x + s.low, s.bottom), pt(s.x - s.low, s.bottom)};
    const int indices[6] = {0, 1, 2, 0, 2, 3};
    SDL_RenderGeometry(sdl_, nullptr, quad, 4, indices, 6);
    text_.clear();
    for (std::size_t k = 0; k < d.words.lines.size(); ++k) {
        labelFont_.layout(
            d.words.lines[k], static_cast<float>(d.words.at.x),
            static_cast<float>(d.words.at.y + static_cast<int>(k) * labelFont_.lineHeight()),
            sdlColor(colours.dropperText), text_);
    }
    labelFont_.draw(text_);
}

void DrawLayer::drawObstacleMarks(const Camera& camera, const FrameView& frame) {
    const Palette& colours = palette(frame.view.theme);
    obstacleMarks_.clear();
    // The selection's yellow, as the selected particle's ring; the preview a dim ghost.
    if (frame.selectedObstacle) {
        batchObstacle(*frame.selectedObstacle, camera, sdlColor(colours.highlight), obstacleMarks_);
    }
    if (frame.obstaclePreview) {
        // Opaque: a translucent capsule would show its caps' overlap with the bar.
        batchObstacle(*frame.obstaclePreview, camera, sdlColor(colours.preview), obstacleMarks_);
    }
    renderer_.drawBatch(obstacleMarks_);
    if (frame.wallAngle) {
        text_.clear();
        const MarkLabel& l = *frame.wallAngle;
        const int w = labelFont_.measure(l.text);
        labelFont_.layout(l.text, std::round(static_cast<float>(l.at.x()) - 0.5f * w),
                          std::round(static_cast<float>(l.at.y()) - 0.5f * labelFont_.lineHeight()),
                          sdlColor(colours.text), text_);
        labelFont_.draw(text_);
    }
}

void DrawLayer::drawBoxMarker(const BoxMarkerView& m, const Palette& colours) {
    const SDL_Color mark = sdlColor(colours.highlight);
    // A filled arrow head pointing to the box, with its label beside it.
    const Vec2 u = m.direction, n(-u.y(), u.x());
    const Vec2 tip = m.at + 12.0 * u, base = m.at - 6.0 * u;
    const auto pt = [&mark](const Vec2& v) {
        return SDL_Vertex{{static_cast<float>(v.x()), static_cast<float>(v.y())}, mark, {0.f, 0.f}};
    };
    const SDL_Vertex tri[3] = {pt(tip), pt(base + 8.0 * n), pt(base - 8.0 * n)};
    SDL_RenderGeometry(sdl_, nullptr, tri, 3, nullptr, 0);
    const int w = hudFont_.measure(m.label);
    // The label beside the arrow on the screen's side, clear of it, kept inside the window.
    const double half =
        std::abs(u.x()) * (w / 2.0 + 4.0) + std::abs(u.y()) * (hudFont_.lineHeight() / 2.0 + 4.0);
    const Vec2 at = m.at - (14.0 + half) * u;
    float x = static_cast<float>(at.x()) - static_cast<float>(w) / 2.f;
    float y = static_cast<float>(at.y()) - static_cast<float>(hudFont_.lineHeight()) / 2.f;
    int vw = 0, vh = 0;
    SDL_GetRendererOutputSize(sdl_, &vw, &vh);
    x = std::clamp(x, 4.f, static_cast<float>(vw - w - 4));
    y = std::clamp(y, 4.f, static_cast<float>(vh - hudFont_.lineHeight() - 4));
    text_.clear();
    hudFont_.layout(m.label, x, y, mark, text_);
    hudFont_.draw(text_);
}

}  // namespace psb::app

namespace psb::app {

void DrawLayer::drawMessagesAfterCapture(const FrameView& frame) {
    if (!frame.overlays.messagesAfterCapture) return;
    drawMessages(sdl_, hudFont_, frame.overlays, frame.layout, palette(frame.view.theme));
}

void DrawLayer::drawRecordingMark(const RecordingMarkView& mark) {
    // A dark plate, a red dot at its left and the label in red: read over any scene.
    // Its box holds the dot and the text (frame_view.cpp sizes it; the layout places it).
    const PixelRect& r = mark.at;
    if (r.w <= 0) return;
    const int dot = hudFont_.lineHeight() / 2;
    const SDL_Rect plate = sdlRect(r);
    SDL_SetRenderDrawBlendMode(sdl_, SDL_BLENDMODE_BLEND);
    SDL_SetRenderDrawColor(sdl_, 20, 20, 24, 220);
    SDL_RenderFillRect(sdl_, &plate);
    const SDL_Rect red{plate.x + 5, r.y + (r.h - dot) / 2, dot, dot};
    SDL_SetRenderDrawColor(sdl_, 235, 60, 50, 255);
    SDL_RenderFillRect(sdl_, &red);
    text_.clear();
    hudFont_.layout(mark.label, static_cast<float>(r.x + dot + 6 + 4), static_cast<float>(r.y + 4),
                    SDL_Color{255, 110, 100, 255}, text_);
    hudFont_.draw(text_);
}

}  // namespace psb::app
