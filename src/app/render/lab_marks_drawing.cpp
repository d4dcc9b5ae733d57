#include "render/lab_marks_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "render/sdl_color.hpp"
#include "render/text.hpp"

namespace psb::app {

namespace {

SDL_FPoint point(const Vec2& v) {
    return {static_cast<float>(v.x()), static_cast<float>(v.y())};
}

/// A line `width` pixels wide from a to b, solid (the circle texture's opaque centre).
void line(GeometryBatch& batch, const Vec2& a, const Vec2& b, double width, SDL_Color color) {
    const Vec2 d = b - a;
    const double length = d.norm();
    if (!(length > 0.0) || !std::isfinite(length)) return;
    const Vec2 side = Vec2(-d.y(), d.x()) * (0.5 * width / length);
    batch.polygon4(point(a + side), point(b + side), point(b - side), point(a - side), color,
                   SDL_FPoint{0.5f, 0.5f});
}

/// Each of its lines centred on its place (or from its left), the block centred on it.
void label(const MarkLabel& l, const Font& font, SDL_Color color, GeometryBatch& text) {
    std::vector<std::string> lines;
    for (std::size_t from = 0; from <= l.text.size();) {
        const std::size_t end = std::min(l.text.find('\n', from), l.text.size());
        lines.push_back(l.text.substr(from, end - from));
        from = end + 1;
    }
    const int lh = font.lineHeight();
    const float top = std::round(static_cast<float>(l.at.y()) -
                                 0.5f * static_cast<float>(lh * static_cast<int>(lines.size())));
    for (std::size_t k = 0; k < lines.size(); ++k) {
        const int w = font.measure(lines[k]);
        const float x = std::round(static_cast<float>(l.at.x()) - (l.left ? 0.f : 0.5f * w));
        font.layout(lines[k], x, top + static_cast<float>(lh * static_cast<int>(k)), color, text);
    }
}

}  // namespace

void batchGridLines(const GridView& grid, GeometryBatch& batch, const Palette& colours) {
    for (const MarkLine& l : grid.lines) {
        line(batch, l.a, l.b, l.strong ? 1.5 : 1.0,
             sdlColor(l.strong ? colours.gridStrong : colours.grid));
    }
}

void batchRuler(const RulerView& r, GeometryBatch& batch, const Palette& colours) {
    const SDL_Color edge = sdlColor(colours.ruler);
    const Vec2 d = r.b - r.a;
    const double length = d.norm();
    if (length > 0.0 && std::isfinite(length)) {
        // The band lies on the ticks' side of the edge, as a ruler's face does.
        const Vec2 n = Vec2(-d.y(), d.x()) / length;
        const SDL_Color face = sdlColor(colours.ruler, 60);
        batch.polygon4(point(r.a), point(r.b), point(r.b + 14.0 * n), point(r.a + 14.0 * n), face,
                       SDL_FPoint{0.5f, 0.5f});
        line(batch, r.a, r.b, 1.5, edge);
        for (const MarkLine& t : r.ticks)
            line(batch, t.a, t.b, t.strong ? 1.5 : 1.0, edge);
    }
    // The handles: a disc at each end, white while held.
    const SDL_Color handle = r.held ? sdlColor(colours.text) : edge;
    for (const Vec2& end : {r.a, r.b}) {
        const auto x = static_cast<float>(end.x()), y = static_cast<float>(end.y());
        batch.quad(x - 5.f, y - 5.f, x + 5.f, y + 5.f, handle);
    }
}

void layoutMarkLabels(const GridView* grid, const RulerView* ruler, const Font& font,
                      const Palette& colours, GeometryBatch& text) {
    text.clear();
    if (grid != nullptr) {
        for (const MarkLabel& l : grid->labels)
            label(l, font, sdlColor(colours.tickText), text);
    }
    if (ruler != nullptr) label(ruler->label, font, sdlColor(colours.ruler), text);
}

}  // namespace psb::app
