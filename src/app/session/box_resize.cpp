#include "session/box_resize.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <particle_sandbox/diagnostics.hpp>

#include "session/units.hpp"

namespace psb::app {

namespace {

/// Centres and radii, pushed apart in place: one pass over a grid of cells as wide as the
/// largest disc, each overlapping pair moved half the overlap each way along its centres' line
/// (light and heavy alike: a rearrangement, not a collision), then kept inside the walls.
/// Returns the deepest overlap the pass found, metres.
double pushApart(std::vector<Vec2>& at, const std::vector<double>& radius, double width,
                 double height) {
    // Cells at least as wide as the widest disc (so an overlapping pair is in neighbouring
    // cells), and no more of them than about two a disc (tiny discs in a huge box).
    const double cell =
        std::max(2.0 * *std::max_element(radius.begin(), radius.end()),
                 std::sqrt(width * height / (2.0 * static_cast<double>(at.size()))));
    const auto nx = static_cast<std::size_t>(std::max(1.0, std::ceil(width / cell)));
    const auto ny = static_cast<std::size_t>(std::max(1.0, std::ceil(height / cell)));
    std::vector<std::vector<std::size_t>> cells(nx * ny);
    const auto cellOf = [&](const Vec2& p) {
        const auto cx = std::min(nx - 1, static_cast<std::size_t>(std::max(0.0, p.x() / cell)));
        const auto cy = std::min(ny - 1, static_cast<std::size_t>(std::max(0.0, p.y() / cell)));
        return std::pair{cx, cy};
    };
    for (std::size_t i = 0; i < at.size(); ++i) {
        const auto [cx, cy] = cellOf(at[i]);
        cells[cy * nx + cx].push_back(i);
    }
    double deepest = 0.0;
    for (std::size_t i = 0; i < at.size(); ++i) {
        const auto [cx, cy] = cellOf(at[i]);
        for (std::size_t y = cy > 0 ? cy - 1 : 0; y <= std::min(ny - 1, cy + 1); ++y) {
            for (std::size_t x = cx > 0 ? cx - 1 : 0; x <= std::min(nx - 1, cx + 1); ++x) {
                for (const std::size_t j : cells[y * nx + x]) {
                    if (j <= i) continue;
                    const Vec2 d = at[j] - at[i];
                    const double dist = d.norm(), reach = radius[i] + radius[j];
                    if (dist >= reach) continue;
                    deepest = std::max(deepest, reach - dist);
                    const Vec2 n = dist > 0.0 ? Vec2(d / dist) : Vec2(1.0, 0.0);
                    const Vec2 half = 0.5 * (reach - dist) * (1.0 + 1e-9) * n;
                    at[i] -= half;
                    at[j] += half;
                }
            }
        }
    }
    for (std::size_t i = 0; i < at.size(); ++i) {
        at[i] = Vec2(std::clamp(at[i].x(), radius[i], width - radius[i]),
                     std::clamp(at[i].y(), radius[i], height - radius[i]));
    }
    return deepest;
}

}  // namespace

std::variant<World, std::string> resizedBox(const World& world, double width, double height) {
    const ParticleArrays& p = world.particles();
    const double sx = width / world.def().width, sy = height / world.def().height;
    std::vector<Vec2> at(p.size());
    std::vector<double> radius(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double r = p.radius[i];
        if (2.0 * r > width || 2.0 * r > height) {
            std::string why = "particle ";
            why += std::to_string(particleNumber(p.id[i]));
            why += " (";
            why += quantity(2.0 * r, "m");
            why += " across) would not fit";
            return why;
        }
        radius[i] = r;
        at[i] = Vec2(std::clamp(p.x[i] * sx, r, width - r), std::clamp(p.y[i] * sy, r, height - r));
    }
    // Squeezed, discs may come to overlap: pushed apart, until none overlaps more than any did
    // before (a discrete-mode gas may overlap a little already).
    const double allowed =
        (p.size() > 1 ? maxOverlap(world) : 0.0) + 1e-9 * std::min(width, height);
    if (p.size() > 1 && (sx < 1.0 || sy < 1.0)) {
        double deepest = 0.0;
        for (int pass = 0; pass < kSqueezePasses; ++pass) {
            deepest = pushApart(at, radius, width, height);
            if (deepest <= allowed) break;
        }
        if (deepest > allowed) {
            std::string why = "the particles would overlap by up to ";
            why += quantity(deepest, "m");
            why += " (they fill too much of the box: squeeze less)";
            return why;
        }
    }
    World resized = world;
    resized.setBox(width, height);
    for (std::size_t i = 0; i < p.size(); ++i)
        resized.setPosition(p.id[i], at[i]);
    if (p.size() > 1 && maxOverlap(resized) > allowed) {
        return std::string(
            "the particles would overlap (they fill too much of the box: squeeze "
            "less)");
    }
    return resized;
}

}  // namespace psb::app
