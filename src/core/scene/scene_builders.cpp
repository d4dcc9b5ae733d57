#include <particle_sandbox/scene_builders.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <unordered_map>
#include <vector>

#include "scene/scene_generate.hpp"
#include "world/validate.hpp"

namespace psb::scenes {
namespace {

// SplitMix64 (scene_generate.hpp): fully specified, so a seed gives the same scene on every
// platform (up to the libm functions of the Gaussian).
using Random = detail::SplitMix64;

/// Random positions tried for each disc of mixed radii before the gas is declared too dense.
constexpr int kPlacementTries = 100000;

/// Finds overlaps among discs placed so far: a hash of square cells as wide as the largest
/// diameter, so a new disc is tested against the 3 × 3 cells around it.
class Placer {
  public:
    explicit Placer(double cell) : cell_(cell) {}
    [[nodiscard]] bool fits(const std::vector<ParticleDef>& placed, Vec2 c, double r) const {
        const std::int64_t cx = coord(c.x()), cy = coord(c.y());
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
            for (std::int64_t dx = -1; dx <= 1; ++dx) {
                const auto it = cells_.find(key(cx + dx, cy + dy));
                if (it == cells_.end()) continue;
                for (const std::size_t k : it->second) {
                    const double s = placed[k].radius + r;
                    if ((placed[k].position - c).squaredNorm() < s * s) return false;
                }
            }
        }
        return true;
    }
    void add(std::size_t k, Vec2 c) { cells_[key(coord(c.x()), coord(c.y()))].push_back(k); }

