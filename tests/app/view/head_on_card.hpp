#pragma once
// The card of the textbook head-on collision the view tests read: 1 kg at 2 m/s meets 3 kg at
// -1 m/s with restitution `e` (e = 1: -2.5 and 0.5 m/s after).

#include "session/last_collision.hpp"

namespace psb::app {

[[nodiscard]] inline CollisionCard headOnCard(double e = 1.0) {
    CollisionCard card;
    Collision& c = card.collision;
    c.time = 2.0 / 3.0;
    c.with = Collision::With::Particle;
    c.a = ParticleId{0, 0};
    c.b = ParticleId{1, 0};
    card.massA = 1.0;
    card.massB = 3.0;
    card.numberA = 1;
    card.numberB = 2;
    c.aBefore = Vec2(2.0, 0.0);
    c.bBefore = Vec2(-1.0, 0.0);
    const double vcm = -0.25;  // the centre of mass's velocity
    c.aAfter = Vec2(vcm - e * (2.0 - vcm), 0.0);
    c.bAfter = Vec2(vcm - e * (-1.0 - vcm), 0.0);
    c.impulse = card.massA * (c.aAfter - c.aBefore);
    return card;
}

}  // namespace psb::app
