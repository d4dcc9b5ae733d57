// The exact stepper's side of resting (resting.hpp decides): a rebuild's sleepers kept, a
// particle put to sleep or woken with what it held up, the recheck of a provisional sleeper.
// Each particle whose motion this changes is predicted again at once, in the order the
// cascade reaches it: a neighbour's prediction reads what the earlier ones scheduled.

#include "exact/stepper.hpp"

namespace psb::exact {

void ExactStepper::keepSleepers(Resting::Snapshot& before) {
    std::vector<Resting::Spot> spots;
    std::vector<bool> carried;
    if (!rest_.keep(before, bodies_, ids_, spots, carried)) return;
    const auto n = static_cast<std::uint32_t>(bodies_.size());
    for (const Resting::Spot& s : spots) {
        for (std::uint32_t q = 0; q < n; ++q) {
            const Body& b = bodies_[q];
            if ((b.flags & kAsleep) && rest_.touches(s, b)) wake(q, 0.0);
        }
    }
    rest_.settleFreed(bodies_, carried);
}

void ExactStepper::settle(std::uint32_t i, double now, bool slow) {
    const Resting::Sleep s = rest_.settle(i, now, slow, around());
    if (s.falls) fallAsleep(i, now, s.depth, s.provisional);
}

void ExactStepper::settleAfterPair(std::uint32_t i, bool justWoken) {
    Body& a = bodies_[i];
    if (a.flags & (kHeld | kAsleep)) return;
    // Off the wall it rested on if the pair pushed it off (or into it: the wall event comes
    // at once and decides).
    const Cold& ac = cold_[i];
    if ((a.flags & kRestX) && !ac.pinX && a.vx != 0.0) a.flags &= ~kRestX;
    if ((a.flags & kRestY) && !ac.pinY && a.vy != 0.0) a.flags &= ~kRestY;
    settle(i, a.t, !justWoken && rest_.slow(a) && rest_.mayRest(i, a.t));
    // Still on a wall or a face, a disc that turns slips or rolls along it (rolls.hpp).
    setRoll(i);
}

void ExactStepper::fallAsleep(std::uint32_t i, double now, std::uint32_t depth, bool provisional) {
    Body& b = bodies_[i];
    advance(i, now);
    rest_.fallAsleep(i, b, now, depth, provisional);
    stopSliding(i);
    // At rest a disc that turns does not turn either: its contacts' friction would stop it.
    rolls_.stopTurning(i, now);
    ++b.count;
}

void ExactStepper::wake(std::uint32_t i, double now) {
    // i wakes, and with it every sleeper it held up: each sleeper near a woken one is judged
    // again (Resting::afterWake), and one whose support has gone wakes in turn.
    const auto rouse = [&](std::uint32_t k) {
        rest_.rouse(k, bodies_[k], now);
        setRoll(k);  // on a wall it rests on, a disc that turns rolls (rolls.hpp)
    };
    rouse(i);
    wakeStack_.assign(1, i);
    while (!wakeStack_.empty()) {
        const std::uint32_t p = wakeStack_.back();
        wakeStack_.pop_back();
        grid_.forEachAround(cold_[p], [&](std::uint32_t q) {
            switch (rest_.afterWake(q, p, now, around())) {
                case Resting::Support::Holds:
                    break;
                case Resting::Support::Provisional:
                    predictCollision(q, now);  // its recheck
                    break;
                case Resting::Support::Gone:
                    rouse(q);
                    predictCollision(q, now);
                    predictCell(q, now);
                    wakeStack_.push_back(q);
                    break;
            }
        });
    }
}

void ExactStepper::handleRecheck(std::uint32_t i, const Event& ev) {
    switch (rest_.recheck(i, ev.time, around())) {
        case Resting::Support::Holds:
            break;
        case Resting::Support::Provisional:
            sleepNeighboursAtRest(i, ev.time);
            rest_.makeProvisional(i, bodies_[i], ev.time);
            break;
        case Resting::Support::Gone:
            wake(i, ev.time);
            predictCell(i, ev.time);
            break;
    }
    predictCollision(i, ev.time);
}

void ExactStepper::sleepNeighboursAtRest(std::uint32_t i, double now) {
    grid_.forEachAround(cold_[i], [&](std::uint32_t q) {
        const Resting::Sleep s = rest_.atRestBeside(q, i, now, around());
        if (!s.falls) return;
        fallAsleep(q, now, s.depth, s.provisional);
        predictCollision(q, now);
        predictCell(q, now);
    });
}

}  // namespace psb::exact
