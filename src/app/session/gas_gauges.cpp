#include "session/gas_gauges.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace psb::app {

bool gasGaugesApply(const World& world) {
    return world.def().walls && world.def().gravity == Vec2::Zero() &&
           world.size() >= kGasMinParticles;
}

void GasGauges::sample(const World& world) {
    const StepCounters& c = world.counters();  // this frame's steps (Monitor clears them)
    if (!samples_.empty() && world.time() < samples_.back().time) samples_.clear();  // went back
    while (!history_.empty() && history_.back().time > world.time())
        history_.pop_back();
    if (!samples_.empty() && world.time() == samples_.back().time) return;  // paused
    Sample s{world.time(), c.wallImpulse, c.collisions, c.wallCollisions};
    if (!samples_.empty()) {
        const Sample& last = samples_.back();
        s.wallImpulse += last.wallImpulse;
        s.collisions += last.collisions;
        s.wallCollisions += last.wallCollisions;
    }
    samples_.push_back(s);
    // Keep one sample at or before the window's start, so the window is whole.
    while (samples_.size() > 2 && samples_[1].time <= s.time - kWindow)
        samples_.pop_front();
    // The plot's point, every kHistoryEvery seconds while the gauges apply.
    if (gasGaugesApply(world) &&
        (history_.empty() || s.time >= history_.back().time + kHistoryEvery - 1e-9)) {
        const GasReading r = reading(world);
        history_.push_back(
            {s.time, r.pressure, r.pressureError, r.idealPressure, r.hardDiskPressure});
        if (history_.size() > kHistoryPoints) history_.pop_front();
    }
}

GasReading GasGauges::reading(const World& world) const {
    GasReading r;
    const ParticleArrays& p = world.particles();
    r.particles = p.size();
    const double w = world.def().width, h = world.def().height;
    r.area = w * h;
    double ke = 0.0, covered = 0.0, radii = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        ke += 0.5 * p.mass[i] * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
        covered += std::numbers::pi * p.radius[i] * p.radius[i];
        radii += p.radius[i];
    }
    if (r.particles == 0 || r.area <= 0.0) return r;
    const auto n = static_cast<double>(r.particles);
    r.kT = ke / n;
    r.coverage = covered / r.area;
    // The centres reach no closer to a wall than a radius: the area they move in.
    const double rim = radii / n;
    r.reach = std::max(0.0, w - 2.0 * rim) * std::max(0.0, h - 2.0 * rim);
    if (r.reach <= 0.0) return r;
    r.idealPressure = n * r.kT / r.reach;
    const double eta = r.coverage;
    r.hardDiskPressure =
        eta < 1.0 ? r.idealPressure * (1.0 + eta * eta / 8.0) / ((1.0 - eta) * (1.0 - eta)) : 0.0;

    if (samples_.size() < 2) return r;
    const Sample& first = samples_.front();
    const Sample& last = samples_.back();
    r.window = last.time - first.time;
    if (r.window < kMinWindow) return r;
    const double perimeter = 2.0 * (w + h);
    r.pressure = (last.wallImpulse - first.wallImpulse) / r.window / perimeter;
    r.pairRate = static_cast<double>(last.collisions - first.collisions) / r.window;
    r.wallRate = static_cast<double>(last.wallCollisions - first.wallCollisions) / r.window;
    // Block averages: the wall impulse between the samples nearest each block's ends.
    std::array<double, kBlocks> block{};
    std::size_t at = 0;
    double sum = 0.0;
    int blocks = 0;
    for (int k = 0; k < kBlocks; ++k) {
        const double end = first.time + r.window * (k + 1) / kBlocks;
        const std::size_t from = at;
        while (at + 1 < samples_.size() && samples_[at + 1].time <= end + 1e-12)
            ++at;
        const double span = samples_[at].time - samples_[from].time;
        if (span <= 0.0) continue;
        block[blocks] = (samples_[at].wallImpulse - samples_[from].wallImpulse) / span / perimeter;
        sum += block[blocks];
        ++blocks;
    }
    if (blocks >= 2) {
        const double mean = sum / blocks;
        double var = 0.0;
        for (int k = 0; k < blocks; ++k)
            var += (block[k] - mean) * (block[k] - mean);
        var /= (blocks - 1);
        r.pressureError = std::sqrt(var / blocks);
    }
    return r;
}

}  // namespace psb::app
