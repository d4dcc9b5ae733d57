// The exact step's loop: a step, the events up to its end, and the state written back to the
// world's arrays when someone reads them. The overview is in stepper.hpp.

#include "exact/stepper.hpp"

#include <algorithm>

#include "exact/motion.hpp"
#include "support/periodic_box.hpp"
#include "world/stage_timer.hpp"

namespace psb::exact {

namespace {

// Events per particle between two re-sorts of the particles into cell order.
constexpr std::uint64_t kResortEvery = 8;

}  // namespace

double ExactStepper::step(ParticleArrays& p, const WorldDef& def, double dt,
                          std::uint64_t eventsPerParticle, StepProfile& profile,
                          StepCounters& counters) {
    StageTimer total(profile.total);
    double& rebuildMs = profile.stage("rebuild");
    double& eventsMs = profile.stage("events");
    profile.stage("sync");  // added by World when the state is read
    if (stale_) {
        // The world's arrays must hold the current state before they are read back in.
        if (syncOwed_) sync(p);
        StageTimer t(rebuildMs);
        rebuild(p, def);
    }
    // Pairs placed overlapping are part of the state: report them, not only the overlaps met
    // at collisions (which rounding keeps at a few ulps). Every step that carries one at its
    // placed distance reports it, not only the one that found it: counters reset between steps
    // (the app's per frame) with no change to the world, so no rebuild, still bound the state.
    counters.maxOverlap = std::max(counters.maxOverlap, placed_.deepest());
    recorder_.startStep(clock_);
    events_ = 0;
    // The jam guard counts per step.
    jams_.startStep(bodies_, cold_);
    maxOverlap_ = counters.maxOverlap;
    const double start = clock_;
    const double tEnd = start + dt;
    const std::uint64_t perStep = bodies_.size() + 1;
    const std::uint64_t budget =
        eventsPerParticle > UINT64_MAX / perStep ? UINT64_MAX : eventsPerParticle * perStep;
    double reached = tEnd;
    {
        StageTimer t(eventsMs);
        reached = runEvents(tEnd, counters, budget);
    }
    clock_ = reached;
    syncOwed_ = !bodies_.empty();
    counters.maxOverlap = std::max(counters.maxOverlap, maxOverlap_);
    counters.events += events_;
    ++counters.steps;
    // dt itself, not tEnd - start: the world's clock adds what it asked for, bit for bit.
    return reached == tEnd ? dt : std::min(dt, reached - start);
}

double ExactStepper::runEvents(double tEnd, StepCounters& counters, std::uint64_t budget) {
    std::uint64_t processed = 0;
    for (;;) {
        const EventQueue::Entry top = queue_.top();
        if (!(top.time <= tEnd)) break;
        if (budget > 0 && ++processed > budget) {
            // The state is exact up to the next event: the step ends there, the time left is
            // not simulated, and the next step goes on from there, the queue as it is. (Flying
            // the rest freely would take particles through each other and the walls.)
            ++counters.cutShort;
            return top.time;
        }
        if (++eventsSinceSort_ > kResortEvery * bodies_.size()) {
            // Particles drift away from the neighbours they were stored next to; restoring
            // cell order keeps each 3 × 3 search in a few cache lines. Indices only change:
            // no position, velocity or event time is touched.
            sortByCell(true);
            eventsSinceSort_ = 0;
            continue;
        }
        // Events come in time order, which is random in space: the next particle's lines are
        // almost never in cache. Start fetching them while this event is handled.
        if (const std::uint32_t next = queue_.likelyNext(); next != UINT32_MAX) {
            __builtin_prefetch(&bodies_[next / 2]);
            __builtin_prefetch(&cold_[next / 2]);
            queue_.prefetch(next);
        }
        const std::uint32_t i = top.key / 2;
        if (top.key % 2 == 1) {
            handleCell(i, top.time);
            continue;
        }
        const Event ev = cold_[i].coll;
        switch (ev.kind) {
            case Kind::Pair:
                handlePair(i, ev, counters);
                break;
            case Kind::Wall:
                handleWall(i, ev, counters);
                break;
            case Kind::Obstacle:
                handleObstacle(i, ev, counters);
                break;
            case Kind::Slide:
                handleSlide(i, ev);
                break;
            case Kind::Recheck:
                handleRecheck(i, ev);
                break;
            case Kind::Roll:
                handleRoll(i, ev);
                break;
            case Kind::None:
                return tEnd;  // unreachable: None events are at +infinity
        }
    }
    return tEnd;
}

void ExactStepper::sync(ParticleArrays& p) {
    // One pass in the stepper's order; every particle's state at the end of the last step.
    const std::size_t n = bodies_.size();
    const double t = clock_;
    const Body* bodies = bodies_.data();
    const std::uint32_t* order = order_.data();
    double* x = p.x.data();
    double* y = p.y.data();
    double* vx = p.vx.data();
    double* vy = p.vy.data();
    for (std::size_t k = 0; k < n; ++k) {
        const Body& b = bodies[k];
        const std::uint32_t i = order[k];
        if (gravity_.on) {
            const Motion m = motionAt(k, b, t);
            x[i] = m.x;
            y[i] = m.y;
            vx[i] = m.vx;
            vy[i] = m.vy;
            continue;
        }
        const double h = t - b.t;
        x[i] = b.x + b.vx * h;
        y[i] = b.y + b.vy * h;
        vx[i] = b.vx;
        vy[i] = b.vy;
    }
    rolls_.sync(p, order_, t);
    if (def_.walls) {
        // At 10¹⁹ m/s one ulp of the clock is a metre: a centre reckoned from a wall event's
        // time can land past the wall. What the world reports stays in the box (a no-op at
        // any speed an ulp of the clock does not make a distance of).
        for (std::size_t k = 0; k < n; ++k) {
            const std::uint32_t i = order[k];
            const double r = bodies[k].r;
            if (!cold_[k].pinX) x[i] = std::clamp(x[i], r, def_.width - r);
            if (!cold_[k].pinY) y[i] = std::clamp(y[i], r, def_.height - r);
        }
    }
    if (def_.periodic) {
        // Centres a rounding past an edge (the box's faces are crossed at the face itself)
        // into [0, width) × [0, height), with the offsets that go with them.
        for (std::size_t k = 0; k < n; ++k) {
            const std::uint32_t i = order[k];
            p.unwrapX[i] = unwrapX_[k];
            p.unwrapY[i] = unwrapY_[k];
            periodic::wrapInto(x[i], p.unwrapX[i], def_.width);
            periodic::wrapInto(y[i], p.unwrapY[i], def_.height);
        }
    }
    syncOwed_ = false;
}

void ExactStepper::sortByCell(bool midRun) {
    const auto n = static_cast<std::uint32_t>(bodies_.size());
    const std::vector<std::uint32_t> to = grid_.cellOrder(cold_);
    renumber(bodies_, to);
    renumber(cold_, to);
    renumber(order_, to);
    renumber(ids_, to);
    if (!unwrapX_.empty()) {
        renumber(unwrapX_, to);
        renumber(unwrapY_, to);
    }
    if (gravity_.on) rest_.renumber(to);
    slides_.renumber(to);
    rolls_.renumber(to);
    if (midRun) {
        // Carry the scheduled events over to the new indices.
        std::vector<double> times(2 * static_cast<std::size_t>(n));
        for (std::uint32_t i = 0; i < n; ++i) {
            times[2 * to[i]] = queue_.timeOf(2 * i);
            times[2 * to[i] + 1] = queue_.timeOf(2 * i + 1);
        }
        for (Cold& c : cold_) {
            if (c.coll.kind == Kind::Pair) c.coll.partner = to[c.coll.partner];
        }
        jams_.renumber(to);
        queue_.reset(2 * n, queue_.bucketWidth());
        for (std::uint32_t k = 0; k < 2 * n; ++k)
            queue_.update(k, times[k]);
        grid_.clearMembers();
        for (std::uint32_t i = 0; i < n; ++i)
            grid_.insert(i, cold_[i]);
    }
}

std::size_t ExactStepper::memoryBytes() const {
    std::size_t bytes = sizeof(Body) * bodies_.capacity() + sizeof(Cold) * cold_.capacity() +
                        sizeof(std::uint32_t) * order_.capacity() +
                        sizeof(ParticleId) * ids_.capacity() + grid_.memoryBytes() +
                        queue_.memoryBytes() + obstacles_.memoryBytes() + rest_.memoryBytes() +
                        slides_.memoryBytes() + rolls_.memoryBytes();
    bytes += sizeof(double) * (unwrapX_.capacity() + unwrapY_.capacity());
    return bytes + placed_.memoryBytes();
}

}  // namespace psb::exact
