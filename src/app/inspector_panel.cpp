#include "inspector_panel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "units.hpp"

namespace psb::app {

std::vector<std::string> inspectorLines(const Particle& p, const EditPrompt& prompt) {
    char buf[160];
    std::vector<std::string> lines;
    const auto line = [&](const char* format, auto... values) {
        std::snprintf(buf, sizeof buf, format, values...);
        lines.emplace_back(buf);
    };
    const Vec2 momentum = p.mass * p.velocity;
    const auto n = [](double v) { return quantity(v, "", false); };  // "-40 400", "0.00200"
    const auto pair = [&](const char* name, const Vec2& v, const char* unit) {
        lines.push_back(std::string(name) + "(" + n(v.x()) + ", " + n(v.y()) + ") " + unit);
    };
    line("Particle %u", p.id.slot);
    pair("position        ", p.position, "m");
    pair("velocity        ", p.velocity, "m/s");
    lines.push_back("speed           " + quantity(p.velocity.norm(), "m/s", false));
    pair("momentum        ", momentum, "kg m/s");
    lines.push_back("kinetic energy  " + quantity(0.5 * p.mass * p.velocity.squaredNorm(), "J"));
    lines.push_back("mass            " + quantity(p.mass, "kg", false));
    lines.push_back("radius          " + quantity(p.radius, "m"));
    if (!prompt.active() || prompt.target() != p.id) {
        lines.emplace_back("Enter: edit");
        return lines;
    }
    lines.emplace_back("");
    lines.emplace_back("Edit  Tab: next  Enter: apply  Esc: cancel");
    for (int k = 0; k < kEditFields; ++k) {
        const auto f = static_cast<EditField>(k);
        const bool active = f == prompt.field();
        line("%s %-6s %s%s %s", active ? ">" : " ", fieldName(f), prompt.text(f).c_str(),
             active ? "_" : "", fieldUnit(f));
    }
    if (!prompt.error().empty()) lines.push_back("Refused: " + prompt.error());
    return lines;
}

void drawSelectionOutline(SDL_Renderer* renderer, const Camera& camera, const Particle& p) {
    constexpr int kSegments = 64;
    const Vec2 c = camera.worldToScreen(p.position);
    const double rim = camera.toScreen(p.radius);
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_NONE);
    SDL_SetRenderDrawColor(renderer, 255, 230, 0, 255);
    for (const double gap : {3.0, 4.0}) {
        const double r = std::max(rim + gap, 6.0 + gap - 3.0);
        std::array<SDL_FPoint, kSegments + 1> ring{};
        for (int k = 0; k <= kSegments; ++k) {
            const double a = 2.0 * std::numbers::pi * k / kSegments;
            ring[static_cast<std::size_t>(k)] = {static_cast<float>(c.x() + r * std::cos(a)),
                                                 static_cast<float>(c.y() + r * std::sin(a))};
        }
        SDL_RenderDrawLinesF(renderer, ring.data(), kSegments + 1);
    }
}

}  // namespace psb::app
