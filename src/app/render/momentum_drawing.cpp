#include "render/momentum_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/sdl_color.hpp"
#include "render/text.hpp"
#include "view/arrow_clip.hpp"

namespace psb::app {
namespace {

SDL_FPoint pt(const Vec2& v) {
    return {static_cast<float>(v.x()), static_cast<float>(v.y())};
}

/// A filled arrow from `a` to `b` (pixels): a shaft `halfWidth` px either side and a head of at
/// most `head` px with ±30° flanks.
void appendArrow(GeometryBatch& batch, const Vec2& a, const Vec2& b, double head, double halfWidth,
                 SDL_Color c, bool cut = false) {
    const Vec2 d = b - a;
    const double len = d.norm();
    if (!(len > 1.0)) return;
    const Vec2 u = d / len, n(-u.y(), u.x());
    if (cut) {
        // Cut at a wall (view/arrow_clip.hpp): up to it, and a bar across its end, no head.
        const double bar = cutBarHalf(head, halfWidth);
        const double thick = std::max(2.0, 2.0 * halfWidth);
        batch.polygon4(pt(a + halfWidth * n), pt(b + halfWidth * n), pt(b - halfWidth * n),
                       pt(a - halfWidth * n), c);
        batch.polygon4(pt(b + bar * n), pt(b + bar * n - thick * u), pt(b - bar * n - thick * u),
                       pt(b - bar * n), c);
        return;
    }
    const double h = std::min(head, len);
    const double hw = h * 0.57735;  // tan 30°
    const Vec2 base = b - h * u;
    batch.triangle(pt(b), pt(base + hw * n), pt(base - hw * n), c);
    if (len > h) {
        batch.polygon4(pt(a + halfWidth * n), pt(base + halfWidth * n), pt(base - halfWidth * n),
                       pt(a - halfWidth * n), c);
    }
}

}  // namespace

void MomentumDrawing::draw(SDL_Renderer* renderer, const Font& font, const World& world,
                           const ObservablesSample& now, const Camera& camera,
                           const TimeSeries& series, double arrowSeconds, const PixelRect& legend,
                           const Palette& colours, const Axes& axes) {
    const SDL_Color each = sdlColor(colours.momentumArrow), sum = sdlColor(colours.totalMomentum);
    const ParticleArrays& p = world.particles();
    arrows_.clear();
    text_.clear();
    const double scale = arrowSeconds / meanMass(p);  // metres per kg·m/s
    const double w = camera.viewportWidth(), h = camera.viewportHeight();
    // In a walled box an arrow reaching past a wall ends there, cut (view/arrow_clip.hpp).
    const bool walled = world.def().walls;
    const Camera::ScreenBox inside = camera.boxOnScreen(world.def().width, world.def().height);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec2 c = camera.worldToScreen(Vec2(p.x[i], p.y[i]));
        const Vec2 tip = camera.worldToScreen(
            Vec2(p.x[i] + scale * p.mass[i] * p.vx[i], p.y[i] + scale * p.mass[i] * p.vy[i]));
        if (std::max(c.x(), tip.x()) < 0 || std::min(c.x(), tip.x()) > w ||
            std::max(c.y(), tip.y()) < 0 || std::min(c.y(), tip.y()) > h) {
            continue;
        }
        const ClippedArrow kept = walled ? clipArrow(c, tip, inside) : ClippedArrow{tip, false};
        appendArrow(arrows_, c, kept.tip, 9.0, 0.75, each, kept.cut);
    }

    // The centre of mass's path, one polyline.
    path_.clear();
    for (std::size_t k = 0; k < series.size(); ++k)
        path_.push_back(pt(camera.worldToScreen(series[k].centreOfMass)));
    const TotalMomentumArrow total = totalMomentumArrow(world, now, arrowSeconds);
    const Vec2 com = camera.worldToScreen(total.from);
    path_.push_back(pt(com));

    // The marker: a ring of four quads around a cross, 7 px, so it reads at every zoom.
    const SDL_Color cm = sdlColor(colours.centreOfMass);
    const float x = static_cast<float>(com.x()), y = static_cast<float>(com.y());
    arrows_.quad(x - 7, y - 1, x + 7, y + 1, cm);
    arrows_.quad(x - 1, y - 7, x + 1, y + 7, cm);
    const ClippedArrow kept = walled ? clipArrow(com, camera.worldToScreen(total.to), inside)
                                     : ClippedArrow{camera.worldToScreen(total.to), false};
    appendArrow(arrows_, com, kept.tip, 16.0, 2.0, sum, kept.cut);

    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_NONE);
    arrows_.draw(renderer, nullptr);
    if (path_.size() >= 2) {
        SDL_SetRenderDrawColor(renderer, cm.r, cm.g, cm.b, 255);
        SDL_RenderDrawLinesF(renderer, path_.data(), static_cast<int>(path_.size()));
    }
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_BLEND);

    if (legend.w <= 0) return;
    // The legend sits in the panel column (see PanelLayout), each line in the colour it names.
    GeometryBatch& box = arrows_;
    box.clear();
    const float lx = static_cast<float>(legend.x), ly = static_cast<float>(legend.y);
    box.quad(lx, ly, lx + static_cast<float>(legend.w), ly + static_cast<float>(legend.h),
             sdlColor(colours.panel));
    box.draw(renderer, nullptr);
    const std::vector<std::string> lines = momentumLegend(world, now, arrowSeconds, axes);
    const SDL_Color colors[3] = {sum, each, cm};
    for (std::size_t k = 0; k < lines.size(); ++k) {
        font.layout(lines[k], lx + 4, ly + 2 + static_cast<float>(k * font.lineHeight()),
                    sdlTextColor(colors[k], colours.panel), text_);
    }
    font.draw(text_);
}

}  // namespace psb::app
