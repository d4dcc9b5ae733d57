#include "scene/scene_generate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_set>

namespace psb::detail {
namespace {

// Per axis at most 2^31 sites, so a site index (ix · ny + iy) fits in 64 bits.
constexpr double kMaxSitesPerAxis = 2147483648.0;

struct Lattice {
    double spacing = 0.0;
    std::uint64_t nx = 0, ny = 0;
    double originX = 0.0, originY = 0.0;  // centre of site (0, 0)
};

Lattice latticeWithSpacing(const GenerateSpec& s, double spacing) {
    const double w = s.x1 - s.x0, h = s.y1 - s.y0;
    Lattice l;
    l.spacing = spacing;
    const double nx = std::min(std::floor(w / l.spacing), kMaxSitesPerAxis);
    const double ny = std::min(std::floor(h / l.spacing), kMaxSitesPerAxis);
    l.nx = static_cast<std::uint64_t>(nx);
    l.ny = static_cast<std::uint64_t>(ny);
    // Centre the lattice in the region.
    l.originX = s.x0 + 0.5 * (w - nx * l.spacing) + 0.5 * l.spacing;
    l.originY = s.y0 + 0.5 * (h - ny * l.spacing) + 0.5 * l.spacing;
    return l;
}

Lattice latticeFor(const GenerateSpec& s, std::uint64_t wanted) {
    const double dense = 2.0 * s.radius * (1.0 + 1e-6);
    // About two sites per particle leaves room for randomness; never closer than `dense`, and
    // dense after all when a long thin region leaves the loose lattice too few rows.
    if (wanted > 0) {
        const double area = (s.x1 - s.x0) * (s.y1 - s.y0);
        const double loose = std::sqrt(area / (2.0 * static_cast<double>(wanted)));
        if (loose > dense) {
            const Lattice l = latticeWithSpacing(s, loose);
            if (l.nx * l.ny >= wanted) return l;
        }
    }
    return latticeWithSpacing(s, dense);
}

/// `count` distinct site indices in [0, sites), ascending.
std::vector<std::uint64_t> chooseSites(std::uint64_t count, std::uint64_t sites, SplitMix64& rng) {
    std::vector<std::uint64_t> chosen;
    chosen.reserve(count);
    if (sites <= 4 * count + 16) {
        // Partial Fisher–Yates over all sites: sites is at most ~4 million here.
        std::vector<std::uint64_t> all(sites);
        for (std::uint64_t k = 0; k < sites; ++k)
            all[k] = k;
        for (std::uint64_t k = 0; k < count; ++k) {
            std::swap(all[k], all[k + rng.below(sites - k)]);
            chosen.push_back(all[k]);
        }
    } else {
        // Sparse: rejection sampling; each draw succeeds with probability > 3/4.
        std::unordered_set<std::uint64_t> taken;
        taken.reserve(count);
        while (chosen.size() < count) {
            const std::uint64_t k = rng.below(sites);
            if (taken.insert(k).second) chosen.push_back(k);
        }
    }
    std::sort(chosen.begin(), chosen.end());
    return chosen;
}

}  // namespace

std::uint64_t latticeCapacity(const GenerateSpec& spec) {
    const Lattice l = latticeFor(spec, 0);
    // Saturate rather than overflow (2^31 · 2^31 = 2^62 fits anyway).
    return l.nx * l.ny;
}

std::vector<ParticleDef> generateParticles(const GenerateSpec& spec) {
    SplitMix64 rng(spec.seed);
    const Lattice l = latticeFor(spec, spec.count);
    const std::uint64_t sites = l.nx * l.ny;
    if (spec.count == 0 || sites < spec.count) return {};
    const std::vector<std::uint64_t> chosen = chooseSites(spec.count, sites, rng);

    // Neighbouring centres stay more than 2r apart (spacing - 2·jitter > 2r), and every
    // centre stays at least r inside the region's edge.
    const double jitter = 0.99 * (0.5 * l.spacing - spec.radius);
    std::vector<ParticleDef> out;
    out.reserve(chosen.size());
    for (const std::uint64_t site : chosen) {
        const std::uint64_t ix = site / l.ny, iy = site % l.ny;
        ParticleDef d;
        const double jx = (2.0 * rng.uniform() - 1.0) * jitter;
        const double jy = (2.0 * rng.uniform() - 1.0) * jitter;
        d.position = {l.originX + static_cast<double>(ix) * l.spacing + jx,
                      l.originY + static_cast<double>(iy) * l.spacing + jy};
        // Rounding must not put a disc a hair outside the region.
        d.position.x() = std::clamp(d.position.x(), spec.x0 + spec.radius, spec.x1 - spec.radius);
        d.position.y() = std::clamp(d.position.y(), spec.y0 + spec.radius, spec.y1 - spec.radius);
        d.mass = spec.mass;
        d.radius = spec.radius;
        if (spec.temperature) {
            const double sigma = std::sqrt(*spec.temperature / spec.mass);
            d.velocity = {sigma * rng.normal(), sigma * rng.normal()};
        } else if (spec.speed) {
            const double angle = 2.0 * std::numbers::pi * rng.uniform();
            d.velocity = {*spec.speed * std::cos(angle), *spec.speed * std::sin(angle)};
        }
        if (spec.color) {
            d.color = *spec.color;
        } else {
            auto channel = [&] { return static_cast<std::uint8_t>(100 + rng.below(156)); };
            d.color.r = channel();
            d.color.g = channel();
            d.color.b = channel();
        }
        out.push_back(d);
    }
    return out;
}

}  // namespace psb::detail
