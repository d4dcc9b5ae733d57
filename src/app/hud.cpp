#include "hud.hpp"

#include <cstdio>

namespace psb::app {

std::string windowTitle(std::size_t particles, bool paused, const std::string& scene) {
    std::string t = "Particle Sandbox - " + std::to_string(particles) +
                    (particles == 1 ? " particle" : " particles");
    if (paused) t += " - PAUSED";
    if (!scene.empty()) t += " - " + scene;
    return t;
}

std::vector<std::string> hudLines(const HudData& d) {
    char buf[160];
    std::vector<std::string> lines;
    std::snprintf(buf, sizeof buf, "FPS %.0f | step %.2f ms | draw %.2f ms", d.fps, d.stepMs,
                  d.drawMs);
    lines.emplace_back(buf);
    std::snprintf(buf, sizeof buf, "Time %.2f s x%g | %zu particles%s", d.simTime, d.timeScale,
                  d.particles, d.paused ? " | PAUSED" : "");
    lines.emplace_back(buf);
    std::snprintf(buf, sizeof buf, "KE %.4g J | p [%.4g, %.4g] kg m/s", d.kineticEnergy,
                  d.momentum.x(), d.momentum.y());
    lines.emplace_back(buf);
    std::snprintf(buf, sizeof buf, "New: %.0f kg, r %.3g m", d.spawnMass, d.spawnRadius);
    std::string last = buf;
    if (d.arrowSeconds > 0.0) {
        std::snprintf(buf, sizeof buf, " | arrow = %.3g s of motion", d.arrowSeconds);
        last += buf;
    }
    lines.push_back(last + " | H: help");
    return lines;
}

const std::vector<std::pair<std::string, std::string>>& controls() {
    static const std::vector<std::pair<std::string, std::string>> list = {
        {"Left drag on a particle", "grab it; release to fling it"},
        {"Left drag on empty space", "launch a new particle with the drag's velocity"},
        {"Backspace / Delete (holding)", "delete the held particle"},
        {"M", "spawn a random particle"},
        {"[ / ]", "lighter / heavier new particles"},
        {"S", "show / hide labels (velocity, momentum, mass)"},
        {"A", "show / hide velocity arrows"},
        {"Wheel", "zoom about the cursor"},
        {"Arrow keys, right or middle drag", "pan"},
        {"F", "fit the box to the window"},
        {"Space", "pause / resume"},
        {"N", "one step (while paused)"},
        {", / .", "slow down / speed up time"},
        {"P / 1-9", "next preset / preset by number"},
        {"R", "reload the scene"},
        {"Ctrl+S", "save the world as a scene"},
        {"H", "show / hide this help"},
        {"Esc", "quit"},
    };
    return list;
}

std::vector<std::string> helpLines() {
    std::vector<std::string> lines{"Controls", ""};
    std::size_t width = 0;
    for (const auto& [keys, what] : controls())
        width = std::max(width, keys.size());
    for (const auto& [keys, what] : controls()) {
        lines.push_back(keys + std::string(width + 3 - keys.size(), ' ') + what);
    }
    return lines;
}

}  // namespace psb::app
