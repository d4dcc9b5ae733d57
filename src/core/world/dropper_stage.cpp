// Ball droppers: the next ball, the drop stage's rules and World's checks (dropper.hpp).

#include "world/dropper_stage.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "world/validate.hpp"

namespace psb {

namespace {

/// SplitMix64 (Steele, Lea & Flood 2014): a well-mixed 64-bit value from (seed, n), so that
/// the n-th offset does not depend on the ones before it.
std::uint64_t mix(std::uint64_t seed, std::uint64_t n) {
    std::uint64_t z = seed + (n + 1) * 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

}  // namespace

Vec2 Dropper::nextPosition() const {
    if (spread == 0.0) return position;
    const double u = static_cast<double>(mix(seed, released) >> 11) * 0x1.0p-53;  // [0, 1)
    return {position.x() + spread * (2.0 * u - 1.0), position.y()};
}

namespace detail {

bool ballDue(const Dropper& d, double dt) {
    return d.balls > 0 && d.nextIn <= 0.5 * dt;
}

ParticleDef nextBall(const Dropper& d) {
    return ParticleDef{.position = d.nextPosition(),
                       .velocity = d.velocity,
                       .mass = d.mass,
                       .radius = d.radius,
                       .color = d.color};
}

bool spotClear(const ParticleArrays& p, const ParticleDef& ball, const periodic::Box* box) {
    const double x = ball.position.x(), y = ball.position.y();
    for (std::size_t i = 0; i < p.size(); ++i) {
        double dx = p.x[i] - x, dy = p.y[i] - y;
        if (box) {
            dx = box->imageX(dx);
            dy = box->imageY(dy);
        }
        const double reach = p.radius[i] + ball.radius;
        if (dx * dx + dy * dy < reach * reach) return false;
    }
    return true;
}

void advanceDropper(Dropper& d, double dt, bool releasedBall, bool waiting) {
    if (waiting) {
        d.nextIn = 0.0;  // due now, and one interval after whenever it goes
        return;
    }
    if (releasedBall) {
        --d.balls;
        ++d.released;
        d.nextIn += d.interval;
    }
    if (d.balls == 0) return;
    // Faster than one ball a step, a dropper releases one each step and its debt stays bounded.
    d.nextIn = std::max(d.nextIn - dt, -0.5 * dt);
}

void validateDropper(const Dropper& d, std::size_t index, double width, double height, bool walls,
                     const char* where) {
    const std::string name = "dropper " + std::to_string(index);
    const auto what = [&](const char* field) { return name + " " + field; };
    requireFinite(d.position, where, what("position").c_str());
    requireFinite(d.velocity, where, what("velocity").c_str());
    requirePositive(d.interval, where, what("interval").c_str());
    requirePositive(d.radius, where, what("radius").c_str());
    requireMass(d.mass, where, what("mass").c_str());
    if (!std::isfinite(d.spread) || d.spread < 0.0) {
        fail(where, what("spread").c_str(), "must be finite and >= 0 " + got(d.spread));
    }
    if (!std::isfinite(d.nextIn) || d.nextIn > d.interval) {
        fail(where, what("time to the next ball").c_str(),
             "must be finite and at most the interval " + got(d.nextIn));
    }
    if (d.balls > kMaxDropperBalls) {
        fail(where, what("ball count").c_str(),
             "must be at most " + std::to_string(kMaxDropperBalls) + " (got " +
                 std::to_string(d.balls) + ")");
    }
    if (d.seed > static_cast<std::uint64_t>(INT64_MAX) ||
        d.released > static_cast<std::uint64_t>(INT64_MAX)) {
        fail(where, what("seed").c_str(), "and released count must be below 2^63 (scene files)");
    }
    // The release points, [x - spread, x + spread] at y: inside the box, and with walls the
    // whole ball inside, as the wall stage would keep it.
    const double margin = walls ? d.radius : 0.0;
    if (walls && (2.0 * d.radius > width || 2.0 * d.radius > height)) {
        fail(where, what("radius").c_str(),
             "gives balls wider than the " + csv::number(width) + " x " + csv::number(height) +
                 " m box " + got(d.radius));
    }
    const double x0 = d.position.x() - d.spread, x1 = d.position.x() + d.spread;
    const double y = d.position.y();
    if (x0 < margin || x1 > width - margin || y < margin || y > height - margin) {
        std::string problem = "puts balls outside the box: x from " + csv::number(x0) + " to " +
                              csv::number(x1) + ", y " + csv::number(y) + " m, the box is " +
                              csv::number(width) + " x " + csv::number(height) + " m";
        if (walls) problem += " and a ball's centre must be a radius inside the walls";
        fail(where, what("position").c_str(), problem);
    }
}

void validateDroppers(const Droppers& droppers, double width, double height, bool walls,
                      const char* where) {
    if (droppers.size() > kMaxDroppers) {
        fail(where, "dropper count",
             "must be at most " + std::to_string(kMaxDroppers) + " (got " +
                 std::to_string(droppers.size()) + ")");
    }
    for (std::size_t i = 0; i < droppers.size(); ++i)
        validateDropper(droppers[i], i, width, height, walls, where);
}

}  // namespace detail
}  // namespace psb
