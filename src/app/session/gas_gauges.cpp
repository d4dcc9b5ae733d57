#include "session/gas_gauges.hpp"

#include <cmath>

#include <particle_sandbox/hard_disc_theory.hpp>

namespace psb::app {

bool gasGaugesApply(const World& world) {
    const WorldDef& d = world.def();
    return (d.walls || (d.periodic && d.obstacles.empty())) && d.gravity == Vec2::Zero() &&
           world.size() >= kGasMinParticles;
}

GasReading gasReading(const ObservablesResult& m, const World& world, double minWindow) {
    GasReading r;
    r.area = world.def().width * world.def().height;
    r.periodic = world.def().periodic;
    r.particles = m.particles;
    r.reach = m.area;
    r.coverage = m.packingFraction;
    r.window = m.duration;
    if (r.particles == 0 || !(r.reach > 0.0) || !m.temperature.valid()) return r;
    r.kT = m.temperature.value;
    r.idealPressure = static_cast<double>(r.particles) * r.kT / r.reach;
    // Henderson's for discs covering η of the box (hard_disc_theory.hpp), whatever their sizes.
    r.hardDiskPressure =
        r.coverage < 1.0 ? r.idealPressure * hard_discs::hendersonZ(r.coverage) : 0.0;
    const Measured& p = r.periodic ? m.pressureVirial : m.pressureWalls;
    if (r.window < minWindow || !p.hasError()) return r;
    r.pressure = p.value;
    r.pressureError = p.error;
    r.pairRate = 0.5 * m.collisionRate.value * static_cast<double>(r.particles);
    r.wallRate = m.wallCollisionRate.valid() ? m.wallCollisionRate.value : 0.0;
    return r;
}

void GasGauges::open(World& world) {
    if (windows_.empty()) particles_ = world.size();
    windows_.push_back({ObservablesWindow{{.stateEvery = kStateEvery}}, world.time()});
    windows_.back().measure.open(world);  // turns the world's virial counter on
}

void GasGauges::sample(World& world) {
    const double t = world.time();
    // Time went back, or particles came or went without an edit (a dropper): start over.
    if (!windows_.empty() && (t < lastTime_ || world.size() != particles_)) windows_.clear();
    while (!history_.empty() && history_.back().time > t)
        history_.pop_back();
    if (!gasGaugesApply(world)) {
        windows_.clear();
        if (world.measuringVirial()) world.setMeasureVirial(false);  // only the gauges set it
        return;
    }
    if (windows_.empty()) {
        open(world);
    } else {
        if (t == lastTime_) return;  // paused
        for (Window& w : windows_)
            w.measure.sample(world);
        while (windows_.size() > 1 && t - windows_.front().opened > kWindow + 1e-9)
            windows_.pop_front();
        if (t - windows_.back().opened >= kWindow / kStagger - 1e-9) open(world);
    }
    lastTime_ = t;
    // The plot's point, every kHistoryEvery seconds.
    if (history_.empty() || t >= history_.back().time + kHistoryEvery - 1e-9) {
        const GasReading r = reading(world);
        history_.push_back({t, r.pressure, r.pressureError, r.idealPressure, r.hardDiskPressure});
        if (history_.size() > kHistoryPoints) history_.pop_front();
    }
}

GasReading GasGauges::reading(const World& world) const {
    if (!windows_.empty()) return gasReading(windows_.front().measure.result(), world, kMinWindow);
    if (world.size() == 0) {
        GasReading r;
        r.area = world.def().width * world.def().height;
        return r;
    }
    World copy = world;
    ObservablesWindow now;
    now.open(copy);
    return gasReading(now.result(), world, kMinWindow);
}

}  // namespace psb::app
