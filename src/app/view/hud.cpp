#include "view/hud.hpp"

#include <cmath>
#include <cstdio>

#include "session/units.hpp"

namespace psb::app {

std::string windowTitle(std::size_t particles, bool paused, const std::string& scene,
                        bool unsaved) {
    // The unsaved mark first, as document programs put it, where a cut-off title keeps it.
    std::string t = std::string(unsaved ? "* " : "") + "Particle Sandbox - " +
                    std::to_string(particles) + (particles == 1 ? " particle" : " particles");
    if (paused) t += " - PAUSED";
    if (!scene.empty()) t += " - " + scene;
    if (unsaved) t += " (unsaved changes)";
    return t;
}

std::string foldedChartsNote(bool controlsOpen, bool touch, bool narrow) {
    if (narrow) {
        if (!controlsOpen) return "Charts: no room (widen the window)";
        return touch ? "Charts: no room (<< folds the controls)"
                     : "Charts: no room (C folds the controls)";
    }
    if (!controlsOpen) return "Charts folded away: no room beside the box (widen the window)";
    return touch ? "Charts folded away: no room beside the box (<< folds the controls)"
                 : "Charts folded away: no room beside the box (C folds the controls)";
}

std::string labelsLeftOutNote(std::size_t count, bool offWindow, bool narrow) {
    if (narrow) {
        return "Labels: " + std::to_string(count) +
               (offWindow ? " left out (zoom out)" : " left out (zoom in)");
    }
    return "Labels: " + std::to_string(count) +
           (offWindow ? " left out: no room beside the disc in the window (zoom out)"
                      : " left out where they would overlap (zoom in)");
}

namespace {

/// The HUD's first line: the time, the speed (`speed`), the particles, paused, and `rec`. A video
/// says a past frame's time on it: a line that came and went would move what stands below the
/// HUD mid-clip.
std::string timeLine(const HudData& d, const char* speed, const char* rec) {
    char back[48] = "";
    if (d.forVideo && d.past) std::snprintf(back, sizeof back, " (%.2f s back)", d.secondsBack);
    char buf[200];
    std::snprintf(buf, sizeof buf, "Time %s%s | %s | %zu particle%s%s%s",
                  quantity(d.simTime, "s").c_str(), back, speed, d.particles,
                  d.particles == 1 ? "" : "s", d.paused ? " | PAUSED" : "", rec);
    return buf;
}

/// hudLines in a narrow window: the readings in short words; nothing of a launch or the help.
std::vector<std::string> narrowHudLines(const HudData& d) {
    char buf[200];
    std::vector<std::string> lines;
    char speed[64];
    if (!d.paused && d.reachedTimeScale < 0.95 * d.timeScale) {
        std::snprintf(speed, sizeof speed, "x%.2g of x%g", d.reachedTimeScale, d.timeScale);
    } else {
        std::snprintf(speed, sizeof speed, "x%g", d.timeScale);
    }
    lines.push_back(timeLine(d, speed, d.recording && !d.forVideo ? " | REC" : ""));
    std::snprintf(
        buf, sizeof buf, "KE %s | p (%s, %s) kg m/s", quantity(d.kineticEnergy, "J").c_str(),
        quantity(d.momentum.x(), "", false).c_str(), quantity(d.momentum.y(), "", false).c_str());
    lines.emplace_back(buf);
    if (d.heaviestMass > d.lightestMass) {
        std::snprintf(buf, sizeof buf, "Darker: heavier (%s to %s)",
                      quantity(d.lightestMass, "", false).c_str(),
                      quantity(d.heaviestMass, "kg", false).c_str());
        lines.emplace_back(buf);
    }
    if (d.overlap > 0.0) {
        std::snprintf(buf, sizeof buf, "Overlap: up to %s", quantity(d.overlap, "m").c_str());
        lines.emplace_back(buf);
    }
    if (d.past && !d.forVideo) {
        std::snprintf(buf, sizeof buf,
                      d.touch ? "%.2f s back: Play continues" : "%.2f s back: Space continues",
                      d.secondsBack);
        lines.emplace_back(buf);
    }
    return lines;
}

}  // namespace

std::vector<std::string> hudLines(const HudData& d) {
    if (d.narrow) return narrowHudLines(d);
    char buf[200];
    std::vector<std::string> lines;
    // Below 95 % of the speed asked for, the reached speed is what the user sees.
    char speed[64];
    if (!d.paused && d.reachedTimeScale < 0.95 * d.timeScale) {
        std::snprintf(speed, sizeof speed, "x%.2g of x%g asked (too much to compute)",
                      d.reachedTimeScale, d.timeScale);
    } else {
        std::snprintf(speed, sizeof speed, "x%g", d.timeScale);
    }
    lines.push_back(timeLine(d, speed,
                             !d.recording || d.forVideo ? ""
                             : d.touch                  ? " | REC (Data: Stop recording)"
                                                        : " | REC (X stops)"));
    std::snprintf(buf, sizeof buf, "Kinetic energy %s | momentum (%s, %s) kg m/s",
                  quantity(d.kineticEnergy, "J").c_str(),
                  quantity(d.momentum.x(), "", false).c_str(),
                  quantity(d.momentum.y(), "", false).c_str());
    lines.emplace_back(buf);
    if (d.forVideo) {
        // What the arrows mean is a reading; what a launch would make and the help are not.
        if (d.arrowSeconds > 0.0) {
            std::snprintf(buf, sizeof buf, "Arrows: %.3g s of motion", d.arrowSeconds);
            lines.emplace_back(buf);
        }
    } else {
        std::snprintf(buf, sizeof buf, "New: %s, %s", quantity(d.spawnMass, "kg", false).c_str(),
                      quantity(d.spawnRadius, "m", false).c_str());
        std::string last = buf;
        if (d.arrowSeconds > 0.0) {
            std::snprintf(buf, sizeof buf, " | arrow: %.3g s of motion", d.arrowSeconds);
            last += buf;
        }
        lines.push_back(last + (d.touch ? " | help: the panel's Keys" : " | H: help"));
    }
    if (d.heaviestMass > d.lightestMass) {
        // The shading's key, where the discs are: without it a deeper shade reads as a team.
        std::snprintf(buf, sizeof buf, "Darker discs are heavier (%s to %s)",
                      quantity(d.lightestMass, "", false).c_str(),
                      quantity(d.heaviestMass, "kg", false).c_str());
        lines.emplace_back(buf);
    }
    if (d.overlap > 0.0) {
        std::snprintf(buf, sizeof buf, "Particles overlap by up to %s (real ones would not)",
                      quantity(d.overlap, "m").c_str());
        lines.emplace_back(buf);
    }
    if (d.past && !d.forVideo) {
        std::snprintf(buf, sizeof buf,
                      d.touch
                          ? "Viewing %.2f s back: Play continues from here, < Back and Fwd > step"
                          : "Viewing %.2f s back: Space continues from here, Shift+Left/Right step",
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

namespace {

using Controls = std::vector<std::pair<std::string, std::string>>;

/// The page's list: the window's with what a page does differently. The keys a browser keeps
/// for itself (Ctrl+N a window, Ctrl+T a tab, Ctrl+plus, minus and 0 its zoom) never reach
/// the page: their lines name the panel's control instead.
Controls pageControls(const Controls& window) {
    Controls list;
    for (const auto& [keys, what] : window) {
        if (keys == "Ctrl+R") continue;  // video recording is desktop-only
        if (keys == "Ctrl+N") {
            list.emplace_back("Scene: New scene...", "an empty box");
        } else if (keys == "Ctrl+plus / minus / 0") {
            list.emplace_back("Show: UI scale, Auto", "bigger / smaller UI, automatic size");
        } else if (keys == "Ctrl+T") {
            list.emplace_back("Show: Light", "theme: dark / light, for a projector");
        } else if (keys == "Esc") {
            list.emplace_back(keys, "close a dialog, the help or the edit prompt");
        } else {
            list.emplace_back(keys, what);
        }
    }
    return list;
}

}  // namespace

const std::vector<std::pair<std::string, std::string>>& controls(bool inPage) {
    // Each line says where its button is in the control panel (the column at the left).
    static const Controls list = {
        {"Left drag on a particle", "grab it; release to fling it (panel: Tools)"},
        {"Left drag on empty space", "launch a particle: the drag is its arrow (Tools)"},
        {"Left click on a particle", "select it (panel: Selected particle)"},
        {"Left click on empty space", "clear the selection"},
        {"Left click on a wall or peg", "select it (Delete removes it; Select tool: drag)"},
        {"Enter (selected)", "edit it here (Tab: next field, Esc: cancel)"},
        {"Backspace / Delete", "delete the held or selected particle, or the selected wall or peg"},
        {"W / B", "draw walls / place pegs; again: back to Fling (Tools)"},
        {"M", "spawn a random particle"},
        {"X", "record the selected (or every) particle's path and collisions (Data)"},
        {"Ctrl+R", "record a video of the box / stop and save it (Video: Record video)"},
        {"[ / ]", "smaller / bigger new particles (Tools)"},
        {"S", "show / hide labels (Show)"},
        {"A", "show / hide velocity arrows (Show)"},
        {"Wheel", "zoom about the cursor"},
        {"Arrow keys, right or middle drag", "pan (Tools: Pan)"},
        {"F", "fit the box to the window"},
        {"Space", "pause / resume (Time: Play, Pause)"},
        {"U / Shift+U", "stopwatch start, stop / lap, reset: simulated time (Time)"},
        {"N", "one step while paused (Time: Step)"},
        {"Shift+Left/Right, PgUp/PgDn", "a frame, a second back / forward in time (Time)"},
        {"Ctrl+Z, Ctrl+Shift+Z or Ctrl+Y", "undo / redo the last change (Time: Undo, Redo)"},
        {", / .", "slow down / speed up time (Time: Speed)"},
        {"P / 1-9, 0, Shift+1-4", "next preset / preset 1-9, 10, 11-14 (Scene)"},
        {"R", "restart: back to the set-up Play last started (Time: Restart)"},
        {"E / Shift+E", "restitution down / up by 0.05 (Physics)"},
        {"G", "gravity on / off (Physics)"},
        {"Shift+G", "grid of metres over the box (Show)"},
        {"Q", "ruler: drag its ends or its edge (Show)"},
        {"T", "next mode: discrete, substeps, exact (Physics)"},
        {"O / F3", "profile beside the box (Engine)"},
        {"Ctrl+S / Ctrl+Shift+S", "save the scene / save it under a new name (Scene)"},
        {"Ctrl+N", "new scene: an empty box (Scene: New)"},
        {"V", "momentum and centre of mass (Show)"},
        {"L", "trails: off / selected particle / all (Show)"},
        {"K", "plots of energy, momentum, collisions (Show)"},
        {"D", "speed histogram (Show)"},
        {"J", "last collision card: before and after, momentum, energy (Show)"},
        {"I", "values table: every particle's x, v, p, energy, totals (Show)"},
        {"C", "open / fold the control panel"},
        {"Tab", "keys to the panel: Tab, arrows move, Space presses; Esc: keys back"},
        {"Ctrl+plus / minus / 0", "bigger / smaller UI, automatic size (Show: UI scale)"},
        {"Ctrl+T", "theme: dark / light, for a projector (Show: Light)"},
        {"F12", "save a PNG screenshot"},
        {"H", "show / hide this help"},
        {"Esc", "close a dialog, help, edit; else ask to quit"},
    };
    static const Controls page = pageControls(list);
    return inPage ? page : list;
}

std::vector<std::string> helpLines(bool inPage) {
    std::vector<std::string> lines{"Controls", ""};
    std::size_t width = 0;
    for (const auto& [keys, what] : controls(inPage))
        width = std::max(width, keys.size());
    for (const auto& [keys, what] : controls(inPage)) {
        lines.push_back(keys + std::string(width + 3 - keys.size(), ' ') + what);
    }
    return lines;
}

}  // namespace psb::app
