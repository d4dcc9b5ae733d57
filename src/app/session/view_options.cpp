#include "session/view_options.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace psb::app {

TrailMode nextTrailMode(TrailMode mode) {
    switch (mode) {
        case TrailMode::Off:
            return TrailMode::Selected;
        case TrailMode::Selected:
            return TrailMode::All;
        case TrailMode::All:
            break;
    }
    return TrailMode::Off;
}

const char* toString(TrailMode mode) {
    switch (mode) {
        case TrailMode::Off:
            return "off";
        case TrailMode::Selected:
            return "selected";
        case TrailMode::All:
            break;
    }
    return "all";
}

const char* toString(Theme theme) {
    return theme == Theme::Light ? "light" : "dark";
}

double automaticUiScale(double heightPoints) {
    if (!(heightPoints >= 900.0)) return 1.0;  // NaN too
    return std::min(kMaxUiScale, std::floor(heightPoints / 720.0 * 4.0) / 4.0);
}

double mostUiScale(double widthPoints) {
    if (!(widthPoints > 0.0)) return kMaxUiScale;  // no window yet (NaN too)
    const double most = std::floor(widthPoints / kPanelLeastPoints * 20.0 + 1e-9) / 20.0;
    return std::clamp(most, kMinUiScale, kMaxUiScale);
}

double steppedUiScale(double scale, int steps) {
    for (; steps > 0; --steps) {
        const auto* up =
            std::upper_bound(std::begin(kUiScaleSteps), std::end(kUiScaleSteps), scale + 1e-9);
        if (up == std::end(kUiScaleSteps)) break;
        scale = *up;
    }
    for (; steps < 0; ++steps) {
        const auto* down =
            std::lower_bound(std::begin(kUiScaleSteps), std::end(kUiScaleSteps), scale - 1e-9);
        if (down == std::begin(kUiScaleSteps)) break;
        scale = *(down - 1);
    }
    return scale;
}

double arrowSecondsFor(const World& world) {
    constexpr double kOriginal = 1.0 / 3.0;
    const ParticleArrays& p = world.particles();
    if (p.size() == 0) return kOriginal;
    double sum = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
        sum += p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i];
    const double vrms = std::sqrt(sum / static_cast<double>(p.size()));
    if (!(vrms > 0.0) || !std::isfinite(vrms)) return kOriginal;
    const double w = world.def().width, h = world.def().height;
    const double spacing = std::sqrt(w * h / static_cast<double>(p.size()));
    const double longest = std::min(0.2 * std::min(w, h), 0.75 * spacing);  // metres
    return std::min(kOriginal, longest / vrms);
}

double restingSpeed(const World& world, double frame) {
    const SolverSettings& s = world.solver();
    if (s.mode == StepMode::Exact) return 0.0;
    const double dt = frame / (s.mode == StepMode::Substep ? std::max(1, s.substeps) : 1);
    return 2.0 * world.def().gravity.norm() * dt;
}

double minArrowExtra(double spacingPixels) {
    return std::isfinite(spacingPixels) ? std::min(kMinArrowPixels, 0.5 * spacingPixels)
                                        : kMinArrowPixels;
}

namespace {

/// Each show option's flag and its name in messages, in ShowOption's order.
struct ShowEntry {
    bool ViewOptions::*flag;
    const char* name;
};
constexpr ShowEntry kShowEntries[] = {
    {&ViewOptions::arrows, "Arrows"},
    {&ViewOptions::labels, "Labels"},
    {&ViewOptions::momentum, "Momentum view"},
    {&ViewOptions::plots, "Plots"},
    {&ViewOptions::speeds, "Speed distribution"},
    {&ViewOptions::profile, "Profile"},
    {&ViewOptions::bins, "Bin counts"},
    {&ViewOptions::collision, "Last collision card"},
    {&ViewOptions::values, "Values table"},
    {&ViewOptions::ruler, "Ruler"},
    {&ViewOptions::grid, "Grid"},
    {&ViewOptions::spin, "Spin marks"},
    {&ViewOptions::yUp, "y up"},
};

const ShowEntry& entry(ShowOption option) {
    const auto k = static_cast<std::size_t>(option);
    return kShowEntries[k < std::size(kShowEntries) ? k : std::size(kShowEntries) - 1];
}

}  // namespace

bool& ViewOptions::flag(ShowOption option) {
    return this->*entry(option).flag;
}

std::string showMessage(ShowOption option, bool on) {
    return std::string(entry(option).name) + (on ? " on" : " off");
}

}  // namespace psb::app
