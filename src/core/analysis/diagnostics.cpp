#include <particle_sandbox/diagnostics.hpp>

#include <algorithm>
#include <cmath>

#include <particle_sandbox/world.hpp>

#include "discrete/discrete_step.hpp"
#include "world/step_context.hpp"

namespace psb {
namespace {

/// Neumaier's compensated sum: the error stays ~1 ulp of the result however many terms.
class CompensatedSum {
  public:
    void add(double v) {
        const double t = sum_ + v;
        comp_ += std::abs(sum_) >= std::abs(v) ? (sum_ - t) + v : (v - t) + sum_;
        sum_ = t;
    }
    [[nodiscard]] double value() const { return sum_ + comp_; }

  private:
    double sum_ = 0.0;
    double comp_ = 0.0;
};

}  // namespace

double kineticEnergy(const World& world) {
    const ParticleArrays& p = world.particles();
    CompensatedSum sum;
    for (std::size_t i = 0; i < p.size(); ++i) {
        sum.add(0.5 * p.mass[i] * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]));
    }
    return sum.value();
}

double rotationalEnergy(const World& world) {
    const ParticleArrays& p = world.particles();
    if (!p.rotation) return 0.0;
    CompensatedSum sum;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double inertia = p.inertiaFactor[i] * p.mass[i] * p.radius[i] * p.radius[i];
        sum.add(0.5 * inertia * p.omega[i] * p.omega[i]);
    }
    return sum.value();
}

double rotationalEnergy(const World& world, ParticleId id) {
    const Particle q = world.get(id);
    return 0.5 * q.inertiaFactor * q.mass * q.radius * q.radius * q.angularVelocity *
           q.angularVelocity;
}

double angularMomentum(const World& world, const Vec2& point) {
    const ParticleArrays& p = world.particles();
    CompensatedSum sum;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double rx = p.x[i] - point.x(), ry = p.y[i] - point.y();
        sum.add(p.mass[i] * rx * p.vy[i]);
        sum.add(-p.mass[i] * ry * p.vx[i]);
        if (p.rotation) {
            const double inertia = p.inertiaFactor[i] * p.mass[i] * p.radius[i] * p.radius[i];
            sum.add(inertia * p.omega[i]);
        }
    }
    return sum.value();
}

double potentialEnergy(const World& world) {
    const ParticleArrays& p = world.particles();
    const WorldDef& def = world.def();
    const double gx = def.gravity.x(), gy = def.gravity.y();
    if (gx == 0.0 && gy == 0.0) return 0.0;
    // The box corner furthest along g: the floor for gravity pointing down.
    const double refX = gx > 0.0 ? def.width : 0.0, refY = gy > 0.0 ? def.height : 0.0;
    CompensatedSum sum;
    for (std::size_t i = 0; i < p.size(); ++i) {
        sum.add(p.mass[i] * (gx * (refX - p.x[i]) + gy * (refY - p.y[i])));
    }
    return sum.value();
}

double mechanicalEnergy(const World& world) {
    return kineticEnergy(world) + rotationalEnergy(world) + potentialEnergy(world);
}

Vec2 momentum(const World& world) {
    const ParticleArrays& p = world.particles();
    CompensatedSum sx, sy;
    for (std::size_t i = 0; i < p.size(); ++i) {
        sx.add(p.mass[i] * p.vx[i]);
        sy.add(p.mass[i] * p.vy[i]);
    }
    return {sx.value(), sy.value()};
}

Vec2 momentum(const World& world, ParticleId id) {
    const Particle q = world.get(id);
    return q.mass * q.velocity;
}

Vec2 centreOfMass(const World& world) {
    const ParticleArrays& p = world.particles();
    CompensatedSum m, mx, my;
    for (std::size_t i = 0; i < p.size(); ++i) {
        m.add(p.mass[i]);
        mx.add(p.mass[i] * p.x[i]);
        my.add(p.mass[i] * p.y[i]);
    }
    if (!(m.value() > 0.0)) return {0.5 * world.def().width, 0.5 * world.def().height};
    return {mx.value() / m.value(), my.value() / m.value()};
}

double maxOverlap(const World& world) {
    const ParticleArrays& p = world.particles();
    StepContext ctx;
    ctx.threads = world.threads();
    ctx.broadPhase = BroadPhaseKind::Auto;  // the fast choice for these particles
    stages::findPairs(p, ctx);
    double deepest = 0.0;
    for (const ContactPair& c : ctx.pairs) {
        const double d = std::hypot(p.x[c.j] - p.x[c.i], p.y[c.j] - p.y[c.i]);
        deepest = std::max(deepest, p.radius[c.i] + p.radius[c.j] - d);
    }
    return deepest;
}

double maxOverlapBruteForce(const World& world) {
    const ParticleArrays& p = world.particles();
    double deepest = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        for (std::size_t j = i + 1; j < p.size(); ++j) {
            const double d = std::hypot(p.x[j] - p.x[i], p.y[j] - p.y[i]);
            deepest = std::max(deepest, p.radius[i] + p.radius[j] - d);
        }
    }
    return deepest;
}

}  // namespace psb