  private:
    [[nodiscard]] std::int64_t coord(double v) const {
        return static_cast<std::int64_t>(std::floor(v / cell_));
    }
    static std::uint64_t key(std::int64_t x, std::int64_t y) {
        return (static_cast<std::uint64_t>(x) << 32) ^ static_cast<std::uint64_t>(y & 0xffffffff);
    }
    double cell_;
    std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

Scene boxScene(double width, double height) {
    Scene s;
    s.world.width = width;
    s.world.height = height;
    s.world.walls = true;
    s.world.restitution = 1.0;
    return s;
}

Vec2 thermalVelocity(Random& rng, double temperature, double mass) {
    const double sigma = std::sqrt(temperature / mass);
    const double vx = sigma * rng.normal();
    return {vx, sigma * rng.normal()};
}

}  // namespace

Scene gas(const GasSpec& spec) {
    const char* where = "scenes::gas";
    if (spec.count == 0) detail::fail(where, "count", "must be at least 1");
    detail::requirePositive(spec.radius, where, "radius");
    detail::requireMass(spec.mass, where, "mass");
    detail::requireFinite(spec.temperature, where, "temperature");
    if (!(spec.temperature >= 0.0)) detail::fail(where, "temperature", "must be >= 0");
    detail::requireInRange(spec.packing, 1e-12, kMaxPackingFraction, where, "packing");
    const bool mixed = spec.maxRadius > spec.radius;
    if (mixed) detail::requireFinite(spec.maxRadius, where, "maxRadius");

    Random rng(spec.seed);
    // Radii first, so that the box is sized for the area they cover.
    std::vector<double> radii(spec.count, spec.radius);
    if (mixed) {
        const double ratio = spec.maxRadius / spec.radius;
        for (double& r : radii)
            r = spec.radius * std::pow(ratio, rng.uniform());
        std::sort(radii.begin(), radii.end(), std::greater<>());  // largest placed first
    }
    double area = static_cast<double>(spec.count) * std::numbers::pi * spec.radius * spec.radius;
    if (mixed) {
        area = 0.0;
        for (const double r : radii)
            area += std::numbers::pi * r * r;
    }
    const double side = std::sqrt(area / spec.packing);
    Scene s = boxScene(side, side);
    s.name = "Gas";
    s.particles.reserve(spec.count);
    const auto disc = [&](Vec2 c, double r) {
        ParticleDef d;
        d.position = c;
        d.radius = r;
        d.mass = spec.mass * (r / spec.radius) * (r / spec.radius);
        d.velocity = thermalVelocity(rng, spec.temperature, d.mass);
        d.color = spec.color;
        return d;
    };
    if (spec.overlapping && !mixed) {
        std::mt19937_64 mt(spec.seed);
        std::uniform_real_distribution<double> pos(spec.radius, side - spec.radius);
        std::normal_distribution<double> vel(0.0, std::sqrt(spec.temperature / spec.mass));
        for (std::size_t k = 0; k < spec.count; ++k) {
            ParticleDef d;
            const double x = pos(mt);
            d.position = {x, pos(mt)};
            const double vx = vel(mt);
            d.velocity = {vx, vel(mt)};
            d.mass = spec.mass;
            d.radius = spec.radius;
            d.color = spec.color;
            s.particles.push_back(d);
        }
        s.allowOverlaps = true;
        return s;
    }
    if (!mixed) {
        // The generate block's lattice (scene_generate.hpp): no trial and error, no overlap.
        detail::GenerateSpec g;
        g.count = spec.count;
        g.radius = spec.radius;
        g.mass = spec.mass;
        g.x1 = side;
        g.y1 = side;
        g.temperature = spec.temperature;
        g.color = spec.color;
        g.seed = spec.seed;
        const std::uint64_t capacity = detail::latticeCapacity(g);
        if (spec.count > capacity) {
            detail::fail(where, "packing",
                         csv::number(spec.packing) + " is too dense for " +
                             std::to_string(spec.count) + " discs: their " + csv::number(side) +
                             " m box holds at most " + std::to_string(capacity) +
                             " on the square lattice");
        }
        s.particles = detail::generateParticles(g);
        return s;
    }
    // Random sequential placement, largest first. It jams well below the lattice's π/4 when the
    // radii are nearly equal (near 0.55: 1000 discs of radii 1 to 1.1 m place at 0.5, not 0.55)
    // and comes close to it when they spread widely (radii 1 to 10 m place at 0.785); the
    // bounded tries per disc make a jam an error in seconds, never a hang.
    Placer placer(2.0 * radii.front());
    double covered = 0.0;
    for (const double r : radii) {
        bool placed = false;
        for (int attempt = 0; attempt < kPlacementTries && !placed; ++attempt) {
            const Vec2 c{r + (side - 2.0 * r) * rng.uniform(),
                         r + (side - 2.0 * r) * rng.uniform()};
            if (!placer.fits(s.particles, c, r)) continue;
            placer.add(s.particles.size(), c);
            s.particles.push_back(disc(c, r));
            covered += std::numbers::pi * r * r;
            placed = true;
        }
        if (!placed) {
            detail::fail(where, "packing",
                         csv::number(spec.packing) + " is too dense to place discs of radii " +
                             csv::number(spec.radius) + " to " + csv::number(spec.maxRadius) +
                             " m at random: disc " + std::to_string(s.particles.size() + 1) +
                             " of " + std::to_string(spec.count) + " found no room in " +
                             std::to_string(kPlacementTries) + " tries, the discs placed cover " +
                             csv::number(covered / (side * side)) +
                             " (random placement jams lower the nearer the radii are to equal)");
        }
    }
    return s;
}

Scene brownian(const BrownianSpec& spec) {
    const char* where = "scenes::brownian";
    if (spec.count == 0) detail::fail(where, "count", "must be at least 1");
    detail::requirePositive(spec.lightRadius, where, "lightRadius");
    detail::requireMass(spec.lightMass, where, "lightMass");
    detail::requirePositive(spec.bigRadius, where, "bigRadius");
    detail::requireMass(spec.bigMass, where, "bigMass");
    detail::requirePositive(spec.temperature, where, "temperature");
    detail::requireInRange(spec.packing, 1e-12, kMaxPackingFraction, where, "packing");
    const std::size_t count = spec.count;
    const double bigRadius = spec.bigRadius, r = spec.lightRadius;
    // The light discs cover `packing` of the area the heavy one leaves.
    const double bigArea = std::numbers::pi * bigRadius * bigRadius;
    const double side =
        std::sqrt(static_cast<double>(count) * std::numbers::pi * r * r / spec.packing + bigArea);
    Scene s = boxScene(side, side);
    s.name = "Brownian motion";
    s.description =
        "One heavy disc in a gas of light ones at the same temperature: pushed at random by their "
        "collisions it wanders (Brownian motion), and in the long run its mean kinetic energy "
        "equals a light disc's (equipartition).";
    ParticleDef big;
    big.position = {0.5 * side, 0.5 * side};
    big.radius = bigRadius;
    big.mass = spec.bigMass;
    big.color = {230, 120, 60};
    // The generate block's gas over the whole box, with enough more discs that those under the
    // heavy one can be left out.
    detail::GenerateSpec g;
    g.radius = r;
    g.mass = spec.lightMass;
    g.x1 = side;
    g.y1 = side;
    g.temperature = spec.temperature;
    g.color = Color{150, 170, 190};
    g.seed = spec.seed;
    const double margin =
        std::numbers::pi * (bigRadius + 2.0 * r) * (bigRadius + 2.0 * r) / (side * side);
    g.count = std::min(
        detail::latticeCapacity(g),
        static_cast<std::uint64_t>(std::ceil(static_cast<double>(count) * (1.0 + 2.0 * margin))) +
            16);
    std::vector<ParticleDef> around;
    for (const ParticleDef& d : detail::generateParticles(g)) {
        const double reach = bigRadius + d.radius;
        if ((d.position - big.position).squaredNorm() > reach * reach) around.push_back(d);
    }
    // Leave out the surplus evenly (sites come sorted by column), so the gas fills the box.
    s.particles.push_back(big);
    const std::size_t surplus = around.size() > count ? around.size() - count : 0;
    for (std::size_t k = 0, dropped = 0; k < around.size(); ++k) {
        if (dropped < surplus && k * surplus >= dropped * around.size()) {
            ++dropped;
            continue;
        }
        s.particles.push_back(around[k]);
    }
    if (s.particles.size() != count + 1) {
        detail::fail(where, "packing",
                     csv::number(spec.packing) + " is too dense: the " + csv::number(side) +
                         " m box holds " + std::to_string(s.particles.size() - 1) +
                         " light discs around the heavy one, not " + std::to_string(count));
    }
    s.trails = {0};
    return s;
}

Scene hexagonalLattice(int cols, int rows, double radius, double fraction, std::uint64_t seed) {
    const char* where = "scenes::hexagonalLattice";
    if (cols < 1 || rows < 1) detail::fail(where, "cols, rows", "must be at least 1");
    detail::requirePositive(radius, where, "radius");
    detail::requireInRange(fraction, 1e-12, 0.9069, where, "fraction");
    const double spacing =
        std::sqrt(2.0 * std::numbers::pi * radius * radius / (std::sqrt(3.0) * fraction));
    Scene s = boxScene(cols * spacing, rows * spacing * std::sqrt(3.0) / 2.0);
    s.name = "Hexagonal lattice";
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g(0.0, 1.0);
    for (int row = 0; row < rows; ++row) {
        for (int col = 0; col < cols; ++col) {
            ParticleDef d;
            d.position = {(col + 0.25 + 0.5 * (row % 2)) * spacing,
                          (row + 0.5) * spacing * std::sqrt(3.0) / 2.0};
            const double vx = g(rng);
            d.velocity = {vx, g(rng)};
            d.radius = radius;
            s.particles.push_back(d);
        }
    }
    // Rows are staggered: the box is the lattice's size, so the row ends are clamped into it
    // overlapping their neighbours (a jammed pile, on purpose).
    s.allowOverlaps = true;
    return s;
}

Scene cradle(int balls, double gap, double speed) {
    const char* where = "scenes::cradle";
    if (balls < 1) detail::fail(where, "balls", "must be at least 1");
    detail::requirePositive(gap, where, "gap");
    detail::requireFinite(speed, where, "speed");
    Scene s = boxScene(1e6, 1e6);
    s.world.walls = false;
    s.name = "Newton's cradle";
    ParticleDef striker;
    striker.position = {-2.0 - gap, 0.0};
    striker.velocity = {speed, 0.0};
    s.particles.push_back(striker);
    for (int k = 0; k < balls; ++k) {
        ParticleDef d;
        d.position = {2.0 * k, 0.0};
        s.particles.push_back(d);
    }
    return s;
}

}  // namespace psb::scenes
