// The exact stepper's side of the contacts that last along a surface (slides.hpp, rolls.hpp
// decide their motion): a slide started at a rebound and given its law, a slide's and a roll's
// own events, and the face's answer to a slider a pair hit. Each ends with the particle
// predicted again.

#include "exact/stepper.hpp"

namespace psb::exact {

bool ExactStepper::startSliding(std::uint32_t i, std::uint32_t k, double nx, double ny) {
    if (!slides_.start(i, bodies_[i], cold_[i], obstacles_, k, nx, ny)) return false;
    setSlideAcceleration(i);
    return true;
}

void ExactStepper::setSlideAcceleration(std::uint32_t i) {
    if (rolls_.turns(i)) {
        setRoll(i);  // a disc that turns slips or rolls (rolls.hpp)
        return;
    }
    slides_.setBlockAcceleration(i, bodies_[i], obstacles_, gravity_, def_.friction);
}

void ExactStepper::handleSlide(std::uint32_t i, const Event& ev) {
    Body& a = bodies_[i];
    advance(i, ev.time);
    ++events_;
    ++a.count;
    if (ev.side < 2) {
        // Off the end of the face: free flight.
        stopSliding(i);
        Slides::leaveEnd(a, obstacles_[ev.partner], ev.side);
    } else {
        // Stopped by friction: at rest, held by static friction (and asleep if it may sleep
        // there), or sliding back down a slope steeper than the friction angle.
        a.vx = a.vy = 0.0;
        setSlideAcceleration(i);
        settleAfterPair(i, false);
    }
    predictCollision(i, ev.time);
    predictCell(i, ev.time);
}

void ExactStepper::keepOnFace(std::uint32_t i, StepCounters& counters, bool maySlide) {
    // i slid on a face until a pair hit it just now. Sent off the face, it flies; still on it
    // (not moving away from it), the face answers at once, as the obstacle event that its next
    // prediction would find at this instant would: a rebound, and a slide again if slow.
    Body& a = bodies_[i];
    if (!slides_.stillOnFace(i, a, obstacles_)) return;
    reboundOffObstacle(i, slides_[i].obstacle, collidedWithin(a, a.t), counters, maySlide);
}

void ExactStepper::handleRoll(std::uint32_t i, const Event& ev) {
    Body& a = bodies_[i];
    advance(i, ev.time);
    ++events_;
    ++a.count;  // its acceleration changes: what neighbours predicted with it is stale
    // A block stopped by friction rests, asleep if it may sleep there, or slides back
    // (settleAfterPair gives the phase).
    if (rolls_.endSlip(i, a, cold_[i], slides_, obstacles_, gravity_, def_.friction, ev.time))
        settleAfterPair(i, false);
    predictCollision(i, ev.time);
    predictCell(i, ev.time);
}

}  // namespace psb::exact
