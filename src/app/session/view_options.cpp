#include "session/view_options.hpp"

#include <algorithm>
#include <cmath>

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

double restingSpeed(const World& world) {
    const SolverSettings& s = world.solver();
    if (s.mode == StepMode::Exact) return 0.0;
    const double dt = s.dt / (s.mode == StepMode::Substep ? std::max(1, s.substeps) : 1);
    return 2.0 * world.def().gravity.norm() * dt;
}

double minArrowExtra(double spacingPixels) {
    return std::isfinite(spacingPixels) ? std::min(kMinArrowPixels, 0.5 * spacingPixels)
                                        : kMinArrowPixels;
}

bool& ViewOptions::flag(ShowOption option) {
    switch (option) {
        case ShowOption::Arrows:
            return arrows;
        case ShowOption::Labels:
            return labels;
        case ShowOption::Momentum:
            return momentum;
        case ShowOption::Plots:
            return plots;
        case ShowOption::Speeds:
            return speeds;
        case ShowOption::Profile:
            return profile;
        case ShowOption::Bins:
            break;
    }
    return bins;
}

std::string showMessage(ShowOption option, bool on) {
    const char* what = "Bin counts";
    switch (option) {
        case ShowOption::Arrows:
            what = "Arrows";
            break;
        case ShowOption::Labels:
            what = "Labels";
            break;
        case ShowOption::Momentum:
            what = "Momentum view";
            break;
        case ShowOption::Plots:
            what = "Plots";
            break;
        case ShowOption::Speeds:
            what = "Speed distribution";
            break;
        case ShowOption::Profile:
            what = "Profile";
            break;
        case ShowOption::Bins:
            break;
    }
    return std::string(what) + (on ? " on" : " off");
}

}  // namespace psb::app
