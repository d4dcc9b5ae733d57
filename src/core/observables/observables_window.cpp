// The observables window's sampling (observables.hpp): the counters' growth into the chunk of
// each interval, and every stateEvery samples the particles themselves.

#include <algorithm>
#include <cmath>
#include <numbers>

#include <particle_sandbox/diagnostics.hpp>
#include <particle_sandbox/error.hpp>
#include <particle_sandbox/observables.hpp>
#include <particle_sandbox/world.hpp>

#include "observables/displacement_position.hpp"
#include "observables/window_state.hpp"

namespace psb {

namespace {

void requireSettings(const ObservablesSettings& s) {
    const auto fail = [](const std::string& what) {
        throw InvalidArgument("ObservablesWindow: " + what);
    };
    if (s.stateEvery == 0) fail("stateEvery must be >= 1");
    if (!(std::isfinite(s.pairRange) && s.pairRange >= 0.0))
        fail("pairRange must be finite and >= 0 metres");
    if (!(std::isfinite(s.pairBinWidth) && s.pairBinWidth >= 0.0))
        fail("pairBinWidth must be finite and >= 0 metres");
}

}  // namespace

ObservablesWindow::ObservablesWindow(const ObservablesSettings& settings) : settings_(settings) {
    requireSettings(settings);
}
ObservablesWindow::~ObservablesWindow() = default;
ObservablesWindow::ObservablesWindow(ObservablesWindow&&) noexcept = default;
ObservablesWindow& ObservablesWindow::operator=(ObservablesWindow&&) noexcept = default;

bool ObservablesWindow::isOpen() const {
    return state_ != nullptr;
}

void ObservablesWindow::open(World& world) {
    if (world.size() == 0) throw InvalidArgument("ObservablesWindow::open: the world is empty");
    auto s = std::make_unique<State>(kBlocks);
    const ParticleArrays& p = world.particles();
    const WorldDef& def = world.def();
    s->n = p.size();
    s->ids = p.id;
    std::uint32_t maxSlot = 0;
    for (const ParticleId id : p.id)
        maxSlot = std::max(maxSlot, id.slot);
    s->slotIndex.assign(std::size_t{maxSlot} + 1, UINT32_MAX);
    double radii = 0.0;
    s->equalDiscs = true;
    for (std::size_t i = 0; i < p.size(); ++i) {
        s->slotIndex[p.id[i].slot] = static_cast<std::uint32_t>(i);
        radii += p.radius[i];
        s->coveredArea += std::numbers::pi * p.radius[i] * p.radius[i];
        if (p.radius[i] != p.radius[0] || p.mass[i] != p.mass[0] || p.invMass[i] == 0.0)
            s->equalDiscs = false;
        if (p.rotation && !p.fixedRotation[i]) ++s->turning;
    }
    s->meanRadius = radii / static_cast<double>(p.size());
    s->sigma = 2.0 * p.radius[0];
    s->mass = p.mass[0];
    s->width = def.width;
    s->height = def.height;
    s->walls = def.walls;
    s->periodic = def.periodic;
    s->gravity = !def.gravity.isZero();
    s->obstacles = !def.obstacles.empty();
    s->freedom = static_cast<double>(s->n);
    if (s->periodic && !s->gravity && !s->obstacles && s->n > 1) s->freedom -= 1.0;
    s->openTime = s->lastTime = s->lastStateTime = world.time();
    s->last = world.counters();
    s->lastResets = world.counterResets();

    if (settings_.pairEvery > 0) {
        const double range =
            settings_.pairRange > 0.0 ? settings_.pairRange : 0.5 * std::min(def.width, def.height);
        const double width = settings_.pairBinWidth > 0.0 ? settings_.pairBinWidth
                             : s->equalDiscs              ? s->sigma / 50.0
                                                          : range / 1000.0;
        if (range / width > 1e6) {
            throw InvalidArgument("ObservablesWindow::open: g(r) would need " +
                                  std::to_string(range / width) +
                                  " bins (more than 10^6): a larger pairBinWidth");
        }
        s->pairs.configure(range, width, def.width, def.height, def.periodic);
    }
    const std::uint32_t every =
        settings_.originEvery > 0 ? settings_.originEvery : std::max(1u, settings_.maxLag / 2);
    s->correlation.configure(s->n, settings_.maxLag, every);
    state_ = std::move(s);
    world.setMeasureVirial(true);
    readState(world);
}

void ObservablesWindow::sample(const World& world) {
    if (!state_) throw InvalidArgument("ObservablesWindow::sample: the window is not open");
    State& s = *state_;
    const double now = world.time();
    if (!(now > s.lastTime)) return;  // no step since the last sample
    StepCounters c = world.counters();
    // Counters reset since the last sample (World::resetCounters): they count from 0 again.
    // (A caller that clears them before each frame's steps has as many steps each frame: the
    // reset count tells, not the counts.)
    if (world.counterResets() != s.lastResets || c.steps < s.last.steps ||
        c.collisions < s.last.collisions) {
        s.last = StepCounters{};
    }
    s.lastResets = world.counterResets();
    observables::Chunk& chunk = s.chunks.forNextInterval();
    ++chunk.intervals;
    chunk.time += now - s.lastTime;
    chunk.virial += c.pairVirial - s.last.pairVirial;
    chunk.wallImpulse += c.wallImpulse - s.last.wallImpulse;
    chunk.collisions += c.collisions - s.last.collisions;
    chunk.wallCollisions += c.wallCollisions - s.last.wallCollisions;
    s.last = c;
    s.lastTime = now;
    ++s.samples;
    if (s.samples % settings_.stateEvery == 0) readState(world);
}

void ObservablesWindow::readState(const World& world) {
    State& s = *state_;
    const ParticleArrays& p = world.particles();
    observables::Chunk& chunk = s.chunks.current();
    ++chunk.states;
    chunk.kinetic += kineticEnergy(world);
    if (s.freedom < static_cast<double>(s.n)) {
        // The centre of mass's share is no heat: measured in its frame.
        double px = 0.0, py = 0.0, mass = 0.0;
        for (std::size_t i = 0; i < p.size(); ++i) {
            px += p.mass[i] * p.vx[i];
            py += p.mass[i] * p.vy[i];
            mass += p.mass[i];
        }
        if (mass > 0.0) chunk.kinetic -= 0.5 * (px * px + py * py) / mass;
    }
    if (p.rotation) chunk.rotational += rotationalEnergy(world);
    const std::uint64_t k = s.stateSamples++;
    const double now = world.time();
    if (k == 1) {
        s.stateInterval = now - s.lastStateTime;
    } else if (k > 1 &&
               std::abs((now - s.lastStateTime) - s.stateInterval) > 1e-6 * s.stateInterval &&
               s.correlation.on()) {
        s.correlation.stop();
        s.notes.push_back("the state samples were not evenly spaced in time: MSD and VACF stopped");
    }
    s.lastStateTime = now;

    // The particles in the window's order; a particle added or removed ends what needs them.
    bool same = p.size() == s.n;
    s.x.resize(s.n);
    s.y.resize(s.n);
    s.vx.resize(s.n);
    s.vy.resize(s.n);
    double speeds = 0.0;
    for (std::size_t i = 0; i < p.size() && same; ++i) {
        const ParticleId id = p.id[i];
        const std::uint32_t at = id.slot < s.slotIndex.size() ? s.slotIndex[id.slot] : UINT32_MAX;
        if (at == UINT32_MAX || s.ids[at] != id) {
            same = false;
            break;
        }
        observables::displacementPosition(world, p, i, s.x[at], s.y[at]);
        s.vx[at] = p.vx[i];
        s.vy[at] = p.vy[i];
        speeds += std::sqrt(p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);  // hypot is 5× slower
    }
    if (!same) {
        if (!s.particlesChanged) {
            s.particlesChanged = true;
            s.notes.push_back(
                "particles were added or removed during the window: MSD, VACF, "
                "g(r) and the speeds stopped there; N is the count at the start");
            s.correlation.stop();
        }
        return;
    }
    chunk.speed += speeds / static_cast<double>(s.n);
    s.correlation.add(k, s.x, s.y, s.vx, s.vy, chunk);
    if (settings_.pairEvery > 0 && k % settings_.pairEvery == 0) {
        // g(r) in the world's own coordinates (the box's), not the unwrapped ones.
        for (std::size_t i = 0; i < p.size(); ++i) {
            const std::uint32_t at = s.slotIndex[p.id[i].slot];
            s.x[at] = p.x[i];
            s.y[at] = p.y[i];
        }
        s.pairs.count(s.x, s.y, chunk.pairs);
        ++chunk.snapshots;
    }
}

ObservablesResult ObservablesWindow::close(World& world) {
    if (!state_) throw InvalidArgument("ObservablesWindow::close: the window is not open");
    sample(world);
    world.setMeasureVirial(false);
    ObservablesResult r = result();
    state_.reset();
    return r;
}

}  // namespace psb
