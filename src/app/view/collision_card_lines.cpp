#include "view/collision_card_lines.hpp"

#include <cmath>

#include "session/units.hpp"

namespace psb::app {

namespace {

std::string withUnit(const Vec2& v, const char* unit) {
    std::string s = components(v);
    s += " ";
    s += unit;
    return s;
}

const char* wallName(WallSide side) {
    switch (side) {
        case WallSide::Left:
            return "the left wall";
        case WallSide::Right:
            return "the right wall";
        case WallSide::Top:
            return "the top wall";
        case WallSide::Bottom:
            break;
    }
    return "the bottom wall";
}

/// "lost 25.0 %", "kept (to rounding)", "gained 3.00 %" (a held particle can give energy).
std::string energyChange(double before, double after) {
    if (!(before > 0.0)) return "no kinetic energy before";
    const double lost = (before - after) / before;
    if (std::abs(lost) < 1e-9) return "Kinetic energy kept (elastic, to rounding)";
    const double percent = 100.0 * std::abs(lost);
    return std::string(lost > 0.0 ? "Kinetic energy lost: " : "Kinetic energy gained: ") +
           quantity(percent, "", false) + " % of it";
}

}  // namespace

CollisionCardText collisionCardText(const CollisionCard& card, const Axes& axes) {
    const Collision& c = card.collision;
    // Signed components as the user reads them (the y up option).
    const auto shown = [&](const Vec2& v) { return components(axes.vector(v)); };
    CollisionCardText t;
    const std::string a = std::to_string(card.numberA);
    const std::string at = " at t = " + quantity(c.time, "s");
    if (card.pair()) {
        const std::string b = std::to_string(card.numberB);
        t.title = "Particles " + a + " and " + b + at;
        t.rows = {
            {"v " + a, "m/s", shown(c.aBefore), shown(c.aAfter), "Particle " + a + "'s velocity"},
            {"v " + b, "m/s", shown(c.bBefore), shown(c.bAfter), "Particle " + b + "'s velocity"},
            {"p " + a, "kg m/s", shown(card.massA * c.aBefore), shown(card.massA * c.aAfter),
             "Particle " + a + "'s momentum m v (m = " + quantity(card.massA, "kg", false) + ")"},
            {"p " + b, "kg m/s", shown(card.massB * c.bBefore), shown(card.massB * c.bAfter),
             "Particle " + b + "'s momentum m v (m = " + quantity(card.massB, "kg", false) + ")"},
            {"total p", "kg m/s", shown(card.momentumBefore()), shown(card.momentumAfter()),
             "The two momenta added: a collision between two particles never changes it"},
        };
    } else {
        const std::string other = c.with == Collision::With::Wall
                                      ? std::string(wallName(c.wall()))
                                      : std::string(card.peg ? "a peg" : "a wall segment");
        t.title = "Particle " + a + " and " + other + at;
        t.rows = {
            {"v " + a, "m/s", shown(c.aBefore), shown(c.aAfter), "Particle " + a + "'s velocity"},
            {"p " + a, "kg m/s", shown(card.massA * c.aBefore), shown(card.massA * c.aAfter),
             "Particle " + a + "'s momentum m v (m = " + quantity(card.massA, "kg", false) +
                 "): a fixed wall or obstacle changes it"},
        };
    }
    t.rows.push_back({"kinetic energy", "", quantity(card.energyBefore(), "J"),
                      quantity(card.energyAfter(), "J"),
                      "The sum of \u00bd m v\u00b2: kept by an elastic collision (e = 1)"});
    t.notes.push_back(
        "Impulse on " + a + ": " + withUnit(axes.vector(c.impulse), "N s") +
        (card.pair() ? " (on " + std::to_string(card.numberB) + ": the opposite)" : ""));
    if (card.pair()) {
        const Vec2 change = card.momentumAfter() - card.momentumBefore();
        const double scale = card.massA * (c.aBefore.norm() + c.aAfter.norm()) +
                             card.massB * (c.bBefore.norm() + c.bAfter.norm());
        t.notes.push_back(change.norm() <= 1e-12 * scale
                              ? std::string("Total momentum kept (to rounding)")
                              : "Total momentum changed by " +
                                    withUnit(axes.vector(change), "kg m/s") +
                                    " (a held particle pushes)");
    }
    t.notes.push_back(energyChange(card.energyBefore(), card.energyAfter()));
    return t;
}

std::vector<std::string> collisionCardLines(const CollisionCardText& text) {
    std::vector<std::string> lines{text.title};
    for (const CollisionCardText::Row& r : text.rows)
        lines.push_back(r.name + ": " + r.before + (r.unit.empty() ? "" : " " + r.unit) + " -> " +
                        r.after + (r.unit.empty() ? "" : " " + r.unit));
    lines.insert(lines.end(), text.notes.begin(), text.notes.end());
    return lines;
}

std::string cardAhead(const CollisionCard& card, double shownTime) {
    const double ahead = card.collision.time - shownTime;
    // Closer than the clock's rounding is the collision's own frame (the exact mode's instant
    // falls inside one).
    if (!(ahead > 1e-9)) return {};
    return "The frame shown is " + quantity(ahead, "s") + " before it";
}

}  // namespace psb::app
