#include "session/last_collision.hpp"

#include <utility>

namespace psb::app {

namespace {

double energy(double m, const Vec2& v) {
    return 0.5 * m * v.squaredNorm();
}

/// The card with its two particles' places exchanged (the impulse is then on the other).
void swapSides(CollisionCard& card) {
    Collision& c = card.collision;
    std::swap(c.a, c.b);
    std::swap(c.aBefore, c.bBefore);
    std::swap(c.aAfter, c.bAfter);
    c.impulse = -c.impulse;
    std::swap(card.massA, card.massB);
    std::swap(card.numberA, card.numberB);
}

}  // namespace

Vec2 CollisionCard::momentumBefore() const {
    return massA * collision.aBefore + massB * collision.bBefore;
}

Vec2 CollisionCard::momentumAfter() const {
    return massA * collision.aAfter + massB * collision.bAfter;
}

double CollisionCard::energyBefore() const {
    return energy(massA, collision.aBefore) + energy(massB, collision.bBefore);
}

double CollisionCard::energyAfter() const {
    return energy(massA, collision.aAfter) + energy(massB, collision.bAfter);
}

std::optional<CollisionLog> LastCollision::wanted(bool listening,
                                                  std::optional<ParticleId> selected) {
    if (!listening) return std::nullopt;
    if (selected) return CollisionLog({*selected});
    return CollisionLog();
}

void LastCollision::heard(const std::vector<Collision>& records, const World& world,
                          std::optional<ParticleId> selected) {
    ahead_.reset();  // the world stepped: the future put aside is not this one
    for (auto it = records.rbegin(); it != records.rend(); ++it) {
        const Collision& c = *it;
        const bool follows = selected ? c.involves(*selected) : c.with == Collision::With::Particle;
        if (!follows) continue;
        CollisionCard card;
        card.collision = c;
        // The masses the step ended with: a collision changes none.
        card.massA = world.contains(c.a) ? world.get(c.a).mass : 0.0;
        card.numberA = particleNumber(c.a);
        if (card.pair()) {
            card.massB = world.contains(c.b) ? world.get(c.b).mass : 0.0;
            card.numberB = particleNumber(c.b);
            if (selected && c.b == *selected) swapSides(card);  // the selected one first
        }
        if (c.with == Collision::With::Obstacle && c.where < world.obstacles().size()) {
            card.peg = world.obstacles()[c.where].kind == Obstacle::Kind::Peg;
        }
        card.follows = selected ? particleNumber(*selected) : 0;
        card_ = card;
        return;
    }
}

void LastCollision::follow(std::optional<ParticleId> selected) {
    if (ahead_ && (selected ? !ahead_->collision.involves(*selected) : !ahead_->pair())) {
        ahead_.reset();
    }
    if (!card_) return;
    if (selected ? !card_->collision.involves(*selected) : !card_->pair()) {
        card_.reset();
        return;
    }
    if (selected && card_->pair() && card_->collision.b == *selected) swapSides(*card_);
    card_->follows = selected ? particleNumber(*selected) : 0;
}

void LastCollision::dropAfter(double time, bool viewing) {
    if (card_ && card_->collision.time > time && !viewing) {
        ahead_ = std::move(card_);
        card_.reset();
    } else if (!card_ && ahead_ && ahead_->collision.time <= time) {
        card_ = std::move(ahead_);
        ahead_.reset();
    }
}

}  // namespace psb::app
