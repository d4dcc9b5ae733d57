#include "inspector_panel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace psb::app {

std::vector<std::string> inspectorLines(const Particle& p, const EditPrompt& prompt) {
    char buf[160];
    std::vector<std::string> lines;
    const auto line = [&](const char* format, auto... values) {
        std::snprintf(buf, sizeof buf, format, values...);
        lines.emplace_back(buf);
    };
    const Vec2 momentum = p.mass * p.velocity;
    line("Particle %u", p.id.slot);
    line("position  [%.4g, %.4g] m", p.position.x(), p.position.y());
    line("velocity  [%.4g, %.4g] m/s", p.velocity.x(), p.velocity.y());
    line("speed     %.4g m/s", p.velocity.norm());
    line("momentum  [%.4g, %.4g] kg m/s", momentum.x(), momentum.y());
    line("KE        %.4g J", 0.5 * p.mass * p.velocity.squaredNorm());
    line("mass      %.4g kg", p.mass);
    line("radius    %.4g m", p.radius);
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
