#include "hud.hpp"

#include <cmath>
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
    if (d.paused) {
        std::snprintf(buf, sizeof buf, "Paused: redrawn on input | step %.2f ms | draw %.2f ms",
                      d.stepMs, d.drawMs);
    } else {
        std::snprintf(buf, sizeof buf, "FPS %.0f | step %.2f ms | draw %.2f ms", d.fps, d.stepMs,
                      d.drawMs);
    }
    lines.emplace_back(buf);
    if (!d.renderer.empty()) lines.back() += " | " + d.renderer;
    // Below 95 % of the speed asked for, the reached speed is what the user sees.
    char speed[64];
    if (!d.paused && d.reachedTimeScale < 0.95 * d.timeScale) {
        std::snprintf(speed, sizeof speed, "x%.2g of x%g asked (steps too slow)",
                      d.reachedTimeScale, d.timeScale);
    } else {
        std::snprintf(speed, sizeof speed, "x%g", d.timeScale);
    }
    std::snprintf(buf, sizeof buf, "Time %.2f s %s | %zu particles%s", d.simTime, speed,
                  d.particles, d.paused ? " | PAUSED" : "");
    lines.emplace_back(buf);
    std::snprintf(buf, sizeof buf, "KE %.4g J | p [%.4g, %.4g] kg m/s", d.kineticEnergy,
                  d.momentum.x(), d.momentum.y());
    lines.emplace_back(buf);
    std::snprintf(buf, sizeof buf, "Mode %s | %s | %d thread%s", d.mode.c_str(),
                  d.broadphase.c_str(), d.threads, d.threads == 1 ? "" : "s");
    lines.emplace_back(buf);
    if (!d.overlays.empty()) lines.back() += " | on: " + d.overlays;
    std::snprintf(buf, sizeof buf, "Restitution %.2f | gravity %s", d.restitution,
                  d.gravity.c_str());
    lines.emplace_back(buf);
    if (std::isnan(d.keDrift)) {
        std::snprintf(buf, sizeof buf, "Overlap max %.3g m | %s n/a", d.maxOverlap,
                      d.driftName.c_str());
    } else {
        std::snprintf(buf, sizeof buf, "Overlap max %.3g m | %s %+.2e since last action",
                      d.maxOverlap, d.driftName.c_str(), d.keDrift);
    }
    lines.emplace_back(buf);
    std::snprintf(buf, sizeof buf, "New: %.0f kg, r %.3g m", d.spawnMass, d.spawnRadius);
    std::string last = buf;
    if (d.arrowSeconds > 0.0) {
        std::snprintf(buf, sizeof buf, " | arrow: %.3g s of motion", d.arrowSeconds);
        last += buf;
    }
    lines.push_back(last + " | H: help");
    if (d.past) {
        std::snprintf(buf, sizeof buf,
                      "Viewing %.2f s back: Space continues from here, Shift+Left/Right step",
                      d.secondsBack);
        lines.emplace_back(buf);
    }
    return lines;
}

std::vector<std::string> profileLines(const ProfileData& d) {
    const StepProfile& p = d.profile;
    char buf[96];
    std::vector<std::string> lines{"Profile, last step (ms)"};
    const auto row = [&](const char* name, double ms) {
        std::snprintf(buf, sizeof buf, "%-22s %8.3f", name, ms);
        lines.emplace_back(buf);
    };
    // Each mode's stepper names its own stages (step_profile.hpp).
    for (int k = 0; k < p.stageCount; ++k) {
        const std::string name(p.stages[k].name);
        row(name.c_str(), p.stages[k].ms);
    }
    row("total", p.total);
    if (d.mode == StepMode::Exact) {
        std::snprintf(buf, sizeof buf, "%-22s %8.0f", "events per step", d.eventsPerStep);
        lines.emplace_back(buf);
    } else {
        std::snprintf(buf, sizeof buf, "%-22s %8llu", "pairs",
                      static_cast<unsigned long long>(p.pairs));
        lines.emplace_back(buf);
    }
    row("frame: step", d.frameStepMs);
    row("frame: draw", d.frameDrawMs);
    return lines;
}

const std::vector<std::pair<std::string, std::string>>& controls() {
    static const std::vector<std::pair<std::string, std::string>> list = {
        {"Left drag on a particle", "grab it; release to fling it"},
        {"Left drag on empty space", "launch a particle: the drag is its arrow"},
        {"Left click on a particle", "select it: outline and inspector panel"},
        {"Left click on empty space", "clear the selection"},
        {"Enter (selected)", "edit it (Tab: next field, Esc: cancel)"},
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
        {"Shift+Left/Right, PgUp/PgDn", "a frame, a second back / forward in time"},
        {"Ctrl+Z, Ctrl+Shift+Z or Ctrl+Y", "undo / redo the last change"},
        {", / .", "slow down / speed up time"},
        {"P / 1-9", "next preset / preset by number"},
        {"R", "reset the scene to how it was loaded"},
        {"E / Shift+E", "restitution down / up by 0.05"},
        {"G", "gravity on / off"},
        {"T", "next stepping mode: discrete, substep, exact"},
        {"O / F3", "show / hide the profile overlay"},
        {"Ctrl+S", "save the world as a scene"},
        {"V", "momentum view: m v and the total"},
        {"L", "path traces: off / selected particle / all"},
        {"K", "plots: energy, momentum, collision rate over time"},
        {"D", "speed histogram against Maxwell-Boltzmann"},
        {"F12", "save a PNG screenshot"},
        {"H", "show / hide this help"},
        {"Esc", "close help / edit; quit (asks if unsaved)"},
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
